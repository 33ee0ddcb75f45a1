// SPDX-License-Identifier: MIT
// i2d.stepWorlds: many worlds in one call, each ending with the bits world.step gives it
// alone; a bad batch throws naming the entry and moves no world.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { i2d, groundedWorld, refused } from './fixture.js';

/** A ball dropped from 1 + index metres, a box beside it. */
function drop(index) {
  const { world } = groundedWorld();
  world.createBody({ type: 'dynamic', position: [0, 1 + index] }).createCircle(0.25);
  world.createBody({ type: 'dynamic', position: [1, 2], angle: 0.1 * index }).createBox(0.3, 0.3);
  return world;
}

test('stepWorlds gives each world the bits it has stepped alone', () => {
  const batched = [0, 1, 2, 3].map(drop);
  const alone = [0, 1, 2, 3].map(drop);
  for (let s = 0; s < 90; s++) {
    i2d.stepWorlds(batched, 1 / 60, 4);
    for (const world of alone) world.step(1 / 60, 4);
  }
  assert.deepEqual(batched.map((w) => w.stateHash()), alone.map((w) => w.stateHash()));
  assert.equal(new Set(batched.map((w) => w.stateHash())).size, 4);
  i2d.stepWorlds([]);
});

test('a bad batch throws naming the entry and steps no world', () => {
  const worlds = [drop(0), drop(1)];
  const before = worlds.map((w) => w.stateHash());
  refused(() => i2d.stepWorlds([worlds[0], worlds[1], worlds[0]]), 'I2D_ERR_INVALID_ARGUMENT',
          'worlds[2]: the world is listed twice');
  refused(() => i2d.stepWorlds(worlds, NaN), 'I2D_ERR_INVALID_ARGUMENT', 'time_step is NaN');
  refused(() => i2d.stepWorlds(worlds, 1 / 60, 0), 'I2D_ERR_INVALID_ARGUMENT', 'substep_count is 0');
  assert.throws(() => i2d.stepWorlds([worlds[0], {}]), TypeError);
  const gone = drop(2);
  gone.destroy();
  refused(() => i2d.stepWorlds([worlds[0], worlds[1], gone]), 'I2D_ERR_INVALID_HANDLE', 'worlds[2]');
  assert.deepEqual(worlds.map((w) => w.stateHash()), before);
});

test('a contact hook error is thrown once the whole batch is stepped', () => {
  const worlds = [drop(0), drop(1)];
  for (const world of worlds) {
    world.createBody({ type: 'dynamic', position: [4, 0.2] }).createBox(0.2, 0.2, { enablePreSolveEvents: true });
  }
  worlds[1].setPreSolve(() => { throw new Error('hook says no'); });
  const alone = drop(0);
  alone.createBody({ type: 'dynamic', position: [4, 0.2] }).createBox(0.2, 0.2, { enablePreSolveEvents: true });
  let steps = 0;
  assert.throws(() => {
    while (steps < 60) {
      steps++;
      i2d.stepWorlds(worlds);
    }
  }, /hook says no/);
  // The batch that threw still stepped every world: the hookless one kept pace with alone.
  for (let s = 0; s < steps; s++) alone.step();
  assert.equal(worlds[0].stateHash(), alone.stateHash());
  worlds[1].setPreSolve(null);
  i2d.stepWorlds(worlds);
});
