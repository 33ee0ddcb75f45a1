// SPDX-License-Identifier: MIT
// Queries through the wasm module: boxes, rays and shape geometry.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { groundedWorld } from './fixture.js';

function worldWithThreeBodies() {
  const { world, ground } = groundedWorld({ gravity: [0, 0] });
  const circle = world.createBody({ type: 'dynamic', position: [-5, 2] }).createCircle(0.5);
  const box = world.createBody({ type: 'dynamic', position: [0, 2] }).createBox(1, 0.5);
  const capsule = world.createBody({ type: 'dynamic', position: [5, 2] }).createCapsule([-0.5, 0], [0.5, 0], 0.25);
  return { world, ground: ground.shapes[0], circle, box, capsule };
}

test('an AABB query finds exactly the shapes whose geometry overlaps the box', () => {
  const { world, ground, circle, box, capsule } = worldWithThreeBodies();
  assert.deepEqual(new Set(world.overlapAABB(-6, 1, 6, 3)), new Set([circle, box, capsule]));
  assert.deepEqual(world.overlapAABB(-0.5, 1.8, 0.5, 2.2), [box]);
  assert.deepEqual(world.overlapAABB(-20, -0.5, 20, -0.1), [ground]);
  assert.deepEqual(world.overlapAABB(100, 100, 101, 101), []);
  world.destroy();
});

test('more hits than the first buffer holds are all returned', () => {
  const { world } = groundedWorld({ gravity: [0, 0] });
  for (let i = 0; i < 100; i++) world.createBody({ type: 'dynamic', position: [i * 0.1 - 5, 3] }).createCircle(0.04);
  assert.equal(world.overlapAABB(-6, 2, 6, 4).length, 100);
  world.destroy();
});

test('a ray finds the closest shape with its point, normal and fraction', () => {
  const { world, box } = worldWithThreeBodies();
  const hit = world.castRayClosest([0, 10], [0, -20]);
  assert.equal(hit.shape, box);
  assert.ok(Math.abs(hit.point.y - 2.5) < 1e-5);
  assert.deepEqual(hit.normal, { x: 0, y: 1 });
  assert.ok(Math.abs(hit.fraction - 7.5 / 20) < 1e-6);
  assert.equal(world.castRayClosest([0, 10], [0, 5]), null);
  world.destroy();
});

test('shapes report their kind, bounds and geometry in the body frame', () => {
  const { world, circle, box, capsule } = worldWithThreeBodies();
  assert.equal(circle.type, 'circle');
  assert.deepEqual(circle.geometry(), { type: 'circle', center: { x: 0, y: 0 }, radius: 0.5 });
  assert.deepEqual(box.aabb(), { minX: -1, minY: 1.5, maxX: 1, maxY: 2.5 });
  const polygon = box.geometry();
  assert.equal(polygon.vertices.length, 4);
  assert.deepEqual(polygon.vertices[2], { x: 1, y: 0.5 });
  assert.equal(capsule.geometry().radius, 0.25);
  box.friction = 0.25;
  assert.equal(box.friction, 0.25);
  world.destroy();
});
