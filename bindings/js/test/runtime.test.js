// SPDX-License-Identifier: MIT
// The run-time API (issue 40) through the binding: each group checked by a closed-form
// figure or a round trip, and its refused calls throwing Impulse2dError.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { assertNear, i2d, groundedWorld, refused, stepSeconds } from './fixture.js';

test('a mass override gives F = m a, and the shapes give the mass back', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const box = world.createBody({ type: 'dynamic' });
  box.createBox(0.5, 0.5);  // 1 kg from its density
  box.massData = { mass: 4, center: [0, 0], rotationalInertia: 2 };
  assert.deepEqual(box.massData, { mass: 4, center: { x: 0, y: 0 }, rotationalInertia: 2 });
  box.applyForceToCenter([8, 0]);
  world.step(1 / 60, 4);
  assertNear(box.linearVelocity.x, 8 / 4 / 60, 1e-6, 'v after one step of F / m');
  box.applyMassFromShapes();
  assertNear(box.mass, 1, 1e-6, 'mass from the shapes');
  refused(() => box.setMassData({ mass: -1, rotationalInertia: 1 }), 'I2D_ERR_INVALID_ARGUMENT', 'mass');
  refused(() => box.setMassData({ mass: 1 }), 'I2D_ERR_INVALID_ARGUMENT', 'inertia');
  const ground = world.createBody();
  refused(() => ground.setMassData({ mass: 1, rotationalInertia: 1 }), 'I2D_ERR_INVALID_ARGUMENT', '');
  world.destroy();
});

test('body settings round trip, and bad values are refused with the body unchanged', () => {
  const world = i2d.createWorld();
  const body = world.createBody({ type: 'dynamic' });
  body.createCircle(0.5);
  body.bullet = true;
  body.sleepEnabled = false;
  body.sleepThreshold = 0.25;
  body.gravityScale = -0.5;
  body.linearDamping = 0.75;
  body.angularDamping = 1.5;
  body.fixedRotation = true;
  assert.deepEqual([body.bullet, body.sleepEnabled, body.fixedRotation], [true, false, true]);
  assert.deepEqual([body.sleepThreshold, body.gravityScale, body.linearDamping, body.angularDamping],
                   [0.25, -0.5, 0.75, 1.5]);
  refused(() => { body.linearDamping = -1; }, 'I2D_ERR_INVALID_ARGUMENT', 'damping');
  refused(() => { body.gravityScale = NaN; }, 'I2D_ERR_INVALID_ARGUMENT', 'NaN');
  refused(() => { body.sleepThreshold = -1; }, 'I2D_ERR_INVALID_ARGUMENT', '');
  assert.equal(body.linearDamping, 0.75);

  // A kinematic body sent to a target gets there in the step.
  const platform = world.createBody({ type: 'kinematic' });
  platform.createBox(1, 0.1);
  platform.setTargetTransform([0.5, 0.25], 0, 1 / 60);
  world.step(1 / 60, 4);
  assertNear(platform.position.x, 0.5, 1e-5, 'x');
  assertNear(platform.position.y, 0.25, 1e-5, 'y');
  refused(() => body.setTargetTransform([0, 0], 0, 1), 'I2D_ERR_INVALID_ARGUMENT', '');
  refused(() => platform.setTargetTransform([0, 0], 0, 0), 'I2D_ERR_INVALID_ARGUMENT', '');
  world.destroy();
});

test('disabling what a box rests on makes it fall; enabling brings it back', () => {
  const world = i2d.createWorld();
  const shelf = world.createBody({ position: [0, 5] });
  shelf.createBox(2, 0.1);
  const box = world.createBody({ type: 'dynamic', position: [0, 5.6] });
  box.createBox(0.5, 0.5);
  stepSeconds(world, 1);
  const resting = box.position.y;
  assertNear(resting, 5.6, 0.02, 'resting on the shelf');
  shelf.disable();
  assert.deepEqual([shelf.enabled, box.enabled], [false, true]);
  stepSeconds(world, 0.5);
  assert.ok(box.position.y < resting - 1, `y = ${box.position.y}`);  // g t^2 / 2 = 1.25 m
  shelf.enabled = true;
  assert.equal(shelf.enabled, true);
  shelf.destroy();
  refused(() => shelf.disable(), 'I2D_ERR_INVALID_HANDLE', 'stale');
  refused(() => shelf.enabled, 'I2D_ERR_INVALID_HANDLE', 'stale');
  world.destroy();
});

test('contact data of a resting box: two points, normal (0, 1), impulses m g dt / substeps', () => {
  const { world, ground } = groundedWorld();
  const box = world.createBody({ type: 'dynamic', position: [0, 0.5] });
  const shape = box.createBox(0.5, 0.5);
  stepSeconds(world, 1);
  const contacts = box.contactData();
  assert.equal(contacts.length, 1);
  const [contact] = contacts;
  assert.equal(contact.shapeA, ground.shapes[0]);
  assert.equal(contact.shapeB, shape);
  assert.equal(contact.points.length, 2);
  assertNear(contact.normal.x, 0, 1e-6, 'normal.x');
  assertNear(contact.normal.y, 1, 1e-6, 'normal.y');
  for (const p of contact.points) assertNear(p.point.y, 0, 0.01, 'point on the ground');
  const impulse = contact.points.reduce((sum, p) => sum + p.normalImpulse, 0);
  assertNear(impulse, (1 * 10) / 60 / 4, 1e-3, 'normal impulses of the last substep');
  assert.equal(shape.contactData().length, 1);
  assert.equal(ground.shapes[0].contactData().length, 1);
  shape.destroy();
  refused(() => shape.contactData(), 'I2D_ERR_INVALID_HANDLE', 'stale');
  world.destroy();
});

test('shape geometry, density, material, event flags and closest point', () => {
  const { world } = groundedWorld();
  const ball = world.createBody({ type: 'dynamic', position: [0, 0.5] });
  const shape = ball.createCircle(0.5);
  stepSeconds(world, 0.5);
  assertNear(ball.position.y, 0.5, 0.02, 'resting on radius 0.5');
  shape.setCircle(1);  // grown: it rises to rest on its new radius
  stepSeconds(world, 1);
  assertNear(ball.position.y, 1, 0.02, 'resting on radius 1');
  assertNear(ball.mass, Math.PI, 1e-4, 'mass of the grown circle');
  shape.density = 2;
  assert.equal(shape.density, 2);
  assertNear(ball.mass, 2 * Math.PI, 1e-4, 'mass at density 2');
  shape.setDensity(4, false);
  assertNear(ball.mass, 2 * Math.PI, 1e-4, 'mass kept');
  shape.setCapsule([-0.5, 0], [0.5, 0], 0.25);
  assert.equal(shape.type, 'capsule');
  shape.setPolygon([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]);
  assert.deepEqual(shape.geometry().vertices.length, 4);
  shape.setSegment([-1, 0], [1, 0]);
  assert.equal(shape.type, 'segment');
  refused(() => shape.setCircle(-1), 'I2D_ERR_INVALID_ARGUMENT', 'geometry');
  refused(() => shape.setPolygon([[0, 0], [1, 0], [2, 0]]), 'I2D_ERR_INVALID_ARGUMENT', 'ollinear');
  refused(() => shape.setPolygon([[0, 0]]), 'I2D_ERR_INVALID_ARGUMENT', 'count');
  refused(() => { shape.density = -1; }, 'I2D_ERR_INVALID_ARGUMENT', 'density');
  assert.equal(shape.type, 'segment');

  const material = { friction: 0.25, restitution: 0.5, rollingResistance: 0.125, tangentSpeed: 1.5 };
  shape.material = material;
  assert.deepEqual(shape.material, material);
  refused(() => { shape.material = { ...material, friction: -1 }; }, 'I2D_ERR_INVALID_ARGUMENT', 'friction');
  refused(() => { shape.material = { friction: 1 }; }, 'I2D_ERR_INVALID_ARGUMENT', '');
  shape.sensorEventsEnabled = false;
  shape.contactEventsEnabled = false;
  shape.hitEventsEnabled = true;
  assert.deepEqual([shape.sensorEventsEnabled, shape.contactEventsEnabled, shape.hitEventsEnabled], [false, false, true]);

  shape.setCircle(0.5);
  const p = ball.position;
  const closest = shape.closestPoint([p.x + 3, p.y]);
  assertNear(closest.x, p.x + 0.5, 1e-5, 'closest x');
  assertNear(closest.y, p.y, 1e-5, 'closest y');
  refused(() => shape.closestPoint([NaN, 0]), 'I2D_ERR_INVALID_ARGUMENT', '');
  world.destroy();
});

test('a sensor lists its visitor; a shape that is not a sensor is refused', () => {
  const { world, ground } = groundedWorld();
  const zone = world.createBody({ position: [0, 1] });
  const sensor = zone.createBox(2, 2, { isSensor: true });
  const ball = world.createBody({ type: 'dynamic', position: [0, 0.5] });
  const visitor = ball.createCircle(0.5);
  world.step();
  assert.deepEqual(sensor.sensorOverlaps(), [visitor]);
  refused(() => ground.shapes[0].sensorOverlaps(), 'I2D_ERR_INVALID_ARGUMENT', 'sensor');
  world.destroy();
});

test('the distance between two circles', () => {
  const d = i2d.shapeDistance({ points: [[0, 0]], radius: 0.5 }, { points: [[0, 0]], radius: 0.5, position: [3, 0] });
  assert.deepEqual(d, { pointA: { x: 0.5, y: 0 }, pointB: { x: 2.5, y: 0 }, normal: { x: 1, y: 0 }, distance: 2 });
  const overlapping = i2d.shapeDistance({ points: [[0, 0]], radius: 1 }, { points: [[1, 0]], radius: 1 });
  assert.equal(overlapping.distance, 0);
  refused(() => i2d.shapeDistance({ points: [] }, { points: [[0, 0]] }), 'I2D_ERR_INVALID_ARGUMENT', '');
  refused(() => i2d.shapeDistance({ points: [[0, 0]], radius: -1 }, { points: [[0, 0]] }), 'I2D_ERR_INVALID_ARGUMENT', '');
});

test('world settings round trip, and shiftOrigin moves every position', () => {
  const { world } = groundedWorld();
  world.enableSleeping(false);
  world.enableContinuous(false);
  assert.equal(world.settings().enableImpactChains, true);
  world.enableImpactChains(false);
  world.setContactTuning(20, 5, 2);
  world.setJointTuning(30, 1.5);
  world.setRestitutionThreshold(0.5);
  world.setHitEventThreshold(2.5);
  const s = world.settings();
  assert.deepEqual([s.enableSleep, s.enableContinuous, s.enableImpactChains], [false, false, false]);
  assert.deepEqual([s.contactHertz, s.contactDampingRatio, s.contactPushMaxSpeed], [20, 5, 2]);
  assert.deepEqual([s.jointHertz, s.jointDampingRatio, s.restitutionThreshold, s.hitEventThreshold], [30, 1.5, 0.5, 2.5]);
  assert.equal(s.lengthUnitsPerMeter, 1);
  refused(() => world.setContactTuning(-1, 5, 2), 'I2D_ERR_INVALID_ARGUMENT', 'hertz');
  refused(() => world.setHitEventThreshold(NaN), 'I2D_ERR_INVALID_ARGUMENT', '');
  assert.equal(world.settings().contactHertz, 20);

  const ball = world.createBody({ type: 'dynamic', position: [100, 20] });
  ball.createCircle(0.5);
  world.shiftOrigin([100, -20]);
  assert.deepEqual(ball.position, { x: 0, y: 40 });
  refused(() => world.shiftOrigin([NaN, 0]), 'I2D_ERR_INVALID_ARGUMENT', '');
  refused(() => world.shiftOrigin([2e9, 0]), 'I2D_ERR_INVALID_ARGUMENT', '');
  world.destroy();
  refused(() => world.settings(), 'I2D_ERR_INVALID_HANDLE', 'world');
});

test('a world in 50 units per metre falls 250 units in a second', () => {
  const defaults = i2d.defaultWorldSettings(50);
  const metres = i2d.defaultWorldSettings();
  assert.equal(defaults.lengthUnitsPerMeter, 50);
  assert.equal(defaults.gravity.y, 50 * metres.gravity.y);
  assertNear(defaults.contactSlop, 50 * metres.contactSlop, 1e-6, 'slop scaled');
  const world = i2d.createWorld({ lengthUnitsPerMeter: 50 });
  assert.deepEqual(world.settings(), defaults);
  const ground = world.createBody({ position: [0, -50] });
  ground.createBox(1000, 50);
  const ball = world.createBody({ type: 'dynamic', position: [0, 1000] });
  ball.createCircle(25);
  stepSeconds(world, 1);
  assertNear(ball.position.y, 1000 - 250, 5, 'g t^2 / 2 in units');
  stepSeconds(world, 5);
  assertNear(ball.position.y, 25, 0.5, 'resting on the ground');
  refused(() => i2d.createWorld({ lengthUnitsPerMeter: 0 }), 'I2D_ERR_INVALID_ARGUMENT', '');
  refused(() => i2d.defaultWorldSettings(1e5), 'I2D_ERR_INVALID_ARGUMENT', '');
  world.destroy();
});
