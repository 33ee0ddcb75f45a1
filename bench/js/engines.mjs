// SPDX-License-Identifier: MIT
// One adapter per engine, so that every scene is built by the same code: static and
// dynamic boxes and circles, the tumbler's motor-driven drum, a step, and a body's
// position and angle (metres and radians, y up, counter-clockwise).
// Each engine runs at its own recommended settings for 60 Hz:
//   impulse2d  1/60 s, 4 substeps (as Box2D v3's benchmark); its SIMD build (4-lane
//              WebAssembly SIMD kernels), its scalar build, and its threads build (SIMD
//              kernels) on 1 and 2 workers
//   Rapier2D   1/60 s, its defaults (4 solver iterations, 1 internal PGS iteration); its
//              plain build and its SIMD build (@dimforge/rapier2d-simd-compat)
//   planck     1/60 s, 8 velocity and 3 position iterations (Box2D 2.x's defaults)
//   matter-js  1000/60 ms, its defaults (6 position, 4 velocity iterations); 1 m = 20 px
// The drum is a dynamic body on a revolute joint's motor in impulse2d, Rapier2D and planck;
// matter-js has no joint motor, so its drum is static and turned by the adapter each step
// (kinematic), which no load can slow: its drumDrive says so in the output.
import { loadImpulse2d } from '../../bindings/js/src/index.js';
import RAPIER_PLAIN from '@dimforge/rapier2d-compat';
import RAPIER_SIMD from '@dimforge/rapier2d-simd-compat';
import * as planck from 'planck';
import Matter from 'matter-js';

const FRICTION = 0.6;
// Rapier's velocity motor is a damped servo whose factor (the damping of its default,
// acceleration-based model) sets how hard it pulls toward the target speed. After 120 steps
// of the tumbler its drum was 22 degrees behind at 1, a quarter of a degree at 100 and
// 0.003 at 1e4: at 1e4 the boxes no longer hold it back, as they do not hold back Box2D's
// motor of 1e8 N m.
const RAPIER_MOTOR_FACTOR = 1e4;

// The threads build is loaded once, for both of its worker counts.
let threadsBuild = null;

async function impulse2dEngine(name, { simd = true, threads = false, workerCount = 1 } = {}) {
  const i2d = threads ? (threadsBuild ??= await loadImpulse2d({ threads: true })) : await loadImpulse2d({ simd });
  const drumDrive = 'revolute motor';
  return {
    name,
    drumDrive,
    createWorld({ sleep }) {
      const world = i2d.createWorld({ gravity: [0, -10], enableSleep: sleep, workerCount });
      return {
        staticBox(x, y, hw, hh) { world.createBody({ position: [x, y] }).createBox(hw, hh, { friction: FRICTION }); },
        box(x, y, hw, hh) {
          const body = world.createBody({ type: 'dynamic', position: [x, y] });
          body.createBox(hw, hh, { friction: FRICTION });
          return body;
        },
        circle(x, y, r) {
          const body = world.createBody({ type: 'dynamic', position: [x, y] });
          body.createCircle(r, { friction: FRICTION });
          return body;
        },
        motorDrum({ center, walls, density, speed, maxTorque }) {
          const pivot = world.createBody();
          const drum = world.createBody({ type: 'dynamic', position: center });
          for (const wall of walls) drum.createOffsetBox(wall.hw, wall.hh, wall, 0, { density, friction: FRICTION });
          world.createRevoluteJoint(pivot, drum, {
            localAnchorA: center, enableMotor: true, motorSpeed: speed, maxMotorTorque: maxTorque,
          });
          return { body: drum, drive: drumDrive };
        },
        step() { world.step(1 / 60, 4); },
        position(body) { return body.position; },
        angle(body) { return body.angle; },
        destroy() { world.destroy(); },
      };
    },
  };
}

async function rapierEngine(RAPIER, build) {
  await RAPIER.init();
  const drumDrive = 'revolute motor';
  return {
    name: `Rapier2D ${build}${RAPIER.version()}`,
    drumDrive,
    createWorld({ sleep }) {
      const world = new RAPIER.World({ x: 0, y: -10 });
      world.timestep = 1 / 60;
      const dynamic = (x, y) => world.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(x, y).setCanSleep(sleep));
      return {
        staticBox(x, y, hw, hh) {
          const body = world.createRigidBody(RAPIER.RigidBodyDesc.fixed().setTranslation(x, y));
          world.createCollider(RAPIER.ColliderDesc.cuboid(hw, hh).setFriction(FRICTION), body);
        },
        box(x, y, hw, hh) {
          const body = dynamic(x, y);
          world.createCollider(RAPIER.ColliderDesc.cuboid(hw, hh).setFriction(FRICTION).setDensity(1), body);
          return body;
        },
        circle(x, y, r) {
          const body = dynamic(x, y);
          world.createCollider(RAPIER.ColliderDesc.ball(r).setFriction(FRICTION).setDensity(1), body);
          return body;
        },
        motorDrum({ center, walls, density, speed, maxTorque }) {
          const pivot = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
          const drum = dynamic(center.x, center.y);
          for (const wall of walls) {
            world.createCollider(RAPIER.ColliderDesc.cuboid(wall.hw, wall.hh).setTranslation(wall.x, wall.y)
              .setFriction(FRICTION).setDensity(density), drum);
          }
          const hinge = world.createImpulseJoint(RAPIER.JointData.revolute(center, { x: 0, y: 0 }), pivot, drum, true);
          hinge.configureMotorVelocity(speed, RAPIER_MOTOR_FACTOR);
          // Rapier's SIMD build (0.19) has no motor force limit: its motor is unbounded, as
          // the 1e8 N m limit of the others is in effect.
          if (typeof hinge.setMotorMaxForce === 'function') hinge.setMotorMaxForce(maxTorque);
          return { body: drum, drive: drumDrive };
        },
        step() { world.step(); },
        position(body) { return body.translation(); },
        angle(body) { return body.rotation(); },
        destroy() { world.free(); },
      };
    },
  };
}

async function planckEngine() {
  const drumDrive = 'revolute motor';
  return {
    name: 'planck 1.4',
    drumDrive,
    createWorld({ sleep }) {
      const world = new planck.World({ gravity: planck.Vec2(0, -10), allowSleep: sleep });
      const fixture = { density: 1, friction: FRICTION };
      return {
        staticBox(x, y, hw, hh) { world.createBody({ position: planck.Vec2(x, y) }).createFixture(planck.Box(hw, hh), fixture); },
        box(x, y, hw, hh) {
          const body = world.createDynamicBody({ position: planck.Vec2(x, y) });
          body.createFixture(planck.Box(hw, hh), fixture);
          return body;
        },
        circle(x, y, r) {
          const body = world.createDynamicBody({ position: planck.Vec2(x, y) });
          body.createFixture(planck.Circle(r), fixture);
          return body;
        },
        motorDrum({ center, walls, density, speed, maxTorque }) {
          const pivot = world.createBody();
          const drum = world.createDynamicBody({ position: planck.Vec2(center.x, center.y) });
          for (const wall of walls) {
            drum.createFixture(planck.Box(wall.hw, wall.hh, planck.Vec2(wall.x, wall.y), 0), { density, friction: FRICTION });
          }
          world.createJoint(new planck.RevoluteJoint({ enableMotor: true, motorSpeed: speed, maxMotorTorque: maxTorque },
                                                     pivot, drum, planck.Vec2(center.x, center.y)));
          return { body: drum, drive: drumDrive };
        },
        step() { world.step(1 / 60, 8, 3); },
        position(body) { return body.getPosition(); },
        angle(body) { return body.getAngle(); },
        destroy() {},
      };
    },
  };
}

async function matterEngine() {
  const PX = 20;  // pixels per metre: matter-js is tuned for bodies tens of pixels wide
  const drumDrive = 'kinematic (matter-js has no joint motor)';
  return {
    name: 'matter-js 0.20',
    drumDrive,
    createWorld({ sleep }) {
      // Gravity: gravity.y * gravity.scale px/ms^2 = 10 m/s^2 at 20 px/m.
      const engine = Matter.Engine.create({ enableSleeping: sleep, gravity: { x: 0, y: 0.2, scale: 0.001 } });
      const options = { friction: FRICTION, density: 0.001 };
      const add = (body) => { Matter.Composite.add(engine.world, body); return body; };
      const turning = [];  // static drums and their speeds (rad/s, counter-clockwise)
      return {
        staticBox(x, y, hw, hh) {
          add(Matter.Bodies.rectangle(x * PX, -y * PX, 2 * hw * PX, 2 * hh * PX, { ...options, isStatic: true }));
        },
        box(x, y, hw, hh) { return add(Matter.Bodies.rectangle(x * PX, -y * PX, 2 * hw * PX, 2 * hh * PX, options)); },
        circle(x, y, r) { return add(Matter.Bodies.circle(x * PX, -y * PX, r * PX, options)); },
        motorDrum({ center, walls, speed }) {
          const parts = walls.map((wall) => Matter.Bodies.rectangle((center.x + wall.x) * PX, -(center.y + wall.y) * PX,
                                                                    2 * wall.hw * PX, 2 * wall.hh * PX, options));
          const drum = add(Matter.Body.create({ parts, isStatic: true, friction: FRICTION }));
          turning.push({ drum, speed });
          return { body: drum, drive: drumDrive };
        },
        step() {
          // y points down in matter-js: counter-clockwise on screen is a negative angle.
          // updateVelocity: contacts see the drum's wall moving, as they would a kinematic body's.
          for (const { drum, speed } of turning) Matter.Body.rotate(drum, -speed / 60, undefined, true);
          Matter.Engine.update(engine, 1000 / 60);
        },
        position(body) { return { x: body.position.x / PX, y: -body.position.y / PX }; },
        angle(body) { return -body.angle; },
        destroy() { Matter.Engine.clear(engine); },
      };
    },
  };
}

// Each engine's name and its loader, so that only the engines asked for are loaded.
const ENGINES = [
  ['impulse2d.wasm SIMD', (name) => impulse2dEngine(name)],
  ['impulse2d.wasm scalar', (name) => impulse2dEngine(name, { simd: false })],
  ['impulse2d.wasm threads 1 worker', (name) => impulse2dEngine(name, { threads: true })],
  ['impulse2d.wasm threads 2 workers', (name) => impulse2dEngine(name, { threads: true, workerCount: 2 })],
  ['Rapier2D', () => rapierEngine(RAPIER_PLAIN, '')],
  ['Rapier2D SIMD', () => rapierEngine(RAPIER_SIMD, 'SIMD ')],
  ['planck', planckEngine],
  ['matter-js', matterEngine],
];

/** The engines whose names contain one of `only`'s words (all of them without). */
export async function loadEngines(only = []) {
  const wanted = ENGINES.filter(([name]) => only.length === 0 || only.some((word) => name.includes(word)));
  const engines = [];
  for (const [name, load] of wanted) engines.push(await load(name));
  return engines;
}
