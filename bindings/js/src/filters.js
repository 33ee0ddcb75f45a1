// SPDX-License-Identifier: MIT
// Collision and query filters (i2d_filter, i2d_query_filter) as {categoryBits, maskBits,
// groupIndex} objects. The bits are 64 wide in C, more than a JS number holds exactly:
// they are taken as a number (a safe integer) or a BigInt, and given back as BigInts.

const QUERY_FILTER_KEYS = ['categoryBits', 'maskBits'];
const FILTER_KEYS = [...QUERY_FILTER_KEYS, 'groupIndex'];

/** value as a uint64 BigInt; what names it in the TypeError for anything else. */
export function toBits(value, what) {
  if (typeof value === 'bigint') return BigInt.asUintN(64, value);
  if (Number.isSafeInteger(value)) return BigInt.asUintN(64, BigInt(value));
  throw new TypeError(`${what} takes an integer (a number or a BigInt), not ${String(value)}`);
}

function checkKeys(filter, keys, what) {
  if (filter === null || typeof filter !== 'object') {
    throw new TypeError(`${what} takes an object such as {categoryBits, maskBits}, not ${String(filter)}`);
  }
  for (const key of Object.keys(filter)) {
    if (!keys.includes(key)) throw new TypeError(`${what} has no setting '${key}'; known: ${keys.join(', ')}`);
  }
}

/**
 * Writes the i2d_query_filter at `at`: the default query filter (every shape) with the
 * settings filter has; undefined leaves the default.
 */
export function writeQueryFilter(rt, at, filter, what = 'a query filter') {
  rt.u8.copyWithin(at, rt.allFilter, rt.allFilter + rt.size('i2d_query_filter'));
  if (filter === undefined) return at;
  checkKeys(filter, QUERY_FILTER_KEYS, what);
  writeBits(rt, at, 'i2d_query_filter', filter, what);
  return at;
}

/** Writes the settings filter has into the i2d_filter at `at` (a shape def's). */
export function writeFilter(rt, at, filter, what = 'a shape filter') {
  checkKeys(filter, FILTER_KEYS, what);
  writeBits(rt, at, 'i2d_filter', filter, what);
  if (filter.groupIndex !== undefined) rt.i32[(at + rt.field('i2d_filter.group_index')) >> 2] = filter.groupIndex;
}

/** The i2d_query_filter at `at` as {categoryBits, maskBits}. */
export function readQueryFilter(rt, at) {
  const read = (name) => rt.u64[(at + rt.field(`i2d_query_filter.${name}`)) >> 3];
  return { categoryBits: read('category_bits'), maskBits: read('mask_bits') };
}

function writeBits(rt, at, type, filter, what) {
  if (filter.categoryBits !== undefined) {
    rt.u64[(at + rt.field(`${type}.category_bits`)) >> 3] = toBits(filter.categoryBits, `${what}'s categoryBits`);
  }
  if (filter.maskBits !== undefined) {
    rt.u64[(at + rt.field(`${type}.mask_bits`)) >> 3] = toBits(filter.maskBits, `${what}'s maskBits`);
  }
}
