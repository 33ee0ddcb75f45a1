// SPDX-License-Identifier: MIT
// Checks of shape geometry passed through the C API, with messages that name the field.
#pragma once

#include <impulse2d/impulse2d.h>

#include "boundary.hpp"
#include "collision/collision_constants.hpp"
#include "collision/shape_proxy.hpp"

namespace i2d::capi {

/// A rotation within 1e-3 of unit length, normalised exactly into out.
bool normalized_rotation(Call& call, i2d_rot q, const char* what, Rot& out);
bool valid_circle(Call& call, const i2d_circle& c, const char* what);
bool valid_aabb(Call& call, const i2d_aabb& a, const char* what);
/// valid_aabb and within the pure functions' range (|coordinate| <= max_coordinate).
bool valid_collide_aabb(Call& call, const i2d_aabb& a, const char* what);
bool valid_radius(Call& call, float radius, const char* what);
bool valid_transform(Call& call, const i2d_transform& xf, const char* what);
bool valid_circle_ptr(Call& call, const i2d_circle* c, const char* what);
bool valid_core_length(Call& call, i2d_vec2 p1, i2d_vec2 p2, const char* what);
bool valid_capsule(Call& call, const i2d_capsule* c, const char* what);
bool valid_segment(Call& call, const i2d_segment* s, const char* what);
bool valid_polygon(Call& call, const i2d_polygon* p, const char* what);
/// `min_edge`: a caller's polygon has edges of at least the slop; one a world already holds
/// may be a box of the smallest half extents (min_box_edge).
bool valid_convex_polygon(Call& call, const i2d_polygon* p, const char* what, float min_edge = linear_slop);
/// 1..8 points within the coordinate range and a radius in [0, max_shape_extent].
bool valid_proxy_input(Call& call, const i2d_vec2* points, int32_t count, float radius, const char* what);
/// The caller's proxy, checked and made convex again (a hand-built proxy need not be).
bool core_proxy(Call& call, const i2d_shape_proxy* proxy, ShapeProxy& out, const char* what = "proxy");

}  // namespace i2d::capi
