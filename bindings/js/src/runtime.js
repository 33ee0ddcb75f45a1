// SPDX-License-Identifier: MIT
// The loaded module and what every wrapper needs from it: scratch memory for arguments
// and results, struct offsets by name (from the module's own description of its structs,
// see layout.js), and turning a refused call into an exception.
import { Impulse2dError } from './errors.js';
import { JOINT_KIND_NAMES } from './joint_kinds.js';
import { offsets, readDescription, usageProblems } from './layout.js';
import { vx, vy } from './vectors.js';

// Structs passed by value (i2d_vec2, i2d_rot, i2d_aabb, filters) cross the wasm C ABI
// as pointers to a copy, and struct results come back through a pointer the caller
// gives: both live in one scratch block. 64-bit ids cross as BigInt.
const SCRATCH_BYTES = 1024;
const RESULT = 0;          // results (up to 256 bytes: i2d_polygon is the largest read)
const ARG0 = 512;          // by-value arguments, 64 bytes apart
const ARG_STRIDE = 64;

export class Runtime {
  /** description overrides what the module reports (for tests); threadPoolSize is how
   *  many worker threads the module's build keeps for worlds (0: none). */
  constructor(module, description = readDescription(module), threadPoolSize = 0) {
    this.m = module;
    this.threadPoolSize = threadPoolSize;
    /** Of those, how many the worlds alive hold (World.create takes, destroy gives back). */
    this.threadsLent = 0;
    this.views = null;
    const problems = usageProblems(description).concat(scratchProblems(description));
    if (problems.length > 0) {
      throw new Error('impulse2d: the WebAssembly module\'s structs do not match this binding (rebuild dist/ ' +
                      `with bindings/js/build.sh from the same sources):\n  ${problems.join('\n  ')}`);
    }
    /** Map of C struct name -> {name, size, align, fields}: the module's description. */
    this.description = description;
    this.layout = offsets(description);
    this.scratch = module._malloc(SCRATCH_BYTES);
    this.defaults = {
      world: this.readDefault('_i2d_default_world_def', 'i2d_world_def'),
      body: this.readDefault('_i2d_default_body_def', 'i2d_body_def'),
      shape: this.readDefault('_i2d_default_shape_def', 'i2d_shape_def'),
      explosion: this.readDefault('_i2d_default_explosion_def', 'i2d_explosion_def'),
      batch: this.readDefault('_i2d_default_batch_def', 'i2d_batch_def'),
      character: this.readDefault('_i2d_default_character_def', 'i2d_character_def'),
      debugDraw: this.readDefault('_i2d_default_debug_draw', 'i2d_debug_draw'),
    };
    for (const kind of JOINT_KIND_NAMES) {
      this.defaults[`${kind}_joint`] = this.readDefault(`_i2d_default_${kind}_joint_def`, `i2d_${kind}_joint_def`);
    }
    this.allFilter = this.m._malloc(this.size('i2d_query_filter'));
    this.m._i2d_default_query_filter(this.allFilter);
  }

  size(type) { return this.field(type); }

  field(name) {
    const value = this.layout.get(name);
    if (value === undefined) throw new Error(`impulse2d: no layout entry ${name}`);
    return value;
  }

  // The heap may have grown during the last call: a single-threaded module then detaches
  // the old buffer and replaces its HEAP views, and in the threads build a worker may have
  // grown the shared memory, which the module's own views on this thread do not follow.
  // So the views are checked against the memory's buffer on each use.
  heap() {
    const buffer = this.m.wasmMemory?.buffer ?? this.m.HEAPU8.buffer;
    if (this.views === null || this.views.u8.buffer !== buffer) {
      this.views = { f32: new Float32Array(buffer), i32: new Int32Array(buffer), u32: new Uint32Array(buffer),
                     u8: new Uint8Array(buffer), u64: new BigUint64Array(buffer) };
    }
    return this.views;
  }

  get f32() { return this.heap().f32; }
  get i32() { return this.heap().i32; }
  get u32() { return this.heap().u32; }
  get u8() { return this.heap().u8; }
  get u64() { return this.heap().u64; }

  result() { return this.scratch + RESULT; }
  arg(index) { return this.scratch + ARG0 + index * ARG_STRIDE; }

  /** Writes two floats at argument slot `index` and returns its address. */
  vec2(index, x, y) {
    return this.writeVec2(this.arg(index), x, y);
  }

  /** Writes an i2d_vec2 at address `at` and returns it. */
  writeVec2(at, x, y) {
    const f = this.f32;
    f[at >> 2] = x;
    f[(at >> 2) + 1] = y;
    return at;
  }

  /** Writes a rotation (cosine, sine) of `angle` radians at argument slot `index`. */
  rot(index, angle) {
    return this.vec2(index, Math.cos(angle), Math.sin(angle));
  }

  readVec2(at) {
    const f = this.f32;
    return { x: f[at >> 2], y: f[(at >> 2) + 1] };
  }

  readDefault(fn, type) {
    const bytes = this.size(type);
    this.m[fn](this.result());
    return this.u8.slice(this.result(), this.result() + bytes);
  }

  /** Copies a default def into a fresh block (freed by the caller). */
  defBlock(which) {
    const bytes = this.defaults[which];
    const at = this.m._malloc(bytes.length);
    this.u8.set(bytes, at);
    return at;
  }

  lastError() {
    const status = this.m._i2d_last_status();
    const message = this.m.UTF8ToString(this.m._i2d_last_error_message());
    return new Impulse2dError(status, message);
  }

  /** Throws the library's error unless status is I2D_OK. */
  check(status) {
    if (status !== 0) throw this.lastError();
  }

  /** Throws unless the last call succeeded (for getters, which return zero on error). */
  checkLast() {
    if (this.m._i2d_last_status() !== 0) throw this.lastError();
  }

  /** Writes an i2d_transform (position, angle in radians) at argument slot `index`. */
  transform(index, position, angle) {
    const at = this.arg(index);
    this.writeVec2(at + this.field('i2d_transform.p'), vx(position), vy(position));
    this.writeVec2(at + this.field('i2d_transform.q'), Math.cos(angle), Math.sin(angle));
    return at;
  }

  /**
   * For the C getters that fill up to capacity entries of `stride` bytes and return how
   * many there are: fill(out, capacity) is the call, read(out, count) what the caller
   * makes of the entries (before the block is freed). Throws what the library refused.
   */
  filled(stride, fill, read) {
    let capacity = 16;
    for (;;) {
      const out = this.m._malloc(capacity * stride);
      try {
        const total = fill(out, capacity);
        this.checkLast();
        if (total <= capacity) return read(out, total);
        capacity = total;
      } finally {
        this.m._free(out);
      }
    }
  }

  /** Throws the library's error for a null id. */
  checkId(id) {
    if (id === 0n) throw this.lastError();
    return id;
  }
}

// Structs read into the result block or written into an argument slot must fit there.
const BY_VALUE_ARGUMENTS = ['i2d_vec2', 'i2d_rot', 'i2d_aabb', 'i2d_circle', 'i2d_capsule', 'i2d_segment',
  'i2d_transform', 'i2d_mass_data', 'i2d_surface_material'];

function scratchProblems(description) {
  const problems = [];
  for (const struct of description.values()) {
    if (struct.size > ARG0 - RESULT) problems.push(`${struct.name}: ${struct.size} bytes do not fit the result block`);
  }
  for (const name of BY_VALUE_ARGUMENTS) {
    const size = description.get(name)?.size;
    if (size > ARG_STRIDE) problems.push(`${name}: ${size} bytes do not fit an argument slot`);
  }
  return problems;
}
