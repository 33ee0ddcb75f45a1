// SPDX-License-Identifier: MIT
// The platformer's keys: which game actions are held. Arrows or A/D walk; Space, W or Up
// jump. Only while a scene wants them (the platformer), so that elsewhere the keys keep
// their usual meaning (Space pressing a focused button, arrows scrolling).

const ACTIONS = {
  left: ['ArrowLeft', 'a'],
  right: ['ArrowRight', 'd'],
  jump: [' ', 'ArrowUp', 'w'],
};
const GAME_KEYS = new Set(Object.values(ACTIONS).flat());

// Letters by their lower case: a key pressed as 'a' and let go as 'A' (Shift pressed in
// between) is the same key.
const normalized = (key) => (key.length === 1 ? key.toLowerCase() : key);

export class Keyboard {
  constructor(target) {
    /** Whether the current scene takes the keys. */
    this.enabled = false;
    /** Game keys held down, by their normalized name: two keys of one action held, and
     *  one let go, keep the action. */
    this.held = new Set();
    target.addEventListener('keydown', (event) => this.key(event, true));
    target.addEventListener('keyup', (event) => this.key(event, false));
    target.addEventListener('blur', () => this.held.clear());
  }

  key(event, down) {
    const key = normalized(event.key);
    if (!this.enabled || !GAME_KEYS.has(key) || event.ctrlKey || event.metaKey || event.altKey) return;
    event.preventDefault();
    if (down) this.held.add(key);
    else this.held.delete(key);
  }

  /** {left, right, jump}: the actions held now. */
  actions() {
    const any = (action) => ACTIONS[action].some((key) => this.held.has(key));
    return { left: any('left'), right: any('right'), jump: any('jump') };
  }
}
