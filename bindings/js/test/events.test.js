// SPDX-License-Identifier: MIT
// Events through the wasm module: body moves read straight from the world's memory, and
// contact begin and end.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { groundedWorld } from './fixture.js';

test('move events carry every moved body with its transform, read without copying', () => {
  const { world } = groundedWorld();
  const bodies = [];
  for (let i = 0; i < 5; i++) {
    const body = world.createBody({ type: 'dynamic', position: [2 * i, 5 + i] });
    body.createBox(0.5, 0.5);
    bodies.push(body);
  }
  world.step();
  const moves = world.bodyMoves();
  assert.equal(moves.count, 5);
  assert.equal(moves.floats.length, moves.count * moves.stride);
  const seen = new Set();
  for (let i = 0; i < moves.count; i++) {
    const body = moves.body(i);
    seen.add(body);
    const { x, y } = body.position;
    assert.equal(moves.x(i), x);
    assert.equal(moves.y(i), y);
    assert.equal(moves.fellAsleep(i), false);
  }
  assert.deepEqual(seen, new Set(bodies));
  world.destroy();
});

test('a body that fell asleep says so in its last move event and then stops moving', () => {
  const { world } = groundedWorld();
  world.createBody({ type: 'dynamic', position: [0, 0.5] }).createBox(0.5, 0.5);
  let asleep = false;
  for (let i = 0; i < 300 && !asleep; i++) {
    world.step();
    const moves = world.bodyMoves();
    asleep = moves.count === 1 && moves.fellAsleep(0);
  }
  assert.ok(asleep, 'fell asleep within 5 s');
  world.step();
  assert.equal(world.bodyMoves().count, 0);
  world.destroy();
});

test('a falling box begins touching the ground once, and ends when lifted away', () => {
  const { world, ground } = groundedWorld();
  const box = world.createBody({ type: 'dynamic', position: [0, 2] });
  const shape = box.createBox(0.5, 0.5);
  const begun = [];
  for (let i = 0; i < 120; i++) {
    world.step();
    begun.push(...world.contactEvents().begin);
  }
  assert.equal(begun.length, 1);
  assert.deepEqual(new Set(begun[0]), new Set([shape, ground.shapes[0]]));
  box.setTransform([0, 10], 0);
  world.step();
  const { end } = world.contactEvents();
  assert.equal(end.length, 1);
  assert.deepEqual(new Set(end[0]), new Set([shape, ground.shapes[0]]));
  world.destroy();
});

test('move event views stay readable after the heap grows, when taken again', () => {
  const { world } = groundedWorld();
  world.createBody({ type: 'dynamic', position: [0, 5] }).createCircle(0.5);
  world.step();
  // Thousands of bodies force the module's memory to grow.
  for (let i = 0; i < 20000; i++) world.createBody({ type: 'dynamic', position: [i % 100, 20 + i / 100] }).createCircle(0.3);
  world.step();
  const moves = world.bodyMoves();
  assert.equal(moves.count, 20001);
  assert.ok(Number.isFinite(moves.y(20000)));
  world.destroy();
});
