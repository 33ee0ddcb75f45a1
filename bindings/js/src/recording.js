// SPDX-License-Identifier: MIT
// Recording and replay (include/impulse2d/snapshot.h): a world's recording streamed out of
// the module as the library writes it, and a Replay that runs one again checking every
// step's state hash.
import { withBytesInModule } from './snapshot.js';

// i2d_write_fn(const void* bytes, size_t size, void* context): three 32-bit arguments.
const WRITE_SIGNATURE = 'viii';

/**
 * A world's recording in progress: the library calls the writer with each record as it
 * is made, with the world locked. The user's `write` (given a copy of the record) may not
 * throw into the library, so the first error it throws is kept and thrown by stop().
 * Without `write` the records are kept and stop() returns them as one Uint8Array.
 */
export class Recorder {
  constructor(world, write) {
    if (write !== undefined && typeof write !== 'function') {
      throw new TypeError(`World.startRecording takes a function or nothing, not ${typeof write}`);
    }
    this.world = world;
    this.chunks = write === undefined ? [] : null;
    this.error = null;
    const { rt } = world;
    this.pointer = rt.m.addFunction((at, size) => {
      if (this.error !== null) return;
      const record = rt.u8.slice(at, at + size);
      if (this.chunks !== null) {
        this.chunks.push(record);
        return;
      }
      try {
        write(record);
      } catch (error) {
        this.error = error;
      }
    }, WRITE_SIGNATURE);
    try {
      rt.check(rt.m._i2d_world_start_recording(world.id, this.pointer, 0));
    } catch (error) {
      rt.m.removeFunction(this.pointer);
      throw error;
    }
  }

  /** Stops the library's recording and frees the writer; the kept bytes, or undefined. */
  stop() {
    const { rt } = this.world;
    try {
      rt.check(rt.m._i2d_world_stop_recording(this.world.id));
    } finally {
      rt.m.removeFunction(this.pointer);
    }
    if (this.error !== null) throw this.error;
    return this.chunks === null ? undefined : concatenate(this.chunks);
  }

  /** The destroyed world no longer calls the writer. */
  release() {
    this.world.rt.m.removeFunction(this.pointer);
  }
}

function concatenate(chunks) {
  const bytes = new Uint8Array(chunks.reduce((total, chunk) => total + chunk.length, 0));
  let at = 0;
  for (const chunk of chunks) {
    bytes.set(chunk, at);
    at += chunk.length;
  }
  return bytes;
}

/**
 * A recording replayed in a world of its own, made from the snapshot it starts with.
 * step(n) runs up to n more recorded steps, each with the calls recorded before it, and
 * stops after the first whose state hash differs from the recorded one; divergentStep
 * names it (null while every hash matched). seek(k) goes to step k, backwards too. A
 * recording the library refuses throws I2D_ERR_INVALID_SNAPSHOT with its message. The
 * replay's world has no Body objects (the recording made them, not this program): read
 * it with stateHash, counters, draw and the queries. close() destroys both.
 */
export class Replay {
  /** @internal Use Impulse2d.openReplay. `World` is passed in to keep the modules acyclic. */
  constructor(rt, bytes, World) {
    this.rt = rt;
    this.id = rt.checkId(withBytesInModule(rt, bytes, (at, length) => rt.m._i2d_replay_open(at, length, 0)));
    /** The replay's world, to read as the replay goes (the replay owns it). */
    this.world = new World(rt, rt.m._i2d_replay_get_world(this.id));
    this.world.owner = 'replay';
  }

  /** Replays up to count more steps; returns how many ran (fewer at the end of the
   *  recording, or after a step whose hash differed). */
  step(count = 1) {
    const ran = this.rt.m._i2d_replay_step(this.id, count);
    this.rt.checkLast();
    return ran;
  }

  /** Steps replayed so far. */
  get currentStep() { return this.read('_i2d_replay_get_step'); }

  /** Steps in the recording. */
  get stepCount() { return this.read('_i2d_replay_get_step_count'); }

  /** The first step whose hash differed from the recording's (1 for the first), or null. */
  get divergentStep() {
    const step = this.read('_i2d_replay_get_divergent_step');
    return step < 0 ? null : step;
  }

  /** Goes to step (0 to stepCount): the world after that many recorded steps. */
  seek(step) { this.rt.check(this.rt.m._i2d_replay_seek(this.id, step)); }

  /** Closes the replay; its world goes with it. Closing twice is harmless. */
  close() {
    if (this.id === 0n) return;
    const id = this.id;
    this.id = 0n;
    this.rt.check(this.rt.m._i2d_replay_close(id));
  }

  read(getter) {
    const value = this.rt.m[getter](this.id);
    this.rt.checkLast();
    return value;
  }
}
