// SPDX-License-Identifier: MIT
// What the binding's tests share: one loaded module and a world with a ground box.
import { loadImpulse2d } from '../src/index.js';

export const i2d = await loadImpulse2d();

/** A world whose ground box (half 20 x 1) has its top face at y = 0. */
export function groundedWorld(options) {
  const world = i2d.createWorld(options);
  const ground = world.createBody({ position: [0, -1] });
  ground.createBox(20, 1);
  return { world, ground };
}

export function stepSeconds(world, seconds) {
  for (let i = 0; i < Math.round(seconds * 60); i++) world.step(1 / 60, 4);
}
