// SPDX-License-Identifier: MIT
// Creating, stepping and destroying worlds and bodies through the wasm module.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { SIMD_PATH_NAMES } from '../src/index.js';
import { i2d, groundedWorld, stepSeconds } from './fixture.js';

// The package and the library it wraps carry one version.
const packageVersion = JSON.parse(readFileSync(new URL('../package.json', import.meta.url))).version;

test('the module reports the library version and solves contacts on its widest path', () => {
  const [major, minor, patch] = packageVersion.split('.').map(Number);
  assert.equal(i2d.version, (major << 16) | (minor << 8) | patch);
  const world = i2d.createWorld();
  assert.equal(SIMD_PATH_NAMES[world.simdPath()], i2d.simd ? 'wasm128' : 'scalar');
  assert.equal(world.settings().simdPath, 'automatic');
  world.destroy();
});

test('a world takes its options and counts what it holds', () => {
  const world = i2d.createWorld({ gravity: [1, -3] });
  assert.deepEqual(world.gravity, { x: 1, y: -3 });
  world.gravity = { x: 0, y: -9.5 };
  assert.deepEqual(world.gravity, { x: 0, y: -9.5 });
  const body = world.createBody({ type: 'dynamic' });
  body.createBox(0.5, 0.5);
  body.createCircle(0.25, { center: [1, 0] });
  assert.equal(world.counters().bodyCount, 1);
  assert.equal(world.counters().shapeCount, 2);
  world.destroy();
  assert.equal(world.isValid(), false);
});

test('a falling body follows gravity: after 1 s it has fallen g t^2 / 2 within a centimetre', () => {
  const world = i2d.createWorld({ gravity: [0, -10] });
  const body = world.createBody({ type: 'dynamic', position: [0, 100] });
  body.createCircle(0.5);
  stepSeconds(world, 1);
  assert.ok(Math.abs(body.position.y - 95) < 0.1, `y = ${body.position.y}`);
  assert.ok(Math.abs(body.linearVelocity.y + 10) < 1e-3, `vy = ${body.linearVelocity.y}`);
  world.destroy();
});

test('a box dropped on the ground comes to rest on it and falls asleep', () => {
  const { world } = groundedWorld();
  const box = world.createBody({ type: 'dynamic', position: [0, 3], angle: 0.3 });
  box.createBox(0.5, 0.5, { density: 2 });
  assert.equal(box.mass, 2);
  stepSeconds(world, 4);
  const { y } = box.position;
  assert.ok(Math.abs(y - 0.5) < 0.02, `resting centre at ${y}`);
  assert.ok(Math.abs(Math.sin(2 * box.angle)) < 0.01, `face down: angle ${box.angle}`);
  assert.equal(box.awake, false);
  assert.equal(box.quarantined, false);
  world.destroy();
});

test('velocities, transforms and impulses set through the binding reach the body', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const body = world.createBody({ type: 'dynamic', linearVelocity: [1, 0] });
  body.createCircle(1);
  body.setLinearVelocity({ x: 0, y: 2 });
  body.angularVelocity = 0.5;
  assert.deepEqual(body.linearVelocity, { x: 0, y: 2 });
  assert.equal(body.angularVelocity, 0.5);
  body.setTransform([3, 4], Math.PI / 2);
  assert.deepEqual(body.position, { x: 3, y: 4 });
  assert.ok(Math.abs(body.angle - Math.PI / 2) < 1e-6);
  body.applyLinearImpulse([body.mass * 2, 0]);
  assert.ok(Math.abs(body.linearVelocity.x - 2) < 1e-5);
  world.destroy();
});

test('two runs of the same scene end in the same state hash; a changed one does not', () => {
  const run = (x) => {
    const { world } = groundedWorld();
    for (let i = 0; i < 10; i++) {
      world.createBody({ type: 'dynamic', position: [x + 0.3 * i, 1 + 1.1 * i] }).createBox(0.5, 0.5);
    }
    stepSeconds(world, 1);
    const hash = world.stateHash();
    world.destroy();
    return hash;
  };
  assert.equal(run(0), run(0));
  assert.notEqual(run(0), run(0.01));
});

test('destroying a body destroys its shapes and frees its index for the next body', () => {
  const { world } = groundedWorld();
  const body = world.createBody({ type: 'dynamic', position: [0, 2] });
  const shape = body.createBox(0.5, 0.5);
  const index = body.index;
  body.destroy();
  assert.equal(body.isValid(), false);
  assert.equal(shape.isValid(), false);
  assert.equal(world.counters().bodyCount, 1);
  assert.equal(world.createBody({ type: 'dynamic' }).index, index);
  world.destroy();
});
