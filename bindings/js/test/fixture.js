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

const STEPS = 500;
const HASH_EVERY = 50;

/**
 * Boxes, circles, capsules and triangles, some spinning, dropped into a bin, and a chain of
 * boxes on revolute joints (the hinge kernels) hung from the ground: enough contacts for
 * every SIMD lane, lanes left over, and static and dynamic partners. From 256 awake bodies
 * a world of several workers shares its steps among them (parallel_min_bodies).
 */
export function mixedPile(build, options, bodies = 120) {
  const { world, ground } = groundedWorld(options, build);
  ground.createBox(0.5, 6, { center: [-8, 6] });
  ground.createBox(0.5, 6, { center: [8, 6] });
  for (let i = 0; i < bodies; i++) {
    const body = world.createBody({
      type: 'dynamic', position: [-6 + (i % 12) * 1.05, 1 + Math.floor(i / 12) * 1.1],
      angle: 0.1 * (i % 7), angularVelocity: (i % 5) - 2,
    });
    switch (i % 4) {
      case 0: body.createBox(0.4, 0.3, { friction: 0.4 + 0.05 * (i % 5) }); break;
      case 1: body.createCircle(0.35, { restitution: 0.2 * (i % 3) }); break;
      case 2: body.createCapsule([-0.3, 0], [0.3, 0], 0.2); break;
      default: body.createPolygon([[-0.4, -0.3], [0.4, -0.3], [0, 0.4]]);
    }
  }
  let previous = ground;
  for (let link = 0; link < 8; link++) {
    const body = world.createBody({ type: 'dynamic', position: [12 + link * 0.6, 10] });
    body.createBox(0.3, 0.1);
    world.createRevoluteJoint(previous, body, {
      localAnchorA: previous === ground ? [11.7, 11] : [0.3, 0], localAnchorB: [-0.3, 0],
    });
    previous = body;
  }
  return world;
}

/** The mixed pile's state hash every HASH_EVERY of STEPS steps, and its touching contacts at the end. */
export function mixedPileHashes(build, options, bodies = 120) {
  const world = mixedPile(build, options, bodies);
  const hashes = [];
  for (let s = 1; s <= STEPS; s++) {
    world.step(1 / 60, 4);
    if (s % HASH_EVERY === 0) hashes.push(world.stateHash().toString(16).padStart(16, '0'));
  }
  const { contactCount } = world.counters();
  world.destroy();
  return { hashes, contactCount };
}
