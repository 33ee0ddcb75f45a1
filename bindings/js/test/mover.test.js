// SPDX-License-Identifier: MIT
// The character mover from JavaScript (World.moveCharacter, castMover, collideMover,
// Impulse2d.solvePlanes, clipVector) against closed forms and answers worked by hand, as
// tests/physics/test_character_mover.cpp checks them in C, and its refusals.
//
// The character is a capsule 1.8 m tall of radius 0.3 m, its origin at its feet, moved
// as a game moves one at 60 Hz: the input sets the level speed, gravity is added while it
// is airborne, the velocity a move returns is fed back.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { i2d, groundedWorld, refused, assertNear } from './fixture.js';

const TIME_STEP = 1 / 60;
const GRAVITY = 10;
const RADIUS = 0.3;
const CAPSULE = { center1: { x: 0, y: RADIUS }, center2: { x: 0, y: 1.8 - RADIUS }, radius: RADIUS };
/** The default def's skin and the default world's contact slop, m. */
const SKIN = 0.01;
const SLOP = 0.005;
/** Where a character rests above what it stands on: the skin and 7/8 of the slop (its
 *  casts stop between a half and three quarters of the slop from a surface). */
const REST_GAP = SKIN + 0.875 * SLOP;

/** A character of the default def, moved frame by frame. */
class Character {
  constructor(world, position, settings = {}) {
    Object.assign(this, { world, position, settings, velocity: { x: 0, y: 0 }, last: { onGround: false } });
  }

  move(velocity) {
    this.last = this.world.moveCharacter({ capsule: CAPSULE, position: this.position, velocity,
                                           timeStep: TIME_STEP, ...this.settings });
    this.position = this.last.position;
    return this.last;
  }

  /** One game frame at the level speed inputX, gravity while airborne. */
  frame(inputX) {
    const vy = this.last.onGround ? this.velocity.y : this.velocity.y - GRAVITY * TIME_STEP;
    this.move({ x: inputX, y: vy });
    this.velocity = this.last.velocity;
    return this.last;
  }
}

function framesFor(seconds) { return Math.round(seconds / TIME_STEP); }

test('the default character def is the library\'s', () => {
  const def = i2d.defaultCharacterDef();
  assertNear(def.maxSlopeAngle, Math.PI / 4, 1e-4, 'max slope');
  assert.equal(Math.fround(def.stepHeight), Math.fround(0.25));
  assert.equal(Math.fround(def.snapDistance), Math.fround(0.2));
  assert.equal(Math.fround(def.skin), Math.fround(SKIN));
  assert.equal(def.maxIterations, 5);
  assert.equal(def.pushMass, 80);
  assert.deepEqual(def.filter, { categoryBits: 2n ** 64n - 1n, maskBits: 2n ** 64n - 1n });
});

test('4 m/s on flat ground covers 8 m in 2 s within 1 %, on the ground every frame', () => {
  const { world, ground } = groundedWorld();
  const c = new Character(world, { x: 0, y: REST_GAP });
  c.move({ x: 0, y: 0 });
  assert.ok(c.last.onGround);
  let grounded = 0;
  for (let i = 0; i < framesFor(2); i++) {
    world.step(TIME_STEP, 4);
    grounded += c.frame(4).onGround ? 1 : 0;
    assertNear(c.position.y, REST_GAP, 0.25 * SLOP, 'feet at the rest gap');
  }
  assert.equal(grounded, framesFor(2));
  assertNear(c.position.x, 8, 0.01 * 8, 'distance walked');
  assertNear(c.velocity.x, 4, 1e-6, 'level speed kept');
  assertNear(c.last.groundNormal.y, 1, 1e-6, 'ground normal');
  assert.equal(c.last.groundShape, ground.shapes[0]);
  assert.deepEqual(c.last.groundVelocity, { x: 0, y: 0 });
  assert.equal(c.last.hitCount, 1);
  world.destroy();
});

test('walked into a wall, the character stops at the skin with no speed into it', () => {
  const { world } = groundedWorld();
  world.createBody({ position: [3.5, 1.5] }).createBox(0.5, 1.5);  // its face at x = 3
  const c = new Character(world, { x: 0, y: REST_GAP });
  for (let i = 0; i < framesFor(2); i++) c.frame(4);
  const gap = 3 - (c.position.x + RADIUS);
  assert.ok(gap >= SKIN - 1e-5 && gap <= SKIN + SLOP, `gap ${gap}`);
  assertNear(c.velocity.x, 0, 1e-6, 'speed into the wall');
  assert.ok(c.last.onGround);
  assert.equal(c.last.hitCount, 2);
  world.destroy();
});

test('a character that adds groundVelocity rides a kinematic platform', () => {
  const world = i2d.createWorld();
  const platform = world.createBody({ type: 'kinematic', position: [0, 1], linearVelocity: [2, 0] });
  const top = platform.createBox(2, 0.25);
  const c = new Character(world, { x: 0, y: 1.25 + REST_GAP });
  c.move({ x: 0, y: 0 });
  assert.equal(c.last.groundShape, top);
  assertNear(c.last.groundVelocity.x, 2, 1e-6, 'the platform\'s velocity at the feet');
  const offset = c.position.x - platform.position.x;
  for (let i = 0; i < framesFor(1); i++) {
    world.step(TIME_STEP, 4);
    assert.ok(c.move(c.last.groundVelocity).onGround);
    assertNear(c.position.x - platform.position.x, offset, 1e-4, 'place on the platform');
  }
  assertNear(platform.position.x, 2, 1e-3, 'the platform moved');
  world.destroy();
});

test('walking into a crate pushes it with pushMass, and pushMass 0 pushes nothing', () => {
  for (const pushMass of [80, 0]) {
    const { world } = groundedWorld({ enableSleep: false });
    const crate = world.createBody({ type: 'dynamic', position: [2, 0.5] });
    crate.createBox(0.5, 0.5, { density: 20 });
    for (let i = 0; i < 30; i++) world.step(TIME_STEP, 4);
    const c = new Character(world, { x: 0, y: REST_GAP }, { pushMass });
    for (let i = 0; i < framesFor(2); i++) {
      c.frame(2);
      world.step(TIME_STEP, 4);
      assert.ok(c.position.x + RADIUS <= crate.position.x - 0.5 + 0.01, 'never inside the crate');
    }
    if (pushMass > 0) assert.ok(crate.position.x - 2 > 1, `pushed to ${crate.position.x}`);
    else assertNear(crate.position.x, 2, 1e-4, 'not pushed');
    world.destroy();
  }
});

test('the filter leaves a category out: the character walks through it', () => {
  const { world } = groundedWorld();
  // A wall in category 2; the character's mask leaves bit 2 out.
  world.createBody({ position: [3.5, 1.5] }).createBox(0.5, 1.5, { filter: { categoryBits: 2 } });
  const c = new Character(world, { x: 0, y: REST_GAP }, { filter: { maskBits: ~2n } });
  for (let i = 0; i < framesFor(2); i++) c.frame(4);
  assertNear(c.position.x, 8, 0.08, 'through the wall');
  world.destroy();
});

// A ground (top at y = 0) and a wall whose face is at x = 1: a capsule standing 2 mm above
// the ground with its side 3 mm from the wall touches both within the slop.
function groundAndWall() {
  const { world, ground } = groundedWorld();
  const wall = world.createBody({ position: [1.5, 2] });
  wall.createBox(0.5, 2, { filter: { categoryBits: 4 } });
  const capsule = { center1: { x: 1 - 0.003 - RADIUS, y: 0.002 + RADIUS },
                    center2: { x: 1 - 0.003 - RADIUS, y: 1.5 }, radius: RADIUS };
  return { world, ground, wall, capsule };
}

test('collideMover gives a plane per shape touched, with its separation', () => {
  const { world, capsule } = groundAndWall();
  const planes = world.collideMover(capsule);
  assert.equal(planes.length, 2);
  const floor = planes.find((p) => p.normal.y > 0.5);
  const wall = planes.find((p) => p.normal.x < -0.5);
  assertNear(floor.normal.x, 0, 1e-5, 'floor normal x');  // closest points round to ~1e-6
  assertNear(floor.offset, 0.002, 1e-5, 'floor separation');
  assertNear(wall.normal.y, 0, 1e-5, 'wall normal y');
  assertNear(wall.offset, 0.003, 1e-5, 'wall separation');
  for (const p of planes) {
    assert.equal(p.pushLimit, 3.4028234663852886e38);  // rigid: FLT_MAX
    assert.equal(p.push, 0);
    assert.equal(p.clipVelocity, true);
  }
  // The filter sees what its mask meets: the wall alone (category 4), then nothing.
  const walls = world.collideMover(capsule, { maskBits: 4 });
  assert.equal(walls.length, 1);
  assertNear(walls[0].normal.x, -1, 1e-6, 'the wall');
  assert.deepEqual(world.collideMover(capsule, { maskBits: 0n }), []);
  // Lifted 10 cm, it touches nothing.
  assert.deepEqual(world.collideMover({ ...capsule, center1: { x: 0, y: 0.4 }, center2: { x: 0, y: 1.5 } }), []);
  world.destroy();
});

test('castMover stops between a half and three quarters of the slop from a surface', () => {
  const { world } = groundedWorld();
  // The capsule's foot 1 m above the ground, moved 2 m down: 1 m less the stopping gap.
  const capsule = { center1: { x: 0, y: 1 + RADIUS }, center2: { x: 0, y: 2 }, radius: RADIUS };
  const fraction = world.castMover(capsule, { x: 0, y: -2 });
  assert.ok(fraction >= (1 - 0.75 * SLOP) / 2 - 1e-6 && fraction <= (1 - 0.5 * SLOP) / 2 + 1e-6, `${fraction}`);
  assert.equal(world.castMover(capsule, { x: 0, y: 2 }), 1);    // away: the whole way
  assert.equal(world.castMover(capsule, { x: 0, y: -0.5 }), 1);  // short of the ground
  assert.equal(world.castMover(capsule, [0, -2], { maskBits: 2 }), 1);  // the ground is category 1
  world.destroy();
});

// Planes worked by hand (as the C tests work them).
const plane = (nx, ny, offset, extra = {}) => ({ normal: { x: nx, y: ny }, offset, ...extra });

test('solvePlanes: a floor, a corner, a valley, a soft plane and none', () => {
  let r = i2d.solvePlanes({ x: 1, y: -0.3 }, [plane(0, 1, 0.1)]);
  assertNear(r.translation.x, 1, 1e-6, 'floor: level part kept');
  assertNear(r.translation.y, -0.1, 1e-6, 'floor: down to it');
  assertNear(r.pushes[0], 0.2, 1e-6, 'floor push');
  assert.equal(r.iterationCount, 2);

  r = i2d.solvePlanes([0.3, -0.2], [plane(0, 1, 0), plane(-1, 0, 0.05)]);
  assertNear(r.translation.x, 0.05, 1e-6, 'corner x');
  assertNear(r.translation.y, 0, 1e-6, 'corner y');
  assertNear(r.pushes[0], 0.2, 1e-6, 'corner floor push');
  assertNear(r.pushes[1], 0.25, 1e-6, 'corner wall push');

  // A V of faces 0.6 / 0.8: straight down stops at its bottom, each pushing 1 / 1.6.
  r = i2d.solvePlanes([0, -1], [plane(-0.6, 0.8, 0), plane(0.6, 0.8, 0)]);
  assertNear(Math.hypot(r.translation.x, r.translation.y), 0, 1e-5, 'valley');
  assertNear(r.pushes[0], 0.625, 1e-5, 'valley push');
  assert.ok(r.iterationCount > 2 && r.iterationCount <= 32);

  r = i2d.solvePlanes([0, 0], [plane(0, 1, -0.5, { pushLimit: 0.2 })]);
  assertNear(r.translation.y, 0.2, 1e-6, 'a soft plane pushes its limit');
  r = i2d.solvePlanes([0, 0], [plane(0, 1, -0.5, { pushLimit: Infinity })]);
  assertNear(r.translation.y, 0.5, 1e-6, 'Infinity is rigid');

  r = i2d.solvePlanes([0.25, -2], []);
  assert.deepEqual(r, { translation: { x: 0.25, y: -2 }, iterationCount: 0, pushes: [] });
});

test('clipVector removes the part running into the planes that clip', () => {
  const floor = [plane(0, 1, 0)];
  assert.deepEqual(i2d.clipVector([3, -4], floor), { x: 3, y: 0 });
  assert.deepEqual(i2d.clipVector([3, 4], floor), { x: 3, y: 4 });  // leaving: unchanged
  assert.deepEqual(i2d.clipVector([3, -4], [plane(0, 1, 0), plane(-1, 0, 0)]), { x: 0, y: 0 });
  assert.deepEqual(i2d.clipVector([3, -4], [plane(0, 1, 0, { clipVelocity: false })]), { x: 3, y: -4 });
  const s = Math.sqrt(0.5);
  const v = i2d.clipVector([4, 0], [plane(-s, s, 0)]);
  assertNear(v.x, 2, 1e-6, '45 degree face x');
  assertNear(v.y, 2, 1e-6, '45 degree face y');
  // A floor and a steep face: the nearest vector that runs into neither is zero.
  assert.deepEqual(i2d.clipVector([1, -1], [plane(0, 1, 0), plane(-0.8, 0.6, 0)]), { x: 0, y: 0 });
});

test('bad moves are refused with the library message and change nothing', () => {
  const { world } = groundedWorld();
  const crate = world.createBody({ type: 'dynamic', position: [1, 0.5] });
  crate.createBox(0.5, 0.5);
  const hash = world.stateHash();
  // Walking into the crate from 1 cm off: accepted, this move would push it.
  const move = { capsule: CAPSULE, position: [0.185, REST_GAP], velocity: [3, 0], timeStep: TIME_STEP };
  const bad = (changes, part) => refused(() => world.moveCharacter({ ...move, ...changes }),
                                         'I2D_ERR_INVALID_ARGUMENT', part);
  bad({ position: [NaN, 0] }, 'position');
  bad({ velocity: [0, Infinity] }, 'velocity');
  bad({ timeStep: -TIME_STEP }, 'time_step');
  bad({ timeStep: undefined }, 'time_step');
  bad({ capsule: { ...CAPSULE, radius: 0 } }, 'radius');
  bad({ capsule: undefined }, 'capsule');
  bad({ maxIterations: 0 }, 'max_iterations');
  bad({ skin: 0 }, 'skin');
  bad({ maxSlopeAngle: 2 }, 'max_slope_angle');
  bad({ pushMass: -1 }, 'push_mass');
  assert.throws(() => world.moveCharacter({ ...move, jumpHeight: 2 }), TypeError);
  assert.throws(() => world.moveCharacter({ ...move, filter: { maskBits: 1.5 } }), TypeError);
  assert.throws(() => world.moveCharacter({ ...move, filter: { layer: 1 } }), TypeError);
  assert.throws(() => world.moveCharacter(null), TypeError);
  refused(() => world.castMover({ ...CAPSULE, radius: -1 }, [1, 0]), 'I2D_ERR_INVALID_ARGUMENT', 'mover is -1');
  refused(() => world.castMover(CAPSULE, [NaN, 0]), 'I2D_ERR_INVALID_ARGUMENT', 'translation');
  refused(() => world.collideMover({ ...CAPSULE, center2: [0, NaN] }), 'I2D_ERR_INVALID_ARGUMENT', 'mover.y');
  assert.equal(world.stateHash(), hash);
  world.moveCharacter(move);
  assert.notEqual(world.stateHash(), hash, 'the same move accepted pushes the crate');
  world.destroy();
  refused(() => world.moveCharacter(move), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.castMover(CAPSULE, [1, 0]), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.collideMover(CAPSULE), 'I2D_ERR_INVALID_HANDLE', 'world');
});

test('bad planes are refused with the library message', () => {
  const floor = plane(0, 1, 0);
  refused(() => i2d.solvePlanes([NaN, 0], [floor]), 'I2D_ERR_INVALID_ARGUMENT', 'target_delta');
  refused(() => i2d.solvePlanes([0, -1], [plane(0, 2, 0)]), 'I2D_ERR_INVALID_ARGUMENT', 'unit');
  refused(() => i2d.solvePlanes([0, -1], [plane(0, 1, NaN)]), 'I2D_ERR_INVALID_ARGUMENT',
          'planes[0].plane.offset is NaN');
  refused(() => i2d.solvePlanes([0, -1], [plane(0, 1, 0, { pushLimit: -1 })]), 'I2D_ERR_INVALID_ARGUMENT',
          'planes[0].push_limit is -1');
  refused(() => i2d.clipVector([1, Infinity], [floor]), 'I2D_ERR_INVALID_ARGUMENT', 'vector');
  refused(() => i2d.clipVector([1, 0], [{ offset: 0 }]), 'I2D_ERR_INVALID_ARGUMENT',
          'planes[0].plane.normal.x is NaN');
  assert.throws(() => i2d.solvePlanes([0, -1], floor), TypeError);
  assert.throws(() => i2d.clipVector([0, -1], null), TypeError);
});
