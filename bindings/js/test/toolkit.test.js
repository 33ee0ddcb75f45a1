// SPDX-License-Identifier: MIT
// The game toolkit from JavaScript: contact hooks (a one-way platform, ghosts) and
// explosions, as tests/physics/test_contact_hooks.cpp and test_explosion.cpp check them in
// C. Each hook scene also runs without its hook, as the control that must fail the same
// check.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { i2d, groundedWorld, refused, assertNear, stepSeconds } from './fixture.js';

// The one-way platform: a thin static box whose top is at 3 m; a crate of half size 0.25.
const PLATFORM_TOP = 3;
const PLATFORM_HALF_HEIGHT = 0.1;
const CRATE_HALF = 0.25;
const REST_HEIGHT = PLATFORM_TOP + CRATE_HALF;
const REST_TOLERANCE = 0.01;  // m, the contact slop's order

const speedOf = (v) => Math.hypot(v.x, v.y);

/** A grounded world with the platform; options are its shape's (the hook's opt-in). */
function oneWayPlatform(options) {
  const { world } = groundedWorld();
  const body = world.createBody({ position: [0, PLATFORM_TOP - PLATFORM_HALF_HEIGHT] });
  return { world, platform: body.createBox(2, PLATFORM_HALF_HEIGHT, options) };
}

/** The one-way platform's pre-solve hook: the contact acts only when it pushes the other
 *  shape up (the normal points from shape A to shape B). */
function landsFromAbove(platform) {
  return (shapeA, shapeB, manifold) => {
    const sign = shapeA === platform ? 1 : shapeB === platform ? -1 : 0;
    return sign * manifold.normal.y > 0.95;
  };
}

/** A crate launched up from the ground at 9 m/s (it would rise 4.05 m: past the
 *  platform), watched for `seconds`: the crate and the highest its centre rose. */
function jump(world, seconds = 3) {
  const crate = world.createBody({ type: 'dynamic', position: [0, CRATE_HALF], linearVelocity: [0, 9] });
  crate.createBox(CRATE_HALF, CRATE_HALF);
  let highest = -Infinity;
  for (let i = 0; i < Math.round(seconds * 60); i++) {
    world.step(1 / 60, 4);
    highest = Math.max(highest, crate.position.y);
  }
  return { crate, highest };
}

test('a one-way platform lets a crate up through it and holds it on top', () => {
  const { world, platform } = oneWayPlatform({ enablePreSolveEvents: true });
  assert.equal(platform.preSolveEventsEnabled, true);
  const asked = [];
  const landing = landsFromAbove(platform);
  world.setPreSolve((a, b, manifold) => {
    asked.push([a, b, manifold]);
    return landing(a, b, manifold);
  });
  const { crate, highest } = jump(world);
  assert.ok(highest > REST_HEIGHT + 0.5, `rose to ${highest}`);
  assertNear(crate.position.y, REST_HEIGHT, REST_TOLERANCE, 'resting height');
  assert.ok(speedOf(crate.linearVelocity) < 0.01);
  // The hook saw the package's objects: this world's Shapes and a manifold.
  const [a, b, manifold] = asked.at(-1);
  assert.deepEqual(new Set([a, b]), new Set([platform, crate.shapes[0]]));
  assert.ok(manifold.points.length >= 1 && manifold.points.length <= 2);
  assert.deepEqual(Object.keys(manifold.points[0]).sort(), ['id', 'penetration', 'point']);
  assertNear(speedOf(manifold.normal), 1, 1e-5, 'unit normal');
  world.destroy();
});

test('without the hook the crate is stopped beneath the platform', () => {
  const { world } = oneWayPlatform({ enablePreSolveEvents: true });
  const { highest } = jump(world);
  assert.ok(highest < PLATFORM_TOP - 2 * PLATFORM_HALF_HEIGHT, `rose to ${highest}`);
  world.destroy();
});

test('the pre-solve opt-in changes after creation, and a cleared hook is no longer asked', () => {
  const { world, platform } = oneWayPlatform();  // not opted in: the hook is never asked
  assert.equal(platform.preSolveEventsEnabled, false);
  let asked = 0;
  const landing = landsFromAbove(platform);
  world.setPreSolve((a, b, m) => { asked++; return landing(a, b, m); });
  const before = jump(world, 1.5);
  assert.equal(asked, 0);
  assert.ok(before.highest < PLATFORM_TOP);
  platform.preSolveEventsEnabled = true;
  assert.equal(platform.preSolveEventsEnabled, true);
  const after = jump(world);
  assert.ok(asked > 0);
  assertNear(after.crate.position.y, REST_HEIGHT, REST_TOLERANCE, 'opted in: on top');
  world.setPreSolve(null);
  asked = 0;
  const cleared = jump(world, 1.5);
  assert.equal(asked, 0);
  assert.ok(cleared.highest < PLATFORM_TOP);
  world.destroy();
});

// Ghosts: shapes in groups; two different groups pass through each other, a group meets
// itself and everything in no group (the ground).
function dropGhosts(withFilter) {
  const { world } = groundedWorld();
  const groupOf = new Map();
  const tagged = (x, y, group) => {
    const body = world.createBody({ type: 'dynamic', position: [x, y] });
    groupOf.set(body.createBox(0.5, 0.5, { enableCustomFiltering: true }), group);
    return body;
  };
  if (withFilter) {
    world.setCustomFilter((a, b) => {
      const ga = groupOf.get(a) ?? 0, gb = groupOf.get(b) ?? 0;
      return ga === 0 || gb === 0 || ga === gb;
    });
  }
  tagged(-3, 0.5, 2);
  const fallen = tagged(-3, 3, 1);
  tagged(3, 0.5, 1);
  const stacked = tagged(3, 3, 1);
  stepSeconds(world, 3);
  const heights = { fallen: fallen.position.y, stacked: stacked.position.y };
  world.destroy();
  return heights;
}

test('the custom filter lets two groups pass through each other', () => {
  const { fallen, stacked } = dropGhosts(true);
  assertNear(fallen, 0.5, REST_TOLERANCE, 'through the other group, on the ground');
  assertNear(stacked, 1.5, REST_TOLERANCE, "on its own group's crate");
});

test('without the custom filter the ghosts stack', () => {
  const { fallen, stacked } = dropGhosts(false);
  assertNear(fallen, 1.5, REST_TOLERANCE, 'fallen');
  assertNear(stacked, 1.5, REST_TOLERANCE, 'stacked');
});

/** A crate touching the ground (never asleep: asked every step) with the pre-solve opt-in,
 *  and a ball falling far away that shows each step was done. */
function crateOnGround() {
  const { world } = groundedWorld();
  const crate = world.createBody({ type: 'dynamic', position: [0, 0.5], enableSleep: false });
  crate.createBox(0.5, 0.5, { enablePreSolveEvents: true });
  const ball = world.createBody({ type: 'dynamic', position: [10, 20] });
  ball.createCircle(0.5);
  return { world, crate, ball };
}

test('an error thrown in a hook is thrown by step() after the step, and the pair gets true', () => {
  const { world, crate, ball } = crateOnGround();
  const boom = new Error('from the hook');
  world.setPreSolve(() => { throw boom; });
  for (let i = 0; i < 60; i++) {
    const height = ball.position.y;
    assert.throws(() => world.step(1 / 60, 4), (error) => error === boom);
    assert.ok(ball.position.y < height, 'the step was done');
  }
  assertNear(crate.position.y, 0.5, REST_TOLERANCE, 'held by the ground meanwhile');
  world.setPreSolve(null);
  world.step();  // nothing left over to throw
  world.destroy();
});

test('a hook answering false drops the crate through the ground', () => {
  // The control of the test above: what the crate does had the error turned the pair off.
  const { world, crate } = crateOnGround();
  world.setPreSolve(() => false);
  stepSeconds(world, 1);
  assert.ok(crate.position.y < -1, `at ${crate.position.y}`);
  world.destroy();
});

test('a hook calling its world is refused with I2D_ERR_WORLD_LOCKED and stays set', () => {
  const { world, platform } = oneWayPlatform({ enablePreSolveEvents: true });
  const landing = landsFromAbove(platform);
  let tried = false;
  world.setPreSolve((a, b, manifold) => {
    if (!tried) {
      tried = true;
      refused(() => world.step(), 'I2D_ERR_WORLD_LOCKED', 'i2d_world_step');
      refused(() => b.aabb(), 'I2D_ERR_WORLD_LOCKED', 'i2d_shape_get_aabb');
      refused(() => world.explode({ position: [0, 0] }), 'I2D_ERR_WORLD_LOCKED', 'i2d_world_explode');
      refused(() => world.setPreSolve(null), 'I2D_ERR_WORLD_LOCKED', 'i2d_world_set_pre_solve_callback');
    }
    return landing(a, b, manifold);
  });
  const { crate } = jump(world);
  assert.ok(tried);
  assertNear(crate.position.y, REST_HEIGHT, REST_TOLERANCE, 'the hook still held it on top');
  world.destroy();
});

test('a refusal a hook does not catch comes out of step()', () => {
  // What a refused call inside a hook becomes when the hook does not catch it.
  const { world } = crateOnGround();
  world.setPreSolve(() => world.step());
  refused(() => world.step(), 'I2D_ERR_WORLD_LOCKED', 'i2d_world_step');
  world.destroy();
});

test('hooks hold one function table slot each, freed when cleared, replaced, refused or destroyed', () => {
  // addFunction grows the module's table when no freed slot is left: a slot not given back
  // shows as growth.
  const table = Object.values(i2d.rt.m.asm).find((e) => e instanceof WebAssembly.Table);
  const { world } = crateOnGround();
  world.setPreSolve(() => true);
  world.setCustomFilter(() => true);
  world.setCustomFilter(() => true);  // a replacement holds both for a moment: one slot more
  const size = table.length;
  for (let i = 0; i < 100; i++) {
    world.setPreSolve(() => true);  // replaced: the new one takes a slot, the old one is freed
    world.setPreSolve(null);
    world.setCustomFilter(() => true);
  }
  // A refused set (inside a hook: the world is locked) gives back the slot it took.
  let refusals = 0;
  world.setPreSolve(() => {
    assert.throws(() => world.setCustomFilter(() => false), /called from inside the world's step/);
    refusals++;
    return true;
  });
  stepSeconds(world, 1);
  assert.equal(refusals, 60);
  assert.equal(table.length, size);
  world.destroy();
  assert.deepEqual(world.hooks.pointers, { customFilter: 0, preSolve: 0 });
  // Destroying the world gave both back: a new world's hooks take them.
  const other = i2d.createWorld();
  other.setPreSolve(() => true);
  other.setCustomFilter(() => true);
  assert.equal(table.length, size);
  other.destroy();
});

test('hook setters refuse what is not a function, and a destroyed world', () => {
  const { world } = groundedWorld();
  const shape = world.createBody({ type: 'dynamic' }).createCircle(1);
  assert.throws(() => world.setPreSolve(42), TypeError);
  assert.throws(() => world.setCustomFilter('yes'), TypeError);
  world.destroy();
  refused(() => world.setPreSolve(() => true), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.setCustomFilter(null), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => { shape.preSolveEventsEnabled = true; }, 'I2D_ERR_INVALID_HANDLE', 'destroyed');
  refused(() => shape.preSolveEventsEnabled, 'I2D_ERR_INVALID_HANDLE', 'destroyed');
});

// ---- Explosions: a disc of radius r and mass m whose closest point is within the radius
// leaves at impulsePerLength * 2r / m, straight away from the blast; the speed falls
// linearly to 0 over the falloff.

const DISC_RADIUS = 0.25;

function discAt(world, gap, angle) {
  const d = gap + DISC_RADIUS;
  const body = world.createBody({ type: 'dynamic', position: [d * Math.cos(angle), d * Math.sin(angle)] });
  body.createCircle(DISC_RADIUS);
  return body;
}

const fullSpeed = (impulsePerLength, body) => impulsePerLength * 2 * DISC_RADIUS / body.mass;

test('an explosion gives discs the closed-form speed, away from the blast', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const discs = Array.from({ length: 8 }, (_, k) => discAt(world, 1.5, (2 * Math.PI * k) / 8));
  world.explode({ position: [0, 0], radius: 2, impulsePerLength: 3 });
  for (const disc of discs) {
    const v = disc.linearVelocity, p = disc.position;
    const expected = fullSpeed(3, disc);
    assertNear(speedOf(v), expected, 1e-5 * expected, 'speed');
    assert.ok(v.x * p.x + v.y * p.y > 0, 'away from the blast');
    assert.ok(Math.abs(v.x * p.y - v.y * p.x) < 1e-5 * speedOf(v) * speedOf(p), 'along the line from it');
  }
  world.destroy();
});

test('an explosion fades over its falloff and stops beyond it', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const inside = discAt(world, 0.5, 0);
  const halfway = discAt(world, 2, Math.PI / 2);  // radius + falloff / 2
  const beyond = discAt(world, 3.2, Math.PI);     // past radius + falloff
  world.explode({ position: [0, 0], radius: 1, falloff: 2 });
  assertNear(speedOf(inside.linearVelocity), fullSpeed(1, inside), 1e-5 * fullSpeed(1, inside), 'inside');
  assertNear(speedOf(halfway.linearVelocity), 0.5 * fullSpeed(1, halfway), 1e-5 * fullSpeed(1, halfway), 'halfway');
  assert.deepEqual(beyond.linearVelocity, { x: 0, y: 0 });
  world.destroy();
});

test('an explosion keeps to its mask, and a negative impulse pulls', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const disc = discAt(world, 0.5, 0);
  // The package creates shapes in the default category, 1.
  world.explode({ position: [0, 0], maskBits: 2 });
  assert.deepEqual(disc.linearVelocity, { x: 0, y: 0 });
  world.explode({ position: [0, 0], maskBits: 1n });  // radius 1, impulse 1 per length
  assertNear(speedOf(disc.linearVelocity), fullSpeed(1, disc), 1e-5 * fullSpeed(1, disc), 'pushed');
  assert.ok(disc.linearVelocity.x > 0, 'away from the blast at x = 0');
  world.explode({ position: [0, 0], impulsePerLength: -2 });  // every bit by default
  assertNear(disc.linearVelocity.x, -fullSpeed(1, disc), 1e-5 * fullSpeed(1, disc), 'pulled back past rest');
  world.destroy();
});

test('an explosion refuses bad values with the library message and changes nothing', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const disc = discAt(world, 0.5, 0);
  refused(() => world.explode({ position: [NaN, 0] }), 'I2D_ERR_INVALID_ARGUMENT', 'i2d_world_explode: position.x is NaN');
  refused(() => world.explode({}), 'I2D_ERR_INVALID_ARGUMENT', 'position.x is NaN');
  refused(() => world.explode({ position: [0, 0], radius: -1 }), 'I2D_ERR_INVALID_ARGUMENT', 'radius');
  refused(() => world.explode({ position: [0, 0], falloff: NaN }), 'I2D_ERR_INVALID_ARGUMENT', 'falloff');
  refused(() => world.explode({ position: [0, 0], impulsePerLength: Infinity }), 'I2D_ERR_INVALID_ARGUMENT',
          'impulse_per_length');
  assert.throws(() => world.explode({ position: [0, 0], impulse: 5 }), TypeError);
  assert.deepEqual(disc.linearVelocity, { x: 0, y: 0 });
  world.destroy();
  refused(() => world.explode({ position: [0, 0] }), 'I2D_ERR_INVALID_HANDLE', 'world');
});
