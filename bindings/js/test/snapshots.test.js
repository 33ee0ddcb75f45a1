// SPDX-License-Identifier: MIT
// Snapshots and rollback states through the package: a world restored in place or made
// anew goes on bit for bit as the world that was never saved; eight frames rolled back
// and played again give the same hashes; refused bytes throw and change nothing; the
// binding's Body, Shape and Joint objects follow the world back; no memory is kept.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Impulse2dError, World } from '../src/index.js';
import { i2d, groundedWorld, refused } from './fixture.js';

const BEFORE = 60;  // steps before the save: contacts with impulses, a pile settling
const AFTER = 60;   // steps after it, each hash compared

/** Ground, a pile of mixed shapes, a pendulum on a revolute joint with a motor, a bouncing ball. */
function scene() {
  const { world, ground } = groundedWorld();
  const bodies = [];
  for (let i = 0; i < 12; i++) {
    const body = world.createBody({ type: 'dynamic', position: [-2 + 0.45 * (i % 4), 0.5 + 0.9 * Math.floor(i / 4)],
                                    angle: 0.1 * i });
    if (i % 3 === 0) body.createCircle(0.3, { restitution: 0.4 });
    else if (i % 3 === 1) body.createBox(0.3, 0.2);
    else body.createCapsule([-0.2, 0], [0.2, 0], 0.15);
    bodies.push(body);
  }
  const pivot = world.createBody({ position: [4, 4] });
  const bob = world.createBody({ type: 'dynamic', position: [5.5, 4] });
  bob.createBox(0.3, 0.3, { density: 3 });
  world.createRevoluteJoint(pivot, bob, { localAnchorB: [-1.5, 0], enableMotor: true, motorSpeed: 1, maxMotorTorque: 5 });
  return { world, ground, bodies, bob };
}

function stepHashes(world, steps, beforeEach = () => {}) {
  const hashes = [];
  for (let s = 0; s < steps; s++) {
    beforeEach(s);
    world.step(1 / 60, 4);
    hashes.push(world.stateHash());
  }
  return hashes;
}

/** The scene at the save, its snapshot, and how it goes on never restored. */
function reference() {
  const { world } = scene();
  stepHashes(world, BEFORE);
  const hashAtSave = world.stateHash();
  const bytes = world.takeSnapshot();
  const hashes = stepHashes(world, AFTER);
  const after = world.takeSnapshot();
  world.destroy();
  return { bytes, hashAtSave, hashes, after };
}

test('a snapshot restored in place goes on bit for bit as the world that was never saved', () => {
  const ref = reference();
  const { world } = scene();
  stepHashes(world, BEFORE + 25);  // somewhere else entirely
  assert.notEqual(world.stateHash(), ref.hashAtSave);
  world.restoreSnapshot(ref.bytes);
  assert.equal(world.stateHash(), ref.hashAtSave);
  assert.deepEqual(world.takeSnapshot(), ref.bytes);
  assert.deepEqual(stepHashes(world, AFTER), ref.hashes);
  assert.deepEqual(world.takeSnapshot(), ref.after);
  world.destroy();
});

test('a world made from a snapshot goes on bit for bit, from the bytes or a copy of them', () => {
  const ref = reference();
  for (const [how, make] of [['World.fromSnapshot', () => World.fromSnapshot(i2d, ref.bytes)],
                             ['worldFromSnapshot of a copy', () => i2d.worldFromSnapshot(ref.bytes.slice())],
                             ['an ArrayBuffer', () => i2d.worldFromSnapshot(ref.bytes.slice().buffer)]]) {
    const world = make();
    assert.equal(world.stateHash(), ref.hashAtSave, how);
    assert.deepEqual(stepHashes(world, AFTER), ref.hashes, how);
    assert.deepEqual(world.takeSnapshot(), ref.after, how);
    world.destroy();
  }
});

test('a new world from bytes takeSnapshot returned has its own objects for the saved ones', () => {
  const { world, bodies, bob } = scene();
  bob.userData = 'bob';
  stepHashes(world, 30);
  const bytes = world.takeSnapshot();
  const copy = World.fromSnapshot(i2d, bytes);
  assert.equal(copy.bodies.length, world.bodies.length);
  assert.equal(copy.joints.length, 1);
  const bobThere = copy.bodyByIndex[bob.index];
  assert.notEqual(bobThere, bob);
  assert.equal(bobThere.world, copy);
  assert.equal(bobThere.userData, 'bob');
  assert.deepEqual(bobThere.position, bob.position);
  assert.equal(copy.joints[0].bodyB, bobThere);
  assert.deepEqual(bobThere.joints, copy.joints);
  assert.equal(bobThere.shapes[0].body, bobThere);
  assert.equal(copy.bodyByIndex[bodies[5].index].shapes[0].type, bodies[5].shapes[0].type);
  // Move events of the new world name its own bodies.
  copy.step();
  const moves = copy.bodyMoves();
  assert.ok(moves.count > 0);
  for (let i = 0; i < moves.count; i++) assert.equal(moves.body(i).world, copy);
  // Overlaps find the new world's shapes.
  const p = bobThere.position;
  assert.ok(copy.overlapAABB(p.x - 0.01, p.y - 0.01, p.x + 0.01, p.y + 0.01).includes(bobThere.shapes[0]));
  // The two worlds are independent.
  bobThere.destroy();
  assert.equal(bob.isValid(), true);
  copy.destroy();
  world.destroy();
});

test('an in-place restore brings back the objects of the save and drops those made since', () => {
  const { world, bodies, bob } = scene();
  stepHashes(world, 20);
  const bytes = world.takeSnapshot();
  const hash = world.stateHash();
  const gone = bodies[3];
  const goneShape = gone.shapes[0];
  gone.destroy();
  bodies[4].shapes[0].destroy();
  world.joints[0].destroy();
  const late = world.createBody({ type: 'dynamic', position: [8, 2] });
  late.createCircle(0.5);
  assert.equal(late.index, gone.index);  // the freed index was taken
  stepHashes(world, 10);

  world.restoreSnapshot(bytes);
  assert.equal(world.stateHash(), hash);
  assert.equal(late.isValid(), false);
  assert.ok(!world.bodies.includes(late));
  assert.equal(world.bodyByIndex[gone.index], gone);
  assert.equal(gone.isValid(), true);
  assert.deepEqual(gone.shapes, [goneShape]);
  assert.equal(bodies[4].shapes.length, 1);
  assert.equal(world.joints.length, 1);
  assert.equal(world.joints[0].bodyB, bob);
  assert.deepEqual(bob.joints, world.joints);
  assert.equal(world.counters().bodyCount, world.bodies.length);
  // The next body takes an index no live body has.
  const next = world.createBody();
  assert.equal(world.bodies.filter((b) => b.index === next.index).length, 1);
  world.destroy();
});

test('bytes the binding did not return restore too; objects made since are dropped', () => {
  const { world } = scene();
  stepHashes(world, 20);
  const copy = world.takeSnapshot().slice();
  const count = world.bodies.length;
  const late = world.createBody({ type: 'dynamic' });
  late.createCircle(0.2);
  world.restoreSnapshot(copy);
  assert.equal(late.isValid(), false);
  assert.equal(world.bodies.length, count);
  assert.equal(world.counters().bodyCount, count);
  world.destroy();

  const fresh = i2d.worldFromSnapshot(copy);
  assert.equal(fresh.bodies.length, 0);  // the C API cannot list them
  assert.ok(fresh.counters().bodyCount > 0);
  fresh.destroy();
});

test('rollback: eight frames restored and played again give the hashes of the run that never went back', () => {
  const FRAMES = 130, ROLLBACK_AT = 100, DEPTH = 8;
  // A frame's input, the same whenever the frame is played: a push on one of the bodies.
  const play = (world, bodies, frame) => {
    const body = bodies[(frame * 7) % bodies.length];
    body.applyLinearImpulse([0.2 * (frame % 5) - 0.4, 0.5]);
    world.step(1 / 60, 4);
    return world.stateHash();
  };
  let straight;
  let straightEnd;
  for (const rollBack of [false, true]) {
    const { world, bodies } = scene();
    stepHashes(world, BEFORE);
    const saved = [];
    const hashes = [];
    for (let frame = 0; frame < FRAMES; frame++) {
      saved.push(world.saveState());
      if (rollBack && frame === ROLLBACK_AT) {
        world.restoreState(saved[frame - DEPTH]);
        assert.equal(world.stateHash(), straight[frame - DEPTH - 1]);  // the hash after the frame before
        for (let again = frame - DEPTH; again < frame; again++) {
          assert.equal(play(world, bodies, again), straight[again], `frame ${again} played again`);
        }
      }
      hashes.push(play(world, bodies, frame));
    }
    if (!rollBack) {
      straight = hashes;
      straightEnd = world.takeSnapshot();
    } else {
      assert.deepEqual(hashes, straight);
      assert.deepEqual(world.takeSnapshot(), straightEnd);
    }
    world.destroy();
  }
});

test('truncated, corrupted and foreign bytes throw I2D_ERR_INVALID_SNAPSHOT and change nothing', () => {
  const { world, ground } = groundedWorld();
  const ball = world.createBody({ type: 'dynamic', position: [0, 1] });
  ball.createCircle(0.3);
  stepHashes(world, 30);
  const good = world.takeSnapshot();
  const goodState = world.saveState();
  stepHashes(world, 5);
  const hash = world.stateHash();
  const snapshotSize = world.takeSnapshot().length;
  const unchanged = (what) => {
    assert.equal(world.stateHash(), hash, what);
    assert.equal(world.takeSnapshot().length, snapshotSize, what);
    assert.deepEqual(world.bodies, [ground, ball], what);
    assert.equal(ball.isValid(), true, what);
  };
  const refusedBytes = (restore, bytes, what) => {
    refused(() => restore(bytes), 'I2D_ERR_INVALID_SNAPSHOT', 'refused');
    unchanged(what);
  };
  for (const [name, restore, bytes] of [['snapshot', (b) => world.restoreSnapshot(b), good],
                                        ['state', (b) => world.restoreState(b), goodState]]) {
    for (let length = 0; length < bytes.length; length += Math.max(1, bytes.length >> 6)) {
      refusedBytes(restore, bytes.subarray(0, length), `${name} truncated to ${length}`);
    }
    for (let at = 0; at < bytes.length; at += 7) {
      const changed = bytes.slice();
      changed[at] ^= 0x10;
      refusedBytes(restore, changed, `${name} byte ${at} changed`);
    }
    refusedBytes(restore, new Uint8Array(bytes.length), `${name} zeros`);
    const longer = new Uint8Array(bytes.length + 1);
    longer.set(bytes);
    refusedBytes(restore, longer, `${name} a byte too many`);
  }
  refusedBytes((b) => world.restoreSnapshot(b), goodState, 'a state as a snapshot');
  refusedBytes((b) => world.restoreState(b), good, 'a snapshot as a state');
  refused(() => i2d.worldFromSnapshot(good.subarray(0, good.length - 1)), 'I2D_ERR_INVALID_SNAPSHOT', 'truncated');
  assert.throws(() => world.restoreSnapshot([1, 2, 3]), TypeError);
  assert.throws(() => World.fromSnapshot(i2d, 'bytes'), TypeError);
  unchanged('after the TypeErrors');
  // The good ones are still good.
  world.restoreState(goodState);
  world.restoreSnapshot(good);
  world.destroy();
});

test('a state restores only into its world as its structure stood', () => {
  const { world } = scene();
  stepHashes(world, 10);
  const state = world.saveState();
  const twin = scene().world;
  stepHashes(twin, 10);
  refused(() => twin.restoreState(state), 'I2D_ERR_INVALID_SNAPSHOT', 'another world');
  world.gravity = [0, -9];
  refused(() => world.restoreState(state), 'I2D_ERR_INVALID_SNAPSHOT', 'structure changed');
  const fresh = world.saveState();
  world.createBody({ type: 'dynamic' }).createCircle(0.2);
  refused(() => world.restoreState(fresh), 'I2D_ERR_INVALID_SNAPSHOT', 'structure changed');
  twin.destroy();
  world.destroy();
  refused(() => world.saveState(), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.takeSnapshot(), 'I2D_ERR_INVALID_HANDLE', 'world');
  refused(() => world.restoreState(state), 'I2D_ERR_INVALID_HANDLE', 'world');
});

test('the binding names every status as the library does', () => {
  for (let code = 0; code <= 7; code++) {
    const name = i2d.rt.m.UTF8ToString(i2d.rt.m._i2d_status_string(code));
    if (code > 0) assert.equal(new Impulse2dError(code, '').status, name);
  }
});

test('saving and restoring keep no module memory: thousands of rounds do not grow the heap', () => {
  const world = i2d.createWorld();
  for (let i = 0; i < 150; i++) world.createBody({ type: 'dynamic', position: [i % 15, Math.floor(i / 15)] }).createBox(0.4, 0.4);
  world.step();
  const state = world.saveState();
  const bytes = world.takeSnapshot();
  const heap = i2d.rt.m.HEAPU8.length;
  for (let round = 0; round < 1500; round++) {
    world.restoreState(world.saveState());
    if (round % 10 === 0) world.restoreSnapshot(world.takeSnapshot());
    if (round % 10 === 5) assert.throws(() => world.restoreState(bytes), Impulse2dError);
  }
  // Without the frees: 1500 states of this size would be about 1500 * state.length bytes.
  assert.ok(1500 * state.length > 2 * heap, `the test can see a leak (state ${state.length} bytes)`);
  assert.equal(i2d.rt.m.HEAPU8.length, heap);
  world.destroy();
});
