// SPDX-License-Identifier: MIT
// The threads build: worlds step on Web Workers over shared memory and give the same bits
// at every worker count; the build's workers are lent to worlds and given back; a world
// that would wait for workers that are not there, or run JavaScript hooks on them, is refused.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadImpulse2d, SIMD_PATH_NAMES, wasmThreadsSupported } from '../src/index.js';
import { mixedPile, mixedPileHashes, scalarBuild, simdBuild } from './fixture.js';

const threadsBuild = await loadImpulse2d({ threads: true });

test('node runs the threads build: SIMD kernels and 3 workers to lend', () => {
  assert.ok(wasmThreadsSupported());
  assert.equal(threadsBuild.simd, true);
  assert.equal(threadsBuild.threads, 3);
  assert.equal(simdBuild.threads, 0);
  const world = threadsBuild.createWorld({ workerCount: 2 });
  assert.equal(world.workerCount, 2);
  assert.equal(SIMD_PATH_NAMES[world.simdPath()], 'wasm128');
  world.destroy();
});

/** Web Workers of the build running a thread of the library now. */
const runningThreads = () => threadsBuild.rt.m.PThread.runningWorkers.length;

/** Enough bodies that the world's steps are shared among its workers (256 and more awake). */
const SHARED_PILE = 400;

test('a world of n workers runs n - 1 threads on the build\'s Web Workers while it lives', () => {
  const world = mixedPile(threadsBuild, { workerCount: 3 }, SHARED_PILE);
  try {
    world.step(1 / 60, 4);
    assert.equal(runningThreads(), 2);
  } finally {
    world.destroy();
  }
  assert.equal(runningThreads(), 0);
});

test('1, 2 and 4 workers give the single-threaded builds\' state hash every 50 steps of a 400-body pile', () => {
  const single = mixedPileHashes(simdBuild, {}, SHARED_PILE);
  for (const workerCount of [1, 2, 4]) {
    const threaded = mixedPileHashes(threadsBuild, { workerCount }, SHARED_PILE);
    assert.deepEqual(threaded.hashes, single.hashes, `${workerCount} workers`);
  }
  assert.deepEqual(mixedPileHashes(scalarBuild, {}, SHARED_PILE).hashes, single.hashes, 'the scalar build');
});

test('worlds share the build\'s workers: one asking for more than are free is refused until one gives its back', () => {
  const first = threadsBuild.createWorld({ workerCount: 3 });  // holds 2 of the 3
  assert.throws(() => threadsBuild.createWorld({ workerCount: 3 }), /1 of the build's 3 worker threads are free/);
  const second = threadsBuild.createWorld({ workerCount: 2 });  // the last one
  assert.throws(() => threadsBuild.createWorld({ workerCount: 2 }), /0 of the build's 3/);
  first.destroy();
  const third = threadsBuild.createWorld({ workerCount: 3 });
  second.destroy();
  third.destroy();
  assert.throws(() => threadsBuild.createWorld({ workerCount: 5 }), RangeError);
  assert.throws(() => threadsBuild.createWorld({ workerCount: 0 }), TypeError);
  assert.throws(() => simdBuild.createWorld({ workerCount: 2 }), /this build has no threads/);
});

test('a world of several workers refuses JavaScript hooks, which its workers could not call', () => {
  const world = threadsBuild.createWorld({ workerCount: 2 });
  assert.throws(() => world.setPreSolve(() => true), /runs its hooks on Web Workers/);
  assert.throws(() => world.setCustomFilter(() => true), /runs its hooks on Web Workers/);
  world.setPreSolve(null);  // clearing is always allowed
  world.destroy();
  const single = threadsBuild.createWorld({ workerCount: 1 });
  single.setPreSolve(() => true);
  single.destroy();
});
