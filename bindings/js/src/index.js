// SPDX-License-Identifier: MIT
// impulse2d for JavaScript: the WebAssembly build of the library behind World, Body,
// Shape and Joint classes. Load once, then make worlds:
//   const i2d = await loadImpulse2d();
//   const world = i2d.createWorld({ gravity: [0, -10] });
import createImpulse2dModule from '../dist/impulse2d_wasm.mjs';
import { Runtime } from './runtime.js';
import { World } from './world.js';

export { Impulse2dError } from './errors.js';
export { World } from './world.js';
export { BodyMoves } from './body_moves.js';
export { Body } from './body.js';
export { Shape } from './shape.js';
export {
  Joint, RevoluteJoint, PrismaticJoint, DistanceJoint, WeldJoint, WheelJoint, MotorJoint, MouseJoint, FilterJoint,
} from './joint.js';

/**
 * Instantiates the module. In node the .wasm is read from the package (or `wasmBinary`);
 * in a page it is fetched next to the loader (or from `wasmUrl`).
 */
export async function loadImpulse2d(options = {}) {
  let { wasmBinary, wasmUrl } = options;
  const url = wasmUrl ?? new URL('../dist/impulse2d_wasm.wasm', import.meta.url);
  if (wasmBinary === undefined && typeof process === 'object' && process.versions?.node) {
    const { readFile } = await import('node:fs/promises');
    wasmBinary = await readFile(url);
  }
  const module = await createImpulse2dModule(wasmBinary !== undefined ? { wasmBinary }
                                                                      : { locateFile: () => String(url) });
  return new Impulse2d(new Runtime(module));
}

export class Impulse2d {
  /** @internal */
  constructor(rt) {
    this.rt = rt;
  }

  /** The library's version packed as (major << 16) | (minor << 8) | patch. */
  get version() { return this.rt.m._i2d_version(); }

  createWorld(options) { return World.create(this.rt, options); }

  /** A new world from a snapshot's bytes: World.fromSnapshot(this, bytes). */
  worldFromSnapshot(bytes) { return World.fromSnapshot(this, bytes); }
}
