// SPDX-License-Identifier: MIT
// Conversions between the public value types and the core's (layout-identical) ones.
#pragma once

#include <impulse2d/types.h>

#include "dynamics/shape.hpp"
#include "math/vec2.hpp"

namespace i2d::capi {

inline Vec2 to_core(i2d_vec2 v) { return {v.x, v.y}; }
inline Rot to_core(i2d_rot q) { return {q.c, q.s}; }
inline AABB to_core(i2d_aabb a) { return {to_core(a.min), to_core(a.max)}; }
inline Filter to_core(i2d_filter f) { return {f.category_bits, f.mask_bits, f.group_index}; }
inline QueryFilter to_core(i2d_query_filter f) { return {f.category_bits, f.mask_bits}; }

inline i2d_vec2 to_public(Vec2 v) { return {v.x, v.y}; }
inline i2d_rot to_public(Rot q) { return {q.c, q.s}; }
inline i2d_transform to_public(const Transform& xf) { return {to_public(xf.p), to_public(xf.q)}; }
inline i2d_aabb to_public(const AABB& a) { return {to_public(a.lower), to_public(a.upper)}; }
inline i2d_filter to_public(const Filter& f) { return {f.category_bits, f.mask_bits, f.group_index}; }

}  // namespace i2d::capi
