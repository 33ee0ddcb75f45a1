// SPDX-License-Identifier: MIT
// The joints scene: a plank bridge and a swinging chain on revolute joints, a box on a
// sprung prismatic joint, a ball on a sprung distance joint, a car on wheel joints whose
// motors drive it, and two boxes welded into an L dropped on the bridge. The "joint
// extras" toggle shows their limits, motors and springs.

const FLOOR_HALF_WIDTH = 12;
const BRIDGE = { from: -11, to: -1.5, y: 5, planks: 16, thickness: 0.125 };
const CHAIN = { anchor: { x: 1.5, y: 11 }, links: 10, length: 0.5, radius: 0.1 };
const CAR = { x: -8.5, wheelRadius: 0.4, motorSpeed: -2, motorTorque: 40, suspensionHertz: 4 };

export function jointsScene(world) {
  const ground = world.createBody();
  ground.createOffsetBox(FLOOR_HALF_WIDTH, 0.5, [0, -0.5]);
  for (const side of [-1, 1]) ground.createOffsetBox(0.5, 6, [side * (FLOOR_HALF_WIDTH + 0.5), 6]);
  const middle = bridge(world);
  const chainEnd = chain(world);
  slider(world, { x: 6.5, y: 2 });
  springBall(world, { x: 10, y: 11 });
  const car = carOnWheels(world, { x: CAR.x, y: 1 });
  weldedL(world, { x: -6.5, y: 9 });
  return { view: { x: 0, y: 5.5, height: 16 }, middle, chainEnd, car, carStartX: CAR.x };
}

/**
 * A static body without shapes at a point, for a joint to hold on to. Joints are drawn
 * from each body's origin to its anchor: one at the anchor draws no line across the scene.
 */
function fixedPoint(world, point) {
  return world.createBody({ position: [point.x, point.y] });
}

/** Planks pinned end to end, and at both ends to fixed points. */
function bridge(world) {
  const { from, to, y, planks, thickness } = BRIDGE;
  const width = (to - from) / planks;
  let previous = fixedPoint(world, { x: from, y });
  let middle = null;
  for (let i = 0; i < planks; i++) {
    const plank = world.createBody({ type: 'dynamic', position: [from + (i + 0.5) * width, y] });
    plank.createBox(width / 2, thickness, { density: 20 });
    pin(world, previous, plank, { x: from + i * width, y });
    if (i === planks >> 1) middle = plank;
    previous = plank;
  }
  pin(world, previous, fixedPoint(world, { x: to, y }), { x: to, y });
  return middle;
}

/** A revolute joint between a and b at a world point. */
function pin(world, a, b, point) {
  return world.createRevoluteJoint(a, b, { localAnchorA: a.getLocalPoint(point), localAnchorB: b.getLocalPoint(point) });
}

/** Capsule links laid out level from a fixed point, so that the chain swings down. */
function chain(world) {
  const { anchor, links, length, radius } = CHAIN;
  let previous = fixedPoint(world, anchor);
  let link = null;
  for (let i = 0; i < links; i++) {
    link = world.createBody({ type: 'dynamic', position: [anchor.x + (i + 0.5) * length, anchor.y] });
    link.createCapsule([-length / 2, 0], [length / 2, 0], radius);
    pin(world, previous, link, { x: anchor.x + i * length, y: anchor.y });
    previous = link;
  }
  return link;
}

/** A box on a vertical prismatic joint with limits, sprung toward the middle of its
 *  travel from the bottom, lightly damped: it bobs. */
function slider(world, at) {
  const box = world.createBody({ type: 'dynamic', position: [at.x, at.y] });
  box.createBox(0.75, 0.5);
  world.createPrismaticJoint(fixedPoint(world, at), box, {
    localAxisA: [0, 1], enableLimit: true, lowerTranslation: -1, upperTranslation: 5,
    enableSpring: true, hertz: 0.5, dampingRatio: 0.05, targetTranslation: 3,
  });
}

/** A ball hanging 3 m below a point on a soft distance joint, let go from higher up. */
function springBall(world, at) {
  const ball = world.createBody({ type: 'dynamic', position: [at.x, at.y - 1] });
  ball.createCircle(0.5);
  world.createDistanceJoint(fixedPoint(world, at), ball, {
    length: 3, enableSpring: true, hertz: 1.5, dampingRatio: 0.1,
  });
}

/** A chassis on two sprung wheels whose motors drive it to the right. */
function carOnWheels(world, at) {
  const chassis = world.createBody({ type: 'dynamic', position: [at.x, at.y + 0.5] });
  chassis.createBox(1.2, 0.25);
  for (const dx of [-0.8, 0.8]) {
    const wheel = world.createBody({ type: 'dynamic', position: [at.x + dx, at.y - 0.2] });
    wheel.createCircle(CAR.wheelRadius, { friction: 1.2 });
    world.createWheelJoint(chassis, wheel, {
      localAnchorA: chassis.getLocalPoint(wheel.position), localAxisA: [0, 1], hertz: CAR.suspensionHertz,
      dampingRatio: 0.7, enableMotor: true, motorSpeed: CAR.motorSpeed, maxMotorTorque: CAR.motorTorque,
    });
  }
  return chassis;
}

/** Two boxes held rigidly at a right angle by a weld joint. */
function weldedL(world, at) {
  const upright = world.createBody({ type: 'dynamic', position: [at.x, at.y] });
  upright.createBox(0.2, 0.8);
  const foot = world.createBody({ type: 'dynamic', position: [at.x + 0.6, at.y - 0.6] });
  foot.createBox(0.4, 0.2);
  const corner = { x: at.x + 0.2, y: at.y - 0.6 };
  world.createWeldJoint(upright, foot, { localAnchorA: upright.getLocalPoint(corner), localAnchorB: foot.getLocalPoint(corner) });
}

/** What the browser test reads back. */
export function jointsState(world, scene) {
  return {
    bridgeSag: BRIDGE.y - scene.middle.position.y,
    chainEndDrop: CHAIN.anchor.y - scene.chainEnd.position.y,
    carTravel: scene.car.position.x - scene.carStartX,
    below: world.bodies.filter((b) => b.type === 'dynamic' && b.position.y < 0).length,
  };
}
