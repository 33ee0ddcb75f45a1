// SPDX-License-Identifier: MIT
// One adapter per engine, so that every scene is built by the same code: static and
// dynamic boxes and circles, a step, and a body's position (metres, y up).
// Each engine runs at its own recommended settings for 60 Hz:
//   impulse2d  1/60 s, 4 substeps (as Box2D v3's benchmark)
//   Rapier2D   1/60 s, its defaults (4 solver iterations, 1 internal PGS iteration)
//   planck     1/60 s, 8 velocity and 3 position iterations (Box2D 2.x's defaults)
//   matter-js  1000/60 ms, its defaults (6 position, 4 velocity iterations); 1 m = 20 px
import { loadImpulse2d } from '../../bindings/js/src/index.js';
import RAPIER from '@dimforge/rapier2d-compat';
import * as planck from 'planck';
import Matter from 'matter-js';

const FRICTION = 0.6;

async function impulse2dEngine() {
  const i2d = await loadImpulse2d();
  return {
    name: 'impulse2d.wasm',
    createWorld({ sleep }) {
      const world = i2d.createWorld({ gravity: [0, -10], enableSleep: sleep });
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
        step() { world.step(1 / 60, 4); },
        position(body) { return body.position; },
        destroy() { world.destroy(); },
      };
    },
  };
}

async function rapierEngine() {
  await RAPIER.init();
  return {
    name: `Rapier2D ${RAPIER.version()}`,
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
        step() { world.step(); },
        position(body) { return body.translation(); },
        destroy() { world.free(); },
      };
    },
  };
}

async function planckEngine() {
  return {
    name: 'planck 1.4',
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
        step() { world.step(1 / 60, 8, 3); },
        position(body) { return body.getPosition(); },
        destroy() {},
      };
    },
  };
}

async function matterEngine() {
  const PX = 20;  // pixels per metre: matter-js is tuned for bodies tens of pixels wide
  return {
    name: 'matter-js 0.20',
    createWorld({ sleep }) {
      // Gravity: gravity.y * gravity.scale px/ms^2 = 10 m/s^2 at 20 px/m.
      const engine = Matter.Engine.create({ enableSleeping: sleep, gravity: { x: 0, y: 0.2, scale: 0.001 } });
      const options = { friction: FRICTION, density: 0.001 };
      const add = (body) => { Matter.Composite.add(engine.world, body); return body; };
      return {
        staticBox(x, y, hw, hh) {
          add(Matter.Bodies.rectangle(x * PX, -y * PX, 2 * hw * PX, 2 * hh * PX, { ...options, isStatic: true }));
        },
        box(x, y, hw, hh) { return add(Matter.Bodies.rectangle(x * PX, -y * PX, 2 * hw * PX, 2 * hh * PX, options)); },
        circle(x, y, r) { return add(Matter.Bodies.circle(x * PX, -y * PX, r * PX, options)); },
        step() { Matter.Engine.update(engine, 1000 / 60); },
        position(body) { return { x: body.position.x / PX, y: -body.position.y / PX }; },
        destroy() { Matter.Engine.clear(engine); },
      };
    },
  };
}

export async function loadEngines() {
  return [await impulse2dEngine(), await rapierEngine(), await planckEngine(), await matterEngine()];
}
