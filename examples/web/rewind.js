// SPDX-License-Identifier: MIT
// The page's rewind, as a rollback game keeps its past: the world's rollback state
// (world.saveState) after every frame, the newest last, up to a number of frames and of
// bytes. Going back one frame drops the newest state and restores the one before it;
// stepping on from there saves anew, so the frames that were undone are gone.
//
// A state restores only while the world's structure is as it was saved (no body, shape
// or joint made, destroyed or changed since, include/impulse2d/snapshot.h): the page calls
// restart() after each such change (taking hold of a body, moving the pointer that pulls
// it, letting go), which keeps only the present.

export class Rewind {
  /** At most maxFrames states and maxBytes bytes of them. */
  constructor(maxFrames, maxBytes) {
    this.maxFrames = maxFrames;
    this.maxBytes = maxBytes;
    this.states = [];
    this.bytes = 0;
  }

  /** Forgets the past: the world's present state is the only one kept. */
  restart(world) {
    this.states = [];
    this.bytes = 0;
    this.save(world);
  }

  /** Keeps the world's state after a frame, dropping the oldest past the limits. */
  save(world) {
    const state = world.saveState();
    this.states.push(state);
    this.bytes += state.length;
    while (this.states.length > 1 && (this.states.length > this.maxFrames || this.bytes > this.maxBytes)) {
      this.bytes -= this.states.shift().length;
    }
  }

  /** Frames the world can go back. */
  get frames() { return this.states.length - 1; }

  /** Takes the world one frame back; false when no older state is kept. */
  back(world) {
    if (this.states.length < 2) return false;
    this.bytes -= this.states.pop().length;
    world.restoreState(this.states[this.states.length - 1]);
    return true;
  }
}
