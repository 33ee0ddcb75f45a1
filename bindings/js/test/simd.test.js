// SPDX-License-Identifier: MIT
// The WebAssembly SIMD build (4-lane contact and hinge kernels) gives the scalar build's
// bits: a mixed pile's state hash is compared every 50 steps for 500 steps, between the
// two builds and between the SIMD build's two paths.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadImpulse2d, SIMD_PATH_NAMES, wasmSimdSupported } from '../src/index.js';
import { mixedPileHashes, refused, scalarBuild, simdBuild } from './fixture.js';

/** Touching contacts the settled pile must have for the comparison to mean anything. */
const MIN_CONTACTS = 150;

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
  const scalar = mixedPileHashes(scalarBuild);
  const simd = mixedPileHashes(simdBuild);
  assert.ok(scalar.contactCount > MIN_CONTACTS, `the pile touches (${scalar.contactCount} contacts)`);
  assert.deepEqual(simd.hashes, scalar.hashes);
});

test('in the SIMD build, a world asking for the scalar path gives the same bits', () => {
  const automatic = mixedPileHashes(simdBuild);
  const scalar = mixedPileHashes(simdBuild, { simdPath: 'scalar' });
  assert.deepEqual(scalar.hashes, automatic.hashes);
});

test('a path the build lacks, or a bad simd option, is refused', () => {
  refused(() => simdBuild.createWorld({ simdPath: 'sse2' }), 'I2D_ERR_INVALID_ARGUMENT', 'simd_path');
  refused(() => scalarBuild.createWorld({ simdPath: 'wasm128' }), 'I2D_ERR_INVALID_ARGUMENT', 'simd_path');
  assert.throws(() => simdBuild.createWorld({ simdPath: 'sse3' }), TypeError);
  return assert.rejects(loadImpulse2d({ simd: 'yes' }), TypeError);
});
