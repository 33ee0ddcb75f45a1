// SPDX-License-Identifier: MIT
// Per-shape geometry: mass, bounds, point and box overlap, ray casts.
#pragma once

#include "collision/shapes.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace i2d {

/// Mass, centroid and rotational inertia about the centroid for a uniform density
/// (kg/m^2). Segments have no area and no mass.
MassData compute_mass(const Geometry& g, float density);
float area(const Geometry& g);
/// Tight world-space bounds of the shape placed by xf: the box of its core points (the
/// centre, the segment or the vertices) grown by its radius.
///
/// Inline, and without the core copy geometry.cpp's other tests build: every step refits
/// every awake body's shapes, and so does a bulk transform write for each body it moves.
/// Out of line, the returned box crossed in two registers that GCC put back together
/// through the stack and reloaded in one 16-byte load, a store-forwarding stall per shape;
/// the copy zeroed and filled eight points for a box's four. Same operations in the same
/// order, so the same bits.
inline AABB compute_aabb(const Geometry& g, const Transform& xf) {
    Vec2 lower, upper;
    float radius = 0.0f;
    switch (g.type) {
        case ShapeType::circle:
            lower = upper = transform_point(xf, g.circle.center);
            radius = g.circle.radius;
            break;
        case ShapeType::capsule: {
            const Vec2 p1 = transform_point(xf, g.capsule.center1), p2 = transform_point(xf, g.capsule.center2);
            lower = min(p1, p2);
            upper = max(p1, p2);
            radius = g.capsule.radius;
            break;
        }
        case ShapeType::segment: {
            const Vec2 p1 = transform_point(xf, g.segment.point1), p2 = transform_point(xf, g.segment.point2);
            lower = min(p1, p2);
            upper = max(p1, p2);
            break;
        }
        case ShapeType::chain_segment: {
            const Vec2 p1 = transform_point(xf, g.chain_segment.point1);
            const Vec2 p2 = transform_point(xf, g.chain_segment.point2);
            lower = min(p1, p2);
            upper = max(p1, p2);
            break;
        }
        case ShapeType::polygon: {
#if defined(__SSE2__)
            // Each corner in the lanes [x, y, -x, -y], so that one minimum per vertex keeps
            // the lower corner and the negated upper one. Every lane is the scalar formula
            // of the #else branch to the bit: a product with a negated factor is the
            // negated product, a + (-b) is a - b, rounding commutes with negation, and
            // min(-u, -x) is -max(u, x) (x < y ? x : y, as min() is), taken vertex by
            // vertex in the same order. Scalar, the vertex loop was a chain of shuffles
            // and single minima (clang) that cost a bulk transform write 1 to 2 ns a body.
            const __m128 by_x = _mm_setr_ps(xf.q.c, xf.q.s, -xf.q.c, -xf.q.s);
            const __m128 by_y = _mm_setr_ps(-xf.q.s, xf.q.c, xf.q.s, -xf.q.c);
            const __m128 origin = _mm_setr_ps(xf.p.x, xf.p.y, -xf.p.x, -xf.p.y);
            const auto corner = [&](Vec2 v) {
                const __m128 turned = _mm_add_ps(_mm_mul_ps(by_x, _mm_set1_ps(v.x)), _mm_mul_ps(by_y, _mm_set1_ps(v.y)));
                return _mm_add_ps(turned, origin);
            };
            __m128 box = corner(g.polygon.vertices[0]);
            for (int32_t i = 1; i < g.polygon.count; ++i) {
                box = _mm_min_ps(box, corner(g.polygon.vertices[i]));
            }
            alignas(16) float lanes[4];
            _mm_store_ps(lanes, box);
            lower = {lanes[0], lanes[1]};
            upper = {-lanes[2], -lanes[3]};
#else
            lower = upper = transform_point(xf, g.polygon.vertices[0]);
            for (int32_t i = 1; i < g.polygon.count; ++i) {
                const Vec2 p = transform_point(xf, g.polygon.vertices[i]);
                lower = min(lower, p);
                upper = max(upper, p);
            }
#endif
            radius = g.polygon.radius;
            break;
        }
        case ShapeType::count: break;
    }
    const Vec2 r{radius, radius};
    return {lower - r, upper + r};
}

/// Farthest distance of the shape's points from a point of the body frame, m.
float extent_from(const Geometry& g, Vec2 local_point);
/// Smallest distance from the shape's centroid to its surface, m (a circle's radius, a
/// box's half thickness plus rounding): how far the shape may move in a step before it
/// could pass through something thin. Segments have none (0).
float inner_radius(const Geometry& g);
/// Radius of the shape's rounding (circle and capsule radius, polygon rounding), m:
/// the lever arm of rolling resistance.
float rounding_radius(const Geometry& g);

/// Exact tests, boundary included. Segments contain no point.
bool contains_point(const Geometry& g, const Transform& xf, Vec2 p);
bool overlaps_aabb(const Geometry& g, const Transform& xf, const AABB& box);

struct RayHit {
    Vec2 point;
    Vec2 normal;  // unit, facing the incoming ray
    float fraction = 0.0f;
    bool hit = false;
};

/// First entry of origin + t * translation, t in [0, max_fraction]. A shape that
/// strictly contains the origin is not hit. Segments are hit from either side.
RayHit ray_cast(const Geometry& g, const Transform& xf, Vec2 origin, Vec2 translation, float max_fraction);

}  // namespace i2d
