// SPDX-License-Identifier: MIT
// Recording a world and replaying it: the replay reaches every recorded hash, seeks back
// and forth to them, and refuses a recording changed in one byte; a writer's error comes
// back from stopRecording.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { i2d, groundedWorld, refused } from './fixture.js';

const STEPS = 90;
/** When the recorded program makes and destroys bodies and pushes them. */
const SPAWN_EVERY = 10;

/** Steps a grounded world STEPS times with creations, impulses, setters and a destruction
 *  between steps; returns the world and its hash after each step (index 0: before any). */
function recordedProgram(world) {
  const hashes = [world.stateHash()];
  const bodies = [];
  for (let s = 1; s <= STEPS; s++) {
    if (s % SPAWN_EVERY === 1) {
      const body = world.createBody({ type: 'dynamic', position: [(s % 7) - 3, 4 + (s % 3)], angle: 0.1 * s });
      if (s % 20 === 1) body.createBox(0.4, 0.3);
      else body.createCircle(0.3, { restitution: 0.4 });
      body.applyLinearImpulse([0.5, 0]);
      bodies.push(body);
    }
    if (s === 45) bodies.shift().destroy();
    if (s === 60) bodies[0].linearVelocity = [0, 3];
    world.step(1 / 60, 4);
    hashes.push(world.stateHash());
  }
  return hashes;
}

function recording() {
  const { world } = groundedWorld();
  world.startRecording();
  const hashes = recordedProgram(world);
  const bytes = world.stopRecording();
  world.destroy();
  return { bytes, hashes };
}

test('a replay runs every recorded step to its recorded hash and seeks back and forth', () => {
  const { bytes, hashes } = recording();
  const replay = i2d.openReplay(bytes);
  try {
    assert.equal(replay.stepCount, STEPS);
    assert.equal(replay.currentStep, 0);
    assert.equal(replay.world.stateHash(), hashes[0]);
    assert.equal(replay.step(STEPS + 10), STEPS);
    assert.equal(replay.divergentStep, null);
    assert.equal(replay.world.stateHash(), hashes[STEPS]);
    for (const step of [30, 5, 61, STEPS, 0]) {
      replay.seek(step);
      assert.equal(replay.currentStep, step);
      assert.equal(replay.world.stateHash(), hashes[step], `step ${step}`);
    }
    refused(() => replay.seek(STEPS + 1), 'I2D_ERR_INVALID_ARGUMENT', 'step');
    assert.throws(() => replay.world.destroy(), /belongs to its replay/);
  } finally {
    replay.close();
  }
  replay.close();  // twice is harmless
});

test('a writer gets the recording as it is made, the same bytes stopRecording returns', () => {
  const kept = recording().bytes;
  const { world } = groundedWorld();
  const chunks = [];
  world.startRecording((chunk) => chunks.push(chunk));
  recordedProgram(world);
  assert.equal(world.stopRecording(), undefined);
  world.destroy();
  assert.ok(chunks.length > STEPS, `${chunks.length} records`);
  assert.deepEqual(Buffer.concat(chunks), Buffer.from(kept));
});

test('an error the writer throws is thrown by stopRecording, and the world goes on', () => {
  const { world } = groundedWorld();
  const failure = new Error('disk full');
  world.startRecording(() => { throw failure; });
  world.createBody({ type: 'dynamic', position: [0, 2] }).createCircle(0.5);
  world.step(1 / 60, 4);
  assert.throws(() => world.stopRecording(), (error) => error === failure);
  world.step(1 / 60, 4);
  assert.equal(world.counters().bodyCount, 2);
  world.destroy();
});

test('a recording changed in one byte, or not a recording, is refused', () => {
  const { bytes } = recording();
  const changed = Uint8Array.from(bytes);
  changed[changed.length >> 1] ^= 0x40;
  refused(() => i2d.openReplay(changed), 'I2D_ERR_INVALID_SNAPSHOT', '');
  refused(() => i2d.openReplay(new Uint8Array(64)), 'I2D_ERR_INVALID_SNAPSHOT', '');
  assert.throws(() => i2d.createWorld().startRecording('file.bin'), TypeError);
});
