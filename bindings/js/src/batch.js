// SPDX-License-Identifier: MIT
// Many worlds stepped in one call (i2d_worlds_step). WebAssembly built without threads
// steps them in turn on the calling thread; what the call saves is a crossing into the
// module per world, and it refuses a bad batch whole, as the native library does.
import { World } from './world.js';

const ID_BYTES = 8;

/**
 * Steps every world by timeStep in substeps, each as world.step would. A bad world (not
 * a World, destroyed, or listed twice) or a bad timeStep or substeps throws, naming its
 * index, and steps no world. Throws, once all are stepped, the first error a contact
 * hook threw in any of them.
 */
export function stepWorlds(rt, worlds, timeStep = 1 / 60, substeps = 4) {
  const list = Array.from(worlds);
  list.forEach((world, index) => {
    if (!(world instanceof World)) throw new TypeError(`stepWorlds: worlds[${index}] is not a World`);
  });
  const ids = rt.m._malloc(Math.max(list.length, 1) * ID_BYTES);
  const def = rt.defBlock('batch');
  try {
    const u64 = rt.u64;
    list.forEach((world, index) => { u64[(ids >> 3) + index] = world.id; });
    const status = rt.m._i2d_worlds_step(ids, list.length, timeStep, substeps, def);
    const raised = list.flatMap((world) => world.hooks.takeRaised());
    rt.check(status);
    if (raised.length > 0) throw raised[0];
  } finally {
    rt.m._free(def);
    rt.m._free(ids);
  }
}
