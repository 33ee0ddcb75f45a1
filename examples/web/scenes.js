// SPDX-License-Identifier: MIT
// The page's scenes. Each builds its bodies in a fresh world and says how to judge a
// run: check(world, scene, seconds simulated) returns the figures the browser test reads back.
// The scene a build returns has the camera's view and, optionally, what the page calls
// on it: update(actions, timeStep) after each step, drawExtras(drawer) after the world is
// drawn, takesKeys (the platformer's keys), action {label, run} (a button), click(point)
// (a click off every body), saveGame() / restoreGame(saved) (game state to rewind).
import { explosionScene, explosionState } from './explosion.js';
import { jointsScene, jointsState } from './joints_scene.js';
import { platformer, platformerState } from './platformer.js';

const DEG = Math.PI / 180;

/** Rows of 1 m boxes on a ground box, as the benchmark's large_pyramid but smaller. */
function pyramid(world, rows = 20) {
  const ground = world.createBody({ position: [0, -1] });
  ground.createBox(40, 1);
  let top = null;
  for (let i = 0; i < rows; i++) {
    for (let j = i; j < rows; j++) {
      const x = -rows / 2 + 0.5 * (i + 1) + (j - i);
      top = world.createBody({ type: 'dynamic', position: [x, i + 0.5] });
      top.createBox(0.5, 0.5);
    }
  }
  return { view: { x: 0, y: rows / 2, height: rows + 6 }, top, topStartY: top.position.y };
}

/** Boxes, circles, capsules and triangles dropped in a walled bin. */
function mixedShapes(world, count = 240) {
  const ground = world.createBody();
  ground.createOffsetBox(15, 0.5, [0, -0.5]);
  ground.createOffsetBox(0.5, 10, [-15.5, 9.5]);
  ground.createOffsetBox(0.5, 10, [15.5, 9.5]);
  ground.createOffsetBox(4, 0.25, [-6, 6], -20 * DEG);
  ground.createOffsetBox(4, 0.25, [6, 9], 20 * DEG);
  for (let i = 0; i < count; i++) {
    const x = -12 + (i % 24) * 1.05 + 0.2 * ((i * 7) % 3);
    const y = 14 + Math.floor(i / 24) * 1.2;
    const body = world.createBody({ type: 'dynamic', position: [x, y], angle: (i % 11) * 0.3 });
    switch (i % 4) {
      case 0: body.createBox(0.4, 0.3); break;
      case 1: body.createCircle(0.4, { restitution: 0.2 }); break;
      case 2: body.createCapsule([-0.3, 0], [0.3, 0], 0.2); break;
      default: body.createPolygon([[-0.45, -0.35], [0.45, -0.35], [0, 0.45]]); break;
    }
  }
  return { view: { x: 0, y: 10, height: 24 }, floorY: -1 };
}

// Box2D's tumbler benchmark (bench/scenes.c builds the same drum): a dynamic drum on a
// revolute joint to a static body, its motor at 25 deg/s with a max torque of 1e8 N m,
// which no load of boxes can slow.
const TUMBLER_SPEED = 25 * DEG;      // rad/s, counter-clockwise
const TUMBLER_MAX_TORQUE = 1e8;      // N m
const TUMBLER_DRUM_DENSITY = 50;     // kg/m^2: a 4000 kg drum, heavy against its load

/** A 20 m hollow drum of four 1 m thick walls, turned by its motor, with small boxes inside. */
function tumbler(world, side = 30) {
  const center = { x: 0, y: 10 };
  const pivot = world.createBody();  // static, no shapes: what the hinge holds on to
  const drum = world.createBody({ type: 'dynamic', position: center });
  const walls = { density: TUMBLER_DRUM_DENSITY };
  drum.createOffsetBox(0.5, 10, [10, 0], 0, walls);
  drum.createOffsetBox(0.5, 10, [-10, 0], 0, walls);
  drum.createOffsetBox(10, 0.5, [0, 10], 0, walls);
  drum.createOffsetBox(10, 0.5, [0, -10], 0, walls);
  world.createRevoluteJoint(pivot, drum, {
    localAnchorA: center, enableMotor: true, motorSpeed: TUMBLER_SPEED, maxMotorTorque: TUMBLER_MAX_TORQUE,
  });
  for (let i = 0; i < side; i++) {
    for (let j = 0; j < side; j++) {
      world.createBody({ type: 'dynamic', position: [-7 + 0.5 * j, 3 + 0.5 * i] }).createBox(0.125, 0.125);
    }
  }
  return { view: { x: 0, y: 10, height: 32 }, drum, center, radius: 15 };
}

/** The signed difference of two angles, in (-pi, pi]. */
function angleBetween(a, b) {
  const d = (a - b) % (2 * Math.PI);
  return d > Math.PI ? d - 2 * Math.PI : d <= -Math.PI ? d + 2 * Math.PI : d;
}

export const SCENES = {
  pyramid: {
    title: 'Pyramid (20 rows, 210 boxes)',
    build: (world) => pyramid(world),
    worldOptions: { enableSleep: false },
    check: (world, scene) => ({ topDrop: scene.topStartY - scene.top.position.y }),
  },
  mixed: {
    title: 'Falling mixed shapes (240)',
    build: (world) => mixedShapes(world),
    worldOptions: {},
    check: (world, scene) => ({
      below: world.bodies.filter((b) => b.type === 'dynamic' && b.position.y < scene.floorY).length,
    }),
  },
  tumbler: {
    title: 'Tumbler (900 boxes, drum on a motor)',
    build: (world) => tumbler(world),
    worldOptions: {},
    check: (world, scene, seconds) => ({
      escaped: world.bodies.filter((b) => {
        const p = b.position;
        return b.type === 'dynamic' && Math.hypot(p.x - scene.center.x, p.y - scene.center.y) > scene.radius;
      }).length,
      drumAngle: scene.drum.angle,
      drumType: scene.drum.type,
      // The motor keeps time under the load, and the hinge keeps the drum's centre.
      drumAngleError: angleBetween(scene.drum.angle, TUMBLER_SPEED * seconds),
      drumDrift: Math.hypot(scene.drum.position.x - scene.center.x, scene.drum.position.y - scene.center.y),
    }),
  },
  platformer: {
    title: 'Platformer (arrows or A/D walk, Space/W/Up jump)',
    build: (world) => platformer(world),
    // Its one-way platform is a JavaScript pre-solve hook, which only a world stepped on
    // this thread can call.
    worldOptions: { workerCount: 1 },
    check: (world, scene) => platformerState(scene),
  },
  explosion: {
    title: 'Explosion (click, or Blast)',
    build: (world) => explosionScene(world),
    worldOptions: {},
    check: (world, scene) => explosionState(world, scene),
  },
  joints: {
    title: 'Joints (bridge, chain, slider, spring, car, weld)',
    build: (world) => jointsScene(world),
    worldOptions: {},
    check: (world, scene) => jointsState(world, scene),
  },
};
