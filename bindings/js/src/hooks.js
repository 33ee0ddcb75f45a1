// SPDX-License-Identifier: MIT
// A world's contact hooks (include/impulse2d/toolkit.h): JS functions put in the module's
// function table (addFunction) for the library to call during the step. The .wasm has no
// threads, so they run on the thread that called step(), one at a time.
import { readManifold } from './manifold.js';

// The C types as the wasm ABI passes them: an id (a struct of one uint64_t) as an i64,
// which arrives as a BigInt; a pointer as an i32; bool back as an i32.
const HOOKS = {
  customFilter: { signature: 'ijji', setter: '_i2d_world_set_custom_filter_callback' },
  preSolve: { signature: 'ijjii', setter: '_i2d_world_set_pre_solve_callback' },
};

export class ContactHooks {
  constructor(world) {
    this.world = world;
    /** The table slot of each hook set (0: none), freed when it is replaced or cleared. */
    this.pointers = { customFilter: 0, preSolve: 0 };
    /** What hooks threw during the current step, for step() to throw after it. */
    this.raised = [];
  }

  /** Sets kind's hook to fn, or clears it for null (or undefined). */
  set(kind, fn, method) {
    fn = fn ?? null;
    if (fn !== null && typeof fn !== 'function') {
      throw new TypeError(`World.${method} takes a function or null, not ${typeof fn}`);
    }
    if (fn !== null && this.world.threads > 0) {
      // The hooks run on the step's workers, and a Web Worker cannot call this thread's
      // JavaScript functions.
      throw new Error(`World.${method}: a world with ${this.world.workerCount} workers runs its hooks on Web ` +
                      'Workers, which cannot call this function; use a world of one worker');
    }
    const { m } = this.world.rt;
    const { signature, setter } = HOOKS[kind];
    const pointer = fn === null ? 0 : m.addFunction(this.trampoline(kind, fn), signature);
    try {
      this.world.rt.check(m[setter](this.world.id, pointer, 0));
    } catch (error) {
      // Refused (a locked or destroyed world): the library still holds the old hook.
      if (pointer !== 0) m.removeFunction(pointer);
      throw error;
    }
    this.free(kind);
    this.pointers[kind] = pointer;
  }

  /** The first error a hook threw since the last call, as [error], or []. */
  takeRaised() {
    const raised = this.raised;
    this.raised = [];
    return raised.slice(0, 1);
  }

  /** Frees every table slot: the world was destroyed, so the library calls none of them. */
  release() {
    for (const kind of Object.keys(this.pointers)) this.free(kind);
  }

  free(kind) {
    if (this.pointers[kind] !== 0) this.world.rt.m.removeFunction(this.pointers[kind]);
    this.pointers[kind] = 0;
  }

  /** The function the library calls: the ids as the world's Shape objects, the answer as 0 or 1. */
  trampoline(kind, fn) {
    const world = this.world;
    const shape = (id) => world.shapeById.get(id) ?? id;
    if (kind === 'customFilter') return (a, b) => this.answer(() => fn(shape(a), shape(b)));
    return (a, b, manifold) => this.answer(() => fn(shape(a), shape(b), readManifold(world.rt, manifold)));
  }

  // A JS exception must not unwind through the library's frames (the world would stay
  // locked mid-step): it is kept for step() to throw, and the pair gets true, the answer
  // of a world without the hook.
  answer(ask) {
    try {
      return ask() ? 1 : 0;
    } catch (error) {
      this.raised.push(error);
      return 1;
    }
  }
}
