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
//
// A game keeps state the world does not hold (the platformer's character is moved by
// game code, not a body): save() keeps it beside the world's state, and back() gives it
// back for the game to restore.

export class Rewind {
  /** At most maxFrames states and maxBytes bytes of them. */
  constructor(maxFrames, maxBytes) {
    this.maxFrames = maxFrames;
    this.maxBytes = maxBytes;
    this.states = [];
    this.bytes = 0;
  }

  /** Forgets the past: the world's present state (and the game's) is the only one kept. */
  restart(world, game) {
    this.states = [];
    this.bytes = 0;
    this.save(world, game);
  }

  /** Keeps the world's state after a frame, and the game's if any, dropping the oldest
   *  past the limits. */
  save(world, game) {
    const state = world.saveState();
    this.states.push({ state, game });
    this.bytes += state.length;
    while (this.states.length > 1 && (this.states.length > this.maxFrames || this.bytes > this.maxBytes)) {
      this.bytes -= this.states.shift().state.length;
    }
  }

  /** Frames the world can go back. */
  get frames() { return this.states.length - 1; }

  /** Takes the world one frame back: {game} as saved with that frame, or null when no
   *  older state is kept. */
  back(world) {
    if (this.states.length < 2) return null;
    this.bytes -= this.states.pop().state.length;
    const { state, game } = this.states[this.states.length - 1];
    world.restoreState(state);
    return { game };
  }
}
