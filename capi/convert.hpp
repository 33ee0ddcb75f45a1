// SPDX-License-Identifier: MIT
// Conversions between the public value types and the core's (layout-identical) ones.
#pragma once

#include <impulse2d/types.h>

#include <impulse2d/collision.h>

#include "collision/geometry.hpp"
#include "collision/shapes.hpp"
#include "dynamics/contact/mixing.hpp"
#include "dynamics/body/shape.hpp"
#include "math/vec2.hpp"

namespace i2d::capi {

static_assert(int(I2D_MIX_GEOMETRIC_MEAN) == int(MixingRule::geometric_mean) &&
                  int(I2D_MIX_MINIMUM) == int(MixingRule::minimum) && int(I2D_MIX_MAXIMUM) == int(MixingRule::maximum) &&
                  int(I2D_MIX_AVERAGE) == int(MixingRule::average) && int(I2D_MIX_MULTIPLY) == int(MixingRule::multiply),
              "mixing rules");
/// The rule must have been validated.
inline MixingRule to_core(i2d_mixing_rule r) { return MixingRule(int(r)); }
inline i2d_mixing_rule to_public(MixingRule r) { return i2d_mixing_rule(int(r)); }

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

inline Transform to_core(const i2d_transform& xf) { return {to_core(xf.p), to_core(xf.q)}; }
inline Circle to_core(const i2d_circle& c) { return {to_core(c.center), c.radius}; }
inline Capsule to_core(const i2d_capsule& c) { return {to_core(c.center1), to_core(c.center2), c.radius}; }
inline Segment to_core(const i2d_segment& s) { return {to_core(s.point1), to_core(s.point2)}; }

inline Polygon to_core(const i2d_polygon& p) {
    Polygon out;
    out.count = p.count;
    out.radius = p.radius;
    out.centroid = to_core(p.centroid);
    for (int32_t i = 0; i < p.count; ++i) {
        out.vertices[i] = to_core(p.vertices[i]);
        out.normals[i] = to_core(p.normals[i]);
    }
    return out;
}

inline i2d_polygon to_public(const Polygon& p) {
    i2d_polygon out{};
    out.count = p.count;
    out.radius = p.radius;
    out.centroid = to_public(p.centroid);
    for (int32_t i = 0; i < p.count; ++i) {
        out.vertices[i] = to_public(p.vertices[i]);
        out.normals[i] = to_public(p.normals[i]);
    }
    return out;
}

inline i2d_mass_data to_public(const MassData& md) {
    return {md.mass, to_public(md.center), md.rotational_inertia};
}

inline i2d_cast_output to_public(const RayHit& hit) {
    i2d_cast_output out{};
    if (hit.hit) {
        out.point = to_public(hit.point);
        out.normal = to_public(hit.normal);
        out.fraction = hit.fraction;
        out.hit = true;
    }
    return out;
}

inline i2d_manifold to_public(const Manifold& m) {
    i2d_manifold out{};
    out.normal = to_public(m.normal);
    out.point_count = m.point_count;
    for (int32_t i = 0; i < m.point_count; ++i) {
        out.points[i].point = to_public(m.points[i].point);
        out.points[i].penetration = m.points[i].penetration;
        out.points[i].id = m.points[i].id;
    }
    return out;
}

}  // namespace i2d::capi
