// SPDX-License-Identifier: MIT
// The golden snapshot saved by the native x86-64 build (tests/determinism/data, written by
// tests/determinism/make_golden_snapshot.c) goes on in WebAssembly to the state hash
// recorded beside it, in the scalar build and in the SIMD one: the same bits on the scalar
// and the WebAssembly SIMD kernels as on the native SIMD ones. The native suite checks the
// same file on x86-64 and AArch64 (test_golden_snapshot.cpp).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { SIMD_PATH_NAMES, World } from '../src/index.js';
import { groundedWorld, scalarBuild, simdBuild } from './fixture.js';

const DATA = new URL('../../../tests/determinism/data/', import.meta.url);
const bytes = readFileSync(new URL('golden_snapshot.bin', DATA));
// One line: bytes=N hash_at_load=H0 steps=K hash=H (H0, H: 16 hex digits).
const line = readFileSync(new URL('golden_snapshot.txt', DATA), 'utf8').trim();
const fields = Object.fromEntries(line.split(/\s+/).map((pair) => pair.split('=')));
const golden = {
  size: Number(fields.bytes),
  hashAtLoad: BigInt(`0x${fields.hash_at_load}`),
  steps: Number(fields.steps),
  hash: BigInt(`0x${fields.hash}`),
};

function stepOn(world) {
  assert.equal(world.stateHash(), golden.hashAtLoad, 'the hash when loaded');
  for (let s = 0; s < golden.steps; s++) world.step(1 / 60, 4);
  assert.equal(world.stateHash().toString(16).padStart(16, '0'), golden.hash.toString(16).padStart(16, '0'),
               `the hash after ${golden.steps} steps`);
}

test('the golden file is what its record says', () => {
  assert.match(line, /^bytes=\d+ hash_at_load=[0-9a-f]{16} steps=\d+ hash=[0-9a-f]{16}$/);
  assert.equal(bytes.length, golden.size);
  assert.ok(golden.steps > 0);
});

for (const [build, i2d, path] of [['scalar build', scalarBuild, 'scalar'], ['SIMD build', simdBuild, 'wasm128']]) {
  test(`${build}: the natively saved golden snapshot, made a world in wasm, reaches the recorded hash`, () => {
    const world = World.fromSnapshot(i2d, bytes);
    assert.equal(SIMD_PATH_NAMES[world.simdPath()], path);  // whatever path saved it
    stepOn(world);
    world.destroy();
  });

  test(`${build}: restored in place, into a stepped world and an empty one, it reaches the recorded hash`, () => {
    const { world } = groundedWorld(undefined, i2d);
    world.createBody({ type: 'dynamic', position: [0, 3] }).createCircle(0.5);
    for (let s = 0; s < 20; s++) world.step(1 / 60, 4);
    world.restoreSnapshot(bytes);
    stepOn(world);
    world.destroy();
    const empty = i2d.createWorld();
    empty.restoreSnapshot(bytes);
    stepOn(empty);
    empty.destroy();
  });
}
