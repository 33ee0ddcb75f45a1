// SPDX-License-Identifier: MIT
// Snapshots and rollback states (include/impulse2d/snapshot.h): the library's bytes copied
// out of and into the module's memory, and which Body, Shape and Joint objects a world
// has after a snapshot is restored.
//
// The C API has no call that lists a world's bodies, so the binding cannot rebuild its
// objects from the bytes alone. Instead takeSnapshot remembers, beside the bytes it
// returns (in a WeakMap keyed by that Uint8Array, so the record lives exactly as long as
// the bytes), which objects the world had: restoring those bytes brings the same objects
// back in the same world, or new ones over the translated ids (i2d_body_in_world and the
// like) in another. Bytes the binding did not return (read from a file, copied, made by
// another process) restore just as well in the library; the binding then only drops the
// objects whose ids went stale, and a new world made from them has no objects at all
// (step it, hash it, snapshot it). A rollback state never changes a world's structure (the
// library refuses it otherwise), so its restore leaves the objects as they are.
import { Impulse2dError } from './errors.js';

const I2D_ERR_OUT_OF_MEMORY = 5;

/** Uint8Array returned by takeSnapshot -> {world, bodies: [[Body, Shape[]]], joints: Joint[]}. */
const structureAtSave = new WeakMap();

/** The world's objects now, as a restore of a snapshot taken now should bring them back. */
export function rememberStructure(bytes, world) {
  structureAtSave.set(bytes, {
    world,
    bodies: world.bodies.map((body) => [body, [...body.shapes]]),
    joints: world.joints,
  });
}

/** What rememberStructure kept for these bytes, if they came from a world of runtime rt. */
export function structureOf(bytes, rt) {
  const record = structureAtSave.get(bytes);
  return record !== undefined && record.world.rt === rt ? record : undefined;
}

/**
 * Saves with the library's size and save functions (`_i2d_world_get_<kind>_size`,
 * `_i2d_world_save_<kind>`) into a block of the module's memory and returns a copy of
 * the bytes; the block is freed whatever happens.
 */
export function saveBytes(rt, worldId, sizeFn, saveFn) {
  const size = rt.m[sizeFn](worldId);
  rt.checkLast();  // 0 bytes and a status for a bad world
  const at = allocate(rt, size);
  try {
    const written = rt.result();
    rt.check(rt.m[saveFn](worldId, at, size, written));
    return rt.u8.slice(at, at + rt.u32[written >> 2]);
  } finally {
    rt.m._free(at);
  }
}

/** Copies bytes (a Uint8Array, Node Buffer or ArrayBuffer) into the module's memory, calls
 *  use(address, length) and frees the copy; returns what use returns. */
export function withBytesInModule(rt, bytes, use) {
  const view = asBytes(bytes);
  const at = allocate(rt, Math.max(view.length, 1));  // a refused empty buffer still has an address
  try {
    rt.u8.set(view, at);
    return use(at, view.length);
  } finally {
    rt.m._free(at);
  }
}

function asBytes(bytes) {
  if (bytes instanceof Uint8Array) return bytes;
  if (bytes instanceof ArrayBuffer) return new Uint8Array(bytes);
  throw new TypeError(`a snapshot or state is a Uint8Array or an ArrayBuffer, not ${Object.prototype.toString.call(bytes)}`);
}

function allocate(rt, size) {
  const at = rt.m._malloc(size);
  if (at === 0) throw new Impulse2dError(I2D_ERR_OUT_OF_MEMORY, `the module could not allocate ${size} bytes`);
  return at;
}
