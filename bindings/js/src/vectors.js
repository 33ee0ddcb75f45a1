// SPDX-License-Identifier: MIT
// Points and vectors are accepted as {x, y} or [x, y]; anything else reads as NaN, which
// the library refuses with its own message.

export function vx(v) {
  return v == null ? NaN : Array.isArray(v) ? Number(v[0]) : Number(v.x);
}

export function vy(v) {
  return v == null ? NaN : Array.isArray(v) ? Number(v[1]) : Number(v.y);
}
