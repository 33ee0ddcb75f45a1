// SPDX-License-Identifier: MIT
// What the binding's tests share: one loaded module, a world with a ground box, and the
// assertions for refused calls and measured figures.
import assert from 'node:assert/strict';
import { Impulse2dError, loadImpulse2d } from '../src/index.js';

/** The build loadImpulse2d chooses here (the SIMD one on node >= 16). */
export const i2d = await loadImpulse2d();
/** Both builds, for the tests that compare them: every test file loads each at most once. */
export const scalarBuild = await loadImpulse2d({ simd: false });
export const simdBuild = await loadImpulse2d({ simd: true });

/** A world whose ground box (half 20 x 1) has its top face at y = 0. */
export function groundedWorld(options, build = i2d) {
  const world = build.createWorld(options);
  const ground = world.createBody({ position: [0, -1] });
  ground.createBox(20, 1);
  return { world, ground };
}

export function stepSeconds(world, seconds) {
  for (let i = 0; i < Math.round(seconds * 60); i++) world.step(1 / 60, 4);
}

/** Asserts that fn throws the library's refusal: its status, and a message naming the cause. */
export function refused(fn, status, messagePart) {
  assert.throws(fn, (error) => {
    assert.ok(error instanceof Impulse2dError, `${error}`);
    assert.equal(error.status, status);
    assert.ok(error.message.includes(messagePart), `message: ${error.message}`);
    return true;
  });
}

/** Asserts |actual - expected| <= tolerance, printing all three and what was measured. */
export function assertNear(actual, expected, tolerance, what) {
  assert.ok(Math.abs(actual - expected) <= tolerance,
            `${what}: ${actual} is not within ${tolerance} of ${expected}`);
}
