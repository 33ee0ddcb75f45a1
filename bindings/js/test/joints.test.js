// SPDX-License-Identifier: MIT
// Joints through the wasm module: each kind against a closed form where one is cheap (a
// pendulum's period, a motor's acceleration, a spring's sag, a limit), every setting
// written at creation and through its setter, events, destruction and refused input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  DistanceJoint, FilterJoint, MotorJoint, MouseJoint, PrismaticJoint, RevoluteJoint, WeldJoint, WheelJoint,
} from '../src/index.js';
import { i2d, assertNear, groundedWorld, refused, stepSeconds } from './fixture.js';

const G = 10;

/** A dynamic body with one circle (density 1) at `position`. */
function disc(world, position, radius) {
  const body = world.createBody({ type: 'dynamic', position });
  body.createCircle(radius);
  return body;
}

/**
 * The mean period of x(t) crossing x0 upward, from linear interpolation between steps,
 * over `seconds` of stepping at 60 Hz with `each` called after every step.
 */
function measurePeriod(world, x, x0, seconds, each = () => {}) {
  const crossings = [];
  let previous = x();
  for (let i = 1; i <= Math.round(seconds * 60); i++) {
    world.step(1 / 60, 4);
    each();
    const now = x();
    if (previous < x0 && now >= x0) crossings.push((i - 1 + (x0 - previous) / (now - previous)) / 60);
    previous = now;
  }
  assert.ok(crossings.length >= 3, `only ${crossings.length} upward crossings`);
  return (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
}

test('a pendulum swings with the period 2 pi sqrt(L / g) within 1 %, on a revolute and on a distance joint', () => {
  const L = 1;
  const theta0 = 0.1;  // rad: small, so the amplitude lengthens the period by theta0^2 / 16 only
  const radius = 0.05;
  const pivot = [0, 10];
  const start = [L * Math.sin(theta0), pivot[1] - L * Math.cos(theta0)];
  const simple = 2 * Math.PI * Math.sqrt(L / G) * (1 + theta0 * theta0 / 16);

  // Hinged, the bob turns with the rod, adding its own inertia m r^2 / 2 to m L^2.
  {
    const world = i2d.createWorld({ gravity: [0, -G] });
    const anchor = world.createBody({ position: pivot });
    const bob = disc(world, start, radius);
    const hinge = world.createRevoluteJoint(anchor, bob, { localAnchorB: bob.getLocalPoint(pivot) });
    // The swing angle from the vertical, as the bob's centre shows it, against the joint's own measure.
    let worstAngle = 0;
    const period = measurePeriod(world, () => bob.position.x, 0, 10, () => {
      const p = bob.position;
      const swing = Math.atan2(p.x - pivot[0], pivot[1] - p.y);
      worstAngle = Math.max(worstAngle, Math.abs(hinge.angle - (swing - theta0)));
    });
    const expected = simple * Math.sqrt(1 + radius * radius / (2 * L * L));
    console.log(`revolute pendulum: period ${period.toFixed(5)} s, closed form ${expected.toFixed(5)} s ` +
                `(${(100 * (period / expected - 1)).toFixed(3)} %); joint angle within ${worstAngle.toExponential(2)} rad`);
    assertNear(period, expected, 0.01 * expected, 'revolute pendulum period');
    assertNear(worstAngle, 0, 2e-3, 'joint angle against the swing');
    world.destroy();
  }

  // On a rod between the centres, the bob keeps its orientation: a point mass.
  {
    const world = i2d.createWorld({ gravity: [0, -G] });
    const anchor = world.createBody({ position: pivot });
    const bob = disc(world, start, radius);
    const rod = world.createDistanceJoint(anchor, bob, { length: L });
    let worstLength = 0;
    const period = measurePeriod(world, () => bob.position.x, 0, 10, () => {
      worstLength = Math.max(worstLength, Math.abs(rod.currentLength - L));
    });
    console.log(`distance pendulum: period ${period.toFixed(5)} s, closed form ${simple.toFixed(5)} s ` +
                `(${(100 * (period / simple - 1)).toFixed(3)} %); length within ${worstLength.toExponential(2)} m`);
    assertNear(period, simple, 0.01 * simple, 'distance pendulum period');
    assertNear(worstLength, 0, 1e-3, 'rod length');
    world.destroy();
  }
});

test('a motor turns a disc up to its speed at max torque / inertia, then holds it; its setters take effect', () => {
  const world = i2d.createWorld({ gravity: [0, -G] });
  const axle = world.createBody({ position: [0, 5] });
  const radius = 0.5;
  const wheel = disc(world, [0, 5], radius);
  const inertia = wheel.mass * radius * radius / 2;
  const speed = 3;
  const torque = inertia * speed / 0.5;  // reaches its speed in 0.5 s
  const motor = world.createRevoluteJoint(axle, wheel, { enableMotor: true, motorSpeed: speed, maxMotorTorque: torque });
  stepSeconds(world, 0.25);
  console.log(`motor: ${wheel.angularVelocity.toFixed(5)} rad/s after 0.25 s, closed form ${(torque * 0.25 / inertia).toFixed(5)}; ` +
              `torque ${motor.motorTorque.toFixed(5)} N m of ${torque.toFixed(5)}`);
  assertNear(wheel.angularVelocity, torque * 0.25 / inertia, 0.01 * speed, 'speed while accelerating');
  assertNear(motor.motorTorque, torque, 1e-3 * torque, 'motor torque while accelerating');
  // The hinge carries the disc's weight: the force on B is m g up.
  assertNear(motor.reactionForce.y, wheel.mass * G, 0.01 * wheel.mass * G, 'reaction force');
  assertNear(motor.reactionForce.x, 0, 1e-4, 'sideways reaction');
  stepSeconds(world, 0.75);
  console.log(`motor: ${wheel.angularVelocity.toFixed(5)} rad/s after 1 s, motor speed ${speed}`);
  assertNear(wheel.angularVelocity, speed, 1e-4, 'speed held');
  assertNear(motor.motorTorque, 0, 1e-3 * torque, 'no torque at speed without load');

  motor.maxMotorTorque = 1e4;
  motor.motorSpeed = -speed;
  world.step();
  assertNear(wheel.angularVelocity, -speed, 1e-4, 'speed after reversing with a strong motor');
  motor.enableMotor = false;
  stepSeconds(world, 0.5);
  assertNear(wheel.angularVelocity, -speed, 1e-4, 'a free disc keeps turning');
  assert.equal(motor.enableMotor, false);
  world.destroy();
});

test('limits hold: a hinged bar rests on its lower angle, a slider on its lower translation', () => {
  const world = i2d.createWorld({ gravity: [0, -G] });
  const wall = world.createBody({ position: [0, 5] });
  const bar = world.createBody({ type: 'dynamic', position: [1, 5] });
  bar.createBox(1, 0.1);
  const hinge = world.createRevoluteJoint(wall, bar, {
    localAnchorB: [-1, 0], enableLimit: true, lowerAngle: -0.5, upperAngle: 0.5,
  });
  stepSeconds(world, 2);
  console.log(`revolute limit: angle ${hinge.angle.toFixed(5)} rad against a lower limit of -0.5`);
  assertNear(hinge.angle, -0.5, 0.01, 'bar on its lower limit');
  hinge.setLimits(-0.2, 0.5);
  stepSeconds(world, 1);
  assertNear(hinge.angle, -0.2, 0.01, 'bar on its raised lower limit');
  // One bound past the other is refused, and the joint keeps what it had.
  refused(() => { hinge.lowerAngle = 0.6; }, 'I2D_ERR_INVALID_ARGUMENT', 'lower_angle');
  assert.equal(hinge.lowerAngle, Math.fround(-0.2));

  const rail = world.createBody();
  const slider = world.createBody({ type: 'dynamic', position: [5, 5] });
  slider.createBox(0.5, 0.5);
  const prismatic = world.createPrismaticJoint(rail, slider, {
    localAnchorA: [5, 5], localAxisA: [0, 1], enableLimit: true, lowerTranslation: -1, upperTranslation: 2,
  });
  stepSeconds(world, 2);
  console.log(`prismatic limit: translation ${prismatic.translation.toFixed(5)} m against a lower limit of -1`);
  assertNear(prismatic.translation, -1, 0.01, 'slider on its lower limit');
  assertNear(prismatic.speed, 0, 0.01, 'slider at rest');
  // A motor of 100 N lifts the 1 kg slider at its speed, up to the upper limit.
  Object.assign(prismatic, { enableMotor: true, motorSpeed: 1, maxMotorForce: 100 });
  stepSeconds(world, 0.5);
  assertNear(prismatic.speed, 1, 0.01, 'slider driven at the motor speed');
  assertNear(prismatic.motorForce, slider.mass * G, 0.01 * slider.mass * G, 'motor force carrying the weight');
  stepSeconds(world, 3);
  assertNear(prismatic.translation, 2, 0.01, 'slider on its upper limit');
  world.destroy();
});

test('springs sag by g / (2 pi f)^2: a wheel on its suspension, a body held by a mouse joint', () => {
  const world = i2d.createWorld({ gravity: [0, -G] });
  const chassis = world.createBody({ position: [0, 2] });
  const wheel = disc(world, [0, 1], 0.4);
  const hertz = 2;
  const suspension = world.createWheelJoint(chassis, wheel, { localAnchorA: [0, -1], hertz, dampingRatio: 0.7 });
  stepSeconds(world, 3);
  const wheelSag = G / (2 * Math.PI * hertz) ** 2;
  console.log(`wheel sag ${(-suspension.translation).toFixed(5)} m, closed form ${wheelSag.toFixed(5)} m`);
  assertNear(-suspension.translation, wheelSag, 0.02 * wheelSag, 'wheel sag');
  Object.assign(suspension, { enableMotor: true, motorSpeed: 5, maxMotorTorque: 100 });
  stepSeconds(world, 0.5);
  assertNear(wheel.angularVelocity, 5, 1e-3, 'wheel driven at the motor speed');

  const ground = world.createBody();
  const box = world.createBody({ type: 'dynamic', position: [10, 5] });
  box.createBox(0.5, 0.5);
  const mouseHertz = 4;
  const mouse = world.createMouseJoint(ground, box, { target: [10, 5], hertz: mouseHertz, dampingRatio: 1, maxForce: 1000 });
  stepSeconds(world, 2);
  const mouseSag = G / (2 * Math.PI * mouseHertz) ** 2;
  console.log(`mouse sag ${(5 - box.position.y).toFixed(5)} m, closed form ${mouseSag.toFixed(5)} m`);
  assertNear(5 - box.position.y, mouseSag, 0.05 * mouseSag, 'mouse sag');
  mouse.target = [12, 6];
  stepSeconds(world, 2);
  assertNear(box.position.x, 12, 1e-3, 'box dragged to the new target');
  assertNear(box.position.y, 6 - mouseSag, 1e-3, 'box under the new target');
  // Half the box's weight is all the joint may pull with: it falls at g / 2.
  mouse.maxForce = box.mass * G / 2;
  const y0 = box.position.y;
  stepSeconds(world, 1);
  assertNear(y0 - box.position.y, G / 4, 0.05 * G / 4, 'fall against a force-limited mouse joint');
  world.destroy();
});

test('a motor joint drives its body to the offset pose; a weld holds its body; a filter joint lets two bodies pass', () => {
  const free = i2d.createWorld({ gravity: [0, 0] });
  const base = free.createBody();
  const puck = free.createBody({ type: 'dynamic' });
  puck.createBox(0.5, 0.5);
  free.createMotorJoint(base, puck, { linearOffset: [2, 1], angularOffset: 0.5, maxForce: 100, maxTorque: 100 });
  stepSeconds(free, 3);
  assertNear(puck.position.x, 2, 0.01, 'motor joint x');
  assertNear(puck.position.y, 1, 0.01, 'motor joint y');
  assertNear(puck.angle, 0.5, 0.01, 'motor joint angle');
  free.destroy();

  const { world } = groundedWorld();
  const wall = world.createBody({ position: [0, 5] });
  const shelf = world.createBody({ type: 'dynamic', position: [0.5, 5] });
  shelf.createBox(0.5, 0.1);
  const weld = world.createWeldJoint(wall, shelf, { localAnchorB: [-0.5, 0] });
  stepSeconds(world, 1);
  assertNear(shelf.position.y, 5, 0.01, 'welded shelf height');
  assertNear(shelf.angle, 0, 0.01, 'welded shelf angle');
  assert.ok(weld.reactionTorque > 0, `the weld holds the shelf up: torque ${weld.reactionTorque}`);

  const lower = world.createBody({ type: 'dynamic', position: [5, 0.5] });
  lower.createBox(0.5, 0.5);
  const upper = world.createBody({ type: 'dynamic', position: [5, 3] });
  upper.createBox(0.5, 0.5);
  world.createFilterJoint(lower, upper);
  stepSeconds(world, 2);
  assertNear(upper.position.y, 0.5, 0.02, 'the upper box fell through the lower one to the ground');
  world.destroy();
});

// A value different from the default for every setting of every kind, so that a setting
// written to the wrong place, or not at all, reads back wrong.
const SETTINGS = {
  revolute: {
    referenceAngle: 0.25, enableLimit: true, lowerAngle: -0.5, upperAngle: 0.75, enableMotor: true, motorSpeed: 2,
    maxMotorTorque: 10, enableSpring: true, hertz: 3, dampingRatio: 0.5, targetAngle: 0.125,
  },
  prismatic: {
    localAxisA: { x: 0, y: 1 }, referenceAngle: 0.25, enableLimit: true, lowerTranslation: -1, upperTranslation: 2,
    enableMotor: true, motorSpeed: 1.5, maxMotorForce: 20, enableSpring: true, hertz: 2, dampingRatio: 0.25,
    targetTranslation: 0.5,
  },
  distance: {
    length: 2, enableLimit: true, minLength: 1, maxLength: 3, enableSpring: true, hertz: 4, dampingRatio: 0.5,
    enableMotor: true, motorSpeed: 0.5, maxMotorForce: 30,
  },
  weld: { referenceAngle: 0.5, linearHertz: 5, angularHertz: 6, linearDampingRatio: 0.5, angularDampingRatio: 0.75 },
  wheel: {
    localAxisA: { x: 1, y: 0 }, enableSpring: false, hertz: 3, dampingRatio: 0.25, enableLimit: true,
    lowerTranslation: -0.5, upperTranslation: 0.5, enableMotor: true, motorSpeed: 4, maxMotorTorque: 8,
  },
  motor: { linearOffset: { x: 1, y: 2 }, angularOffset: 0.5, maxForce: 50, maxTorque: 25, correctionFactor: 0.5 },
  mouse: { target: { x: 1, y: 2 }, hertz: 6, dampingRatio: 0.5, maxForce: 250 },
  filter: {},
};
const BASE = {
  localAnchorA: { x: 0.5, y: 0.25 }, localAnchorB: { x: -0.5, y: 0 }, collideConnected: true, forceThreshold: 100,
  torqueThreshold: 50,
};
const CLASSES = {
  revolute: RevoluteJoint, prismatic: PrismaticJoint, distance: DistanceJoint, weld: WeldJoint,
  wheel: WheelJoint, motor: MotorJoint, mouse: MouseJoint, filter: FilterJoint,
};
const creator = (kind) => `create${kind[0].toUpperCase()}${kind.slice(1)}Joint`;

test('every kind takes each of its settings at creation and through its setter, and reads it back', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const a = world.createBody();
  const b = disc(world, [1, 0], 0.25);
  for (const [kind, settings] of Object.entries(SETTINGS)) {
    const expected = { ...BASE, ...settings };
    const read = (joint) => Object.fromEntries(Object.keys(expected).map((name) => [name, joint[name]]));
    const created = world[creator(kind)](a, b, expected);
    assert.ok(created instanceof CLASSES[kind], kind);
    assert.equal(created.type, kind);
    assert.deepEqual(read(created), expected, `${kind}: settings given at creation`);
    const set = world[creator(kind)](a, b);
    assert.notDeepEqual(read(set), expected, `${kind}: the defaults differ from the values set`);
    Object.assign(set, expected);  // in the table's order: each lower bound before its upper one
    assert.deepEqual(read(set), expected, `${kind}: settings given through the setters`);
    assert.equal(set.bodyA, a);
    assert.equal(set.bodyB, b);
  }
  // Axes are stored at unit length.
  const slider = world.createPrismaticJoint(a, b, { localAxisA: [0, 2] });
  assert.deepEqual(slider.localAxisA, { x: 0, y: 1 });
  assert.equal(world.jointCount(), 2 * Object.keys(SETTINGS).length + 1);
  assert.deepEqual(world.joints, [...a.joints]);
  world.destroy();
});

test('a joint whose reaction passes its force threshold is listed after the step, and can be broken', () => {
  const world = i2d.createWorld({ gravity: [0, -G] });
  const hook = world.createBody({ position: [0, 5] });
  const box = world.createBody({ type: 'dynamic', position: [0, 4] });
  box.createBox(0.5, 0.5);
  const weight = box.mass * G;
  const rope = world.createDistanceJoint(hook, box, { length: 1, forceThreshold: 1.5 * weight });
  stepSeconds(world, 1);
  assert.deepEqual(world.jointEvents(), []);
  assertNear(rope.reactionForce.y, weight, 0.01 * weight, 'the rope carries the weight');
  rope.forceThreshold = 0.5 * weight;
  world.step();
  const events = world.jointEvents();
  assert.equal(events.length, 1);
  assert.equal(events[0], rope);
  events[0].destroy();
  assert.equal(world.jointCount(), 0);
  const y0 = box.position.y;
  stepSeconds(world, 0.5);
  assert.ok(y0 - box.position.y > 1, `the box fell once the rope broke (${(y0 - box.position.y).toFixed(2)} m)`);
  world.destroy();
});

test('stale joints are refused: destroyed, destroyed with a body, destroyed with the world', () => {
  const world = i2d.createWorld();
  const ground = world.createBody();
  const a = disc(world, [0, 0], 0.5);
  const b = disc(world, [2, 0], 0.5);
  const hinge = world.createRevoluteJoint(a, b);
  const rope = world.createDistanceJoint(ground, a);
  const weld = world.createWeldJoint(ground, b);
  hinge.destroy();
  assert.equal(hinge.isValid(), false);
  refused(() => hinge.angle, 'I2D_ERR_INVALID_HANDLE', 'stale');
  refused(() => { hinge.motorSpeed = 1; }, 'I2D_ERR_INVALID_HANDLE', 'stale');
  refused(() => hinge.destroy(), 'I2D_ERR_INVALID_HANDLE', 'stale');
  assert.deepEqual(world.joints, [rope, weld]);

  // Destroying a body destroys its joints, in the library and in the binding's lists.
  a.destroy();
  assert.equal(rope.isValid(), false);
  refused(() => rope.currentLength, 'I2D_ERR_INVALID_HANDLE', 'stale');
  assert.equal(world.jointCount(), 1);
  assert.deepEqual(world.joints, [weld]);
  assert.deepEqual(ground.joints, [weld]);
  assert.deepEqual(b.joints, [weld]);
  world.destroy();
  refused(() => weld.reactionForce, 'I2D_ERR_INVALID_HANDLE', 'world');
});

test('bad joints and values are refused with the library message; the world is unchanged', () => {
  const { world, ground } = groundedWorld();
  const box = world.createBody({ type: 'dynamic', position: [0, 2] });
  box.createBox(0.5, 0.5);
  const other = i2d.createWorld();
  const stranger = other.createBody({ type: 'dynamic' });
  const shelf = world.createBody({ position: [3, 0] });
  const hinge = world.createRevoluteJoint(ground, box, { localAnchorA: [0, 3] });
  world.step();
  const hash = world.stateHash();

  refused(() => world.createRevoluteJoint(box, box), 'I2D_ERR_INVALID_ARGUMENT', 'same body');
  refused(() => world.createRevoluteJoint(ground, shelf), 'I2D_ERR_INVALID_ARGUMENT', 'dynamic');
  refused(() => world.createRevoluteJoint(ground, stranger), 'I2D_ERR_INVALID_ARGUMENT', 'another world');
  refused(() => world.createWeldJoint(ground, undefined), 'I2D_ERR_INVALID_HANDLE', 'body_b');
  refused(() => world.createMouseJoint(box, ground), 'I2D_ERR_INVALID_ARGUMENT', 'mouse joint drags a dynamic body');
  refused(() => world.createRevoluteJoint(ground, box, { enableLimit: true, lowerAngle: 1, upperAngle: 0.5 }),
          'I2D_ERR_INVALID_ARGUMENT', 'lower_angle');
  refused(() => world.createRevoluteJoint(ground, box, { lowerAngle: 4 }), 'I2D_ERR_INVALID_ARGUMENT', 'lower_angle');
  refused(() => world.createRevoluteJoint(ground, box, { maxMotorTorque: -1 }), 'I2D_ERR_INVALID_ARGUMENT',
          'max_motor_torque');
  refused(() => world.createDistanceJoint(ground, box, { length: 0 }), 'I2D_ERR_INVALID_ARGUMENT', 'length');
  refused(() => world.createPrismaticJoint(ground, box, { localAxisA: [0, 0] }), 'I2D_ERR_INVALID_ARGUMENT',
          'local_axis_a');
  refused(() => world.createWheelJoint(ground, box, { localAnchorA: [NaN, 0] }), 'I2D_ERR_INVALID_ARGUMENT',
          'local_anchor_a');
  refused(() => world.createMotorJoint(ground, box, { correctionFactor: 2 }), 'I2D_ERR_INVALID_ARGUMENT',
          'correction_factor');
  refused(() => { hinge.motorSpeed = NaN; }, 'I2D_ERR_INVALID_ARGUMENT', 'motor_speed');
  refused(() => { hinge.hertz = -1; }, 'I2D_ERR_INVALID_ARGUMENT', 'hertz');
  refused(() => { hinge.forceThreshold = -1; }, 'I2D_ERR_INVALID_ARGUMENT', 'threshold');
  refused(() => hinge.setLimits(0.5, -0.5), 'I2D_ERR_INVALID_ARGUMENT', 'lower_angle');
  // A setting the kind does not have is the binding's own refusal, before the library is called.
  assert.throws(() => world.createRevoluteJoint(ground, box, { maxMotorTorgue: 5 }),
                { name: 'TypeError', message: /no setting 'maxMotorTorgue'.*maxMotorTorque/ });

  assert.equal(world.jointCount(), 1);
  assert.deepEqual(world.joints, [hinge]);
  assert.deepEqual(box.joints, [hinge]);
  assert.equal(hinge.motorSpeed, 0);
  assert.equal(hinge.hertz, 0);
  assert.equal(world.stateHash(), hash);
  other.destroy();
  world.destroy();
});
