// SPDX-License-Identifier: MIT
// The WebAssembly SIMD build (4-lane contact and hinge kernels) gives the scalar build's
// bits: a mixed pile's state hash is compared every 50 steps for 500 steps, between the
// two builds and between the SIMD build's two paths.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadImpulse2d, SIMD_PATH_NAMES, wasmSimdSupported } from '../src/index.js';
import { groundedWorld, refused, scalarBuild, simdBuild } from './fixture.js';

const STEPS = 500;
const HASH_EVERY = 50;
/** Touching contacts the settled pile must have for the comparison to mean anything. */
const MIN_CONTACTS = 150;

/**
 * Boxes, circles, capsules and triangles, some spinning, dropped into a bin, and a chain of
 * boxes on revolute joints (the hinge kernels) hung from the ground: enough contacts for
 * every SIMD lane, lanes left over, and static and dynamic partners.
 */
function mixedPile(build, options) {
  const { world, ground } = groundedWorld(options, build);
  ground.createBox(0.5, 6, { center: [-8, 6] });
  ground.createBox(0.5, 6, { center: [8, 6] });
  for (let i = 0; i < 120; i++) {
    const body = world.createBody({
      type: 'dynamic', position: [-6 + (i % 12) * 1.05, 1 + Math.floor(i / 12) * 1.1],
      angle: 0.1 * (i % 7), angularVelocity: (i % 5) - 2,
    });
    switch (i % 4) {
      case 0: body.createBox(0.4, 0.3, { friction: 0.4 + 0.05 * (i % 5) }); break;
      case 1: body.createCircle(0.35, { restitution: 0.2 * (i % 3) }); break;
      case 2: body.createCapsule([-0.3, 0], [0.3, 0], 0.2); break;
      default: body.createPolygon([[-0.4, -0.3], [0.4, -0.3], [0, 0.4]]);
    }
  }
  let previous = ground;
  for (let link = 0; link < 8; link++) {
    const body = world.createBody({ type: 'dynamic', position: [12 + link * 0.6, 10] });
    body.createBox(0.3, 0.1);
    world.createRevoluteJoint(previous, body, {
      localAnchorA: previous === ground ? [11.7, 11] : [0.3, 0], localAnchorB: [-0.3, 0],
    });
    previous = body;
  }
  return world;
}

function hashesOf(build, options) {
  const world = mixedPile(build, options);
  const hashes = [];
  for (let s = 1; s <= STEPS; s++) {
    world.step(1 / 60, 4);
    if (s % HASH_EVERY === 0) hashes.push(world.stateHash().toString(16).padStart(16, '0'));
  }
  const { contactCount } = world.counters();
  world.destroy();
  return { hashes, contactCount };
}

test('this node runs WebAssembly SIMD, and the builds report their paths', () => {
  assert.ok(wasmSimdSupported(), 'node >= 16 validates SIMD modules');
  assert.equal(simdBuild.simd, true);
  assert.equal(scalarBuild.simd, false);
  for (const [build, path] of [[simdBuild, 'wasm128'], [scalarBuild, 'scalar']]) {
    const world = build.createWorld();
    assert.equal(SIMD_PATH_NAMES[world.simdPath()], path);
    world.destroy();
  }
});

test('the SIMD build gives the scalar build\'s state hash every 50 steps of a mixed pile', () => {
  const scalar = hashesOf(scalarBuild);
  const simd = hashesOf(simdBuild);
  assert.ok(scalar.contactCount > MIN_CONTACTS, `the pile touches (${scalar.contactCount} contacts)`);
  assert.deepEqual(simd.hashes, scalar.hashes);
});

test('in the SIMD build, a world asking for the scalar path gives the same bits', () => {
  const automatic = hashesOf(simdBuild);
  const scalar = hashesOf(simdBuild, { simdPath: 'scalar' });
  assert.deepEqual(scalar.hashes, automatic.hashes);
});

test('a path the build lacks, or a bad simd option, is refused', () => {
  refused(() => simdBuild.createWorld({ simdPath: 'sse2' }), 'I2D_ERR_INVALID_ARGUMENT', 'simd_path');
  refused(() => scalarBuild.createWorld({ simdPath: 'wasm128' }), 'I2D_ERR_INVALID_ARGUMENT', 'simd_path');
  assert.throws(() => simdBuild.createWorld({ simdPath: 'sse3' }), TypeError);
  return assert.rejects(loadImpulse2d({ simd: 'yes' }), TypeError);
});
