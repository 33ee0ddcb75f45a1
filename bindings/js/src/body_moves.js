// SPDX-License-Identifier: MIT
// The last step's body move events as typed-array views of the world's own event array.

/** A view of the last step's body move events in the module's memory. */
export class BodyMoves {
  constructor(world, address, count) {
    const rt = world.rt;
    this.world = world;
    this.count = count;
    /** Floats (and words) per event. */
    this.stride = rt.size('i2d_body_move_event') / 4;
    const words = this.stride * count;
    /** Event i's transform is floats[i * stride + 0..3]: x, y, cosine, sine. */
    this.floats = new Float32Array(rt.u8.buffer, address, words);
    /** Event i's body index is words[i * stride + userDataWord]. */
    this.words = new Uint32Array(rt.u8.buffer, address, words);
    this.transformWord = rt.field('i2d_body_move_event.transform') / 4;
    this.userDataWord = rt.field('i2d_body_move_event.user_data') / 4;
    this.asleepByte = rt.field('i2d_body_move_event.fell_asleep');
    this.bytes = new Uint8Array(rt.u8.buffer, address, words * 4);
  }

  bodyIndex(i) { return this.words[i * this.stride + this.userDataWord]; }
  body(i) { return this.world.bodyByIndex[this.bodyIndex(i)]; }
  x(i) { return this.floats[i * this.stride + this.transformWord]; }
  y(i) { return this.floats[i * this.stride + this.transformWord + 1]; }
  angle(i) {
    const at = i * this.stride + this.transformWord;
    return Math.atan2(this.floats[at + 3], this.floats[at + 2]);
  }
  fellAsleep(i) { return this.bytes[i * this.stride * 4 + this.asleepByte] !== 0; }
}
