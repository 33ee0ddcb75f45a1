// SPDX-License-Identifier: MIT
// Refused input: every bad call throws an Impulse2dError with the library's status and
// message, and leaves the world as it was.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { i2d, groundedWorld, refused } from './fixture.js';

test('bad world options are refused with the library message', () => {
  refused(() => i2d.createWorld({ gravity: [NaN, 0] }), 'I2D_ERR_INVALID_ARGUMENT', 'gravity');
  refused(() => i2d.createWorld({ contactHertz: -1 }), 'I2D_ERR_INVALID_ARGUMENT', 'contact_hertz');
});

test('bad bodies and shapes are refused and the world keeps its counts and state', () => {
  const { world, ground } = groundedWorld();
  const body = world.createBody({ type: 'dynamic', position: [0, 2] });
  body.createBox(0.5, 0.5);
  world.step();
  const hash = world.stateHash();
  refused(() => world.createBody({ type: 'dynamic', position: [Infinity, 0] }), 'I2D_ERR_INVALID_ARGUMENT', 'position.x');
  refused(() => world.createBody({ type: 'wobbly' }), 'I2D_ERR_INVALID_ARGUMENT', 'type');
  refused(() => body.createBox(-1, 1), 'I2D_ERR_INVALID_ARGUMENT', 'half');
  refused(() => body.createCircle(0), 'I2D_ERR_INVALID_ARGUMENT', 'radius');
  refused(() => body.createBox(0.5, 0.5, { density: NaN }), 'I2D_ERR_INVALID_ARGUMENT', 'density');
  refused(() => body.createPolygon([[0, 0], [1, 0], [2, 0]]), 'I2D_ERR_INVALID_ARGUMENT', 'ollinear');
  refused(() => body.createPolygon([[0, 0]]), 'I2D_ERR_INVALID_ARGUMENT', 'count');
  refused(() => body.createSegment([0, 0], [0, 0]), 'I2D_ERR_INVALID_ARGUMENT', 'segment');
  refused(() => body.setLinearVelocity([NaN, 0]), 'I2D_ERR_INVALID_ARGUMENT', 'NaN');
  refused(() => body.setTransform([0, 0], NaN), 'I2D_ERR_INVALID_ARGUMENT', 'rotation');
  refused(() => world.step(-1, 4), 'I2D_ERR_INVALID_ARGUMENT', 'time_step');
  refused(() => world.step(1 / 60, 0), 'I2D_ERR_INVALID_ARGUMENT', 'substep');
  assert.deepEqual(world.counters().bodyCount, 2);
  assert.deepEqual(world.counters().shapeCount, 2);
  assert.equal(world.stateHash(), hash);
  assert.equal(ground.shapes.length, 1);
  world.destroy();
});

test('stale handles are refused: destroyed bodies, shapes and worlds', () => {
  const { world } = groundedWorld();
  const body = world.createBody({ type: 'dynamic' });
  const shape = body.createCircle(0.5);
  shape.destroy();
  refused(() => shape.aabb(), 'I2D_ERR_INVALID_HANDLE', 'stale');
  refused(() => shape.destroy(), 'I2D_ERR_INVALID_HANDLE', 'stale');
  body.destroy();
  refused(() => body.position, 'I2D_ERR_INVALID_HANDLE', 'stale');
  refused(() => body.destroy(), 'I2D_ERR_INVALID_HANDLE', 'stale');
  refused(() => body.createBox(1, 1), 'I2D_ERR_INVALID_HANDLE', 'stale');
  world.destroy();
  refused(() => world.step(), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.createBody(), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.destroy(), 'I2D_ERR_INVALID_HANDLE', 'world');
});

test('bad query arguments are refused', () => {
  const { world } = groundedWorld();
  refused(() => world.overlapAABB(1, 1, 0, 0), 'I2D_ERR_INVALID_ARGUMENT', 'aabb');
  refused(() => world.castRayClosest([NaN, 0], [1, 0]), 'I2D_ERR_INVALID_ARGUMENT', 'origin');
  world.destroy();
});
