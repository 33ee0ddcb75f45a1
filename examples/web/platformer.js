// SPDX-License-Identifier: MIT
// The platformer scene: a walled level with a 0.2 m ledge (under the mover's default step
// height of 0.25 m, so it is walked onto), a one-way platform, a kinematic platform going
// back and forth, and crates; and the character of character.js, walked from the keys.
//
//   x:  -10.5 wall | start -9.5 | ledge -6.5..-3.5 | one-way -1..3 | moving 3..8.75 | 10.5 wall
import { Character } from './character.js';

const GROUND_HALF_WIDTH = 10.5;
const WALL_HEIGHT = 8;
const START = { x: -9.5, y: 0.02 };
export const LEDGE = { from: -6.5, to: -3.5, top: 0.2 };
/** The one-way platform: its own category bit, so that a move's filter can leave it out. */
export const ONE_WAY = { from: -1, to: 3, top: 2.5, category: 2n };
const PLATFORM_HALF_THICKNESS = 0.1;
/** The moving platform: half its width, its top, the range of its centre (its left end
 *  meets the one-way platform's right end at the near end), and its speed. */
export const MOVING = { halfWidth: 1.25, top: 2.5, minX: 4.25, maxX: 7.5, speed: 2 };
const CRATE_HALF = 0.4;
const CRATES = [{ x: 6, y: CRATE_HALF }, { x: 7.6, y: CRATE_HALF }];
const PLATFORM_CRATE = { x: -0.4, half: 0.3 };
/** A contact holds on the one-way platform only when its normal is this close to up. */
const ONE_WAY_NORMAL_Y = 0.7;

export function platformer(world) {
  const names = new Map();
  const ground = world.createBody();
  names.set(ground.createOffsetBox(GROUND_HALF_WIDTH, 0.5, [0, -0.5]), 'ground');
  for (const side of [-1, 1]) {
    names.set(ground.createOffsetBox(0.5, WALL_HEIGHT / 2, [side * (GROUND_HALF_WIDTH + 0.5), WALL_HEIGHT / 2]), 'wall');
  }
  const ledgeHalf = (LEDGE.to - LEDGE.from) / 2;
  names.set(ground.createOffsetBox(ledgeHalf, LEDGE.top / 2, [LEDGE.from + ledgeHalf, LEDGE.top / 2]), 'ledge');
  const oneWay = oneWayPlatform(world);
  names.set(oneWay, 'oneWay');
  const platform = world.createBody({ type: 'kinematic', position: [MOVING.minX, MOVING.top - PLATFORM_HALF_THICKNESS],
                                      linearVelocity: [MOVING.speed, 0] });
  names.set(platform.createBox(MOVING.halfWidth, PLATFORM_HALF_THICKNESS), 'moving');
  for (const c of CRATES) crate(world, c.x, c.y, CRATE_HALF, names);
  crate(world, PLATFORM_CRATE.x, ONE_WAY.top + PLATFORM_CRATE.half, PLATFORM_CRATE.half, names);
  const character = new Character(world, START, [{ category: ONE_WAY.category, top: ONE_WAY.top }]);
  return {
    view: { x: 0, y: 4.8, height: 14 },
    character, platform, names,
    /** The game's frame, after the world's step: the platform's turn, the character's move. */
    update(actions, timeStep) {
      drivePlatform(platform);
      character.update(actions, timeStep);
    },
    takesKeys: true,
    drawExtras: (drawer) => character.draw(drawer),
    saveGame: () => character.save(),
    restoreGame: (saved) => character.restore(saved),
  };
}

/**
 * A static platform in its own category whose contacts reach the pre-solve hook, which
 * keeps a contact only when it pushes the other body up: bodies jump up through it and
 * land on it. The hook is the world's (one per world), set here for this platform alone.
 */
function oneWayPlatform(world) {
  const half = (ONE_WAY.to - ONE_WAY.from) / 2;
  const body = world.createBody({ position: [ONE_WAY.from + half, ONE_WAY.top - PLATFORM_HALF_THICKNESS] });
  const shape = body.createBox(half, PLATFORM_HALF_THICKNESS,
                               { enablePreSolveEvents: true, filter: { categoryBits: ONE_WAY.category } });
  // The manifold's normal points from shape A to shape B.
  world.setPreSolve((a, b, manifold) => {
    const sign = a === shape ? 1 : b === shape ? -1 : 0;
    return sign === 0 || sign * manifold.normal.y > ONE_WAY_NORMAL_Y;
  });
  return shape;
}

function crate(world, x, y, half, names) {
  const body = world.createBody({ type: 'dynamic', position: [x, y] });
  names.set(body.createBox(half, half, { friction: 0.6 }), 'crate');
}

/** Back and forth between its ends: turned around once past one. Its velocity is part of
 *  the world's state, so a rewind takes the turn back with it. */
function drivePlatform(platform) {
  const { x } = platform.position;
  const vx = platform.linearVelocity.x;
  if (x >= MOVING.maxX && vx > 0) platform.linearVelocity = [-MOVING.speed, 0];
  else if (x <= MOVING.minX && vx < 0) platform.linearVelocity = [MOVING.speed, 0];
}

/** What the browser test reads back. */
export function platformerState(scene) {
  const c = scene.character;
  return {
    character: { x: c.position.x, y: c.position.y, vy: c.velocity.y, onGround: c.onGround,
                 ground: c.groundShape === null ? null : scene.names.get(c.groundShape) ?? 'other' },
    platform: { x: scene.platform.position.x, vx: scene.platform.linearVelocity.x, halfWidth: MOVING.halfWidth },
    oneWay: ONE_WAY.top, ledge: LEDGE.top, movingMinX: MOVING.minX,
  };
}
