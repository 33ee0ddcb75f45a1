// SPDX-License-Identifier: MIT
// Bounds, point containment and box overlap of every shape kind.
#include "collision/geometry.hpp"

#include <cfloat>
#include <cmath>

#include "collision/distance.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// Every kind is a convex core (1, 2 or n points) grown by a radius: a circle is a point,
// a capsule a segment, a segment a segment of radius 0, a polygon its vertices. The
// bounds and overlap tests below work on that common form.
struct Core {
    Vec2 points[max_polygon_vertices];
    int32_t count = 0;
    float radius = 0.0f;
};

Core world_core(const Geometry& g, const Transform& xf) {
    Core c;
    switch (g.type) {
        case ShapeType::circle:
            c.points[0] = transform_point(xf, g.circle.center);
            c.count = 1;
            c.radius = g.circle.radius;
            break;
        case ShapeType::capsule:
            c.points[0] = transform_point(xf, g.capsule.center1);
            c.points[1] = transform_point(xf, g.capsule.center2);
            c.count = 2;
            c.radius = g.capsule.radius;
            break;
        case ShapeType::segment:
            c.points[0] = transform_point(xf, g.segment.point1);
            c.points[1] = transform_point(xf, g.segment.point2);
            c.count = 2;
            break;
        case ShapeType::chain_segment:
            c.points[0] = transform_point(xf, g.chain_segment.point1);
            c.points[1] = transform_point(xf, g.chain_segment.point2);
            c.count = 2;
            break;
        case ShapeType::polygon:
            for (int32_t i = 0; i < g.polygon.count; ++i) {
                c.points[i] = transform_point(xf, g.polygon.vertices[i]);
            }
            c.count = g.polygon.count;
            c.radius = g.polygon.radius;
            break;
        case ShapeType::count: break;
    }
    return c;
}

// Signed distance from a local point to a convex CCW polygon's core: the largest face
// separation inside (<= 0), the Euclidean distance to the nearest edge outside.
float polygon_core_distance(const Polygon& poly, Vec2 p) {
    float separation = -FLT_MAX;
    for (int32_t i = 0; i < poly.count; ++i) {
        separation = max_of(separation, dot(poly.normals[i], p - poly.vertices[i]));
    }
    if (separation <= 0.0f) {
        return separation;
    }
    float best = FLT_MAX;
    for (int32_t i = 0; i < poly.count; ++i) {
        const Vec2 q = closest_point_on_segment(poly.vertices[i], poly.vertices[i + 1 == poly.count ? 0 : i + 1], p);
        best = min_of(best, distance_squared(p, q));
    }
    return std::sqrt(best);
}

}  // namespace

float extent_from(const Geometry& g, Vec2 local_point) {
    const Core c = world_core(g, Transform{});
    float farthest = 0.0f;
    for (int32_t i = 0; i < c.count; ++i) {
        farthest = max_of(farthest, length(c.points[i] - local_point));
    }
    return farthest + c.radius;
}

float inner_radius(const Geometry& g) {
    switch (g.type) {
        case ShapeType::circle: return g.circle.radius;
        case ShapeType::capsule: return g.capsule.radius;
        case ShapeType::segment: return 0.0f;
        case ShapeType::chain_segment: return 0.0f;
        default: break;
    }
    const Polygon& p = g.polygon;
    float nearest = FLT_MAX;
    for (int32_t i = 0; i < p.count; ++i) {
        nearest = min_of(nearest, dot(p.normals[i], p.vertices[i] - p.centroid));
    }
    return max_of(nearest, 0.0f) + p.radius;
}

float rounding_radius(const Geometry& g) { return world_core(g, Transform{}).radius; }

bool contains_point(const Geometry& g, const Transform& xf, Vec2 p) {
    switch (g.type) {
        case ShapeType::circle: {
            const float r = g.circle.radius;
            return distance_squared(transform_point(xf, g.circle.center), p) <= r * r;
        }
        case ShapeType::capsule: {
            const Vec2 local = inv_transform_point(xf, p);
            const Vec2 q = closest_point_on_segment(g.capsule.center1, g.capsule.center2, local);
            return distance_squared(q, local) <= g.capsule.radius * g.capsule.radius;
        }
        case ShapeType::segment: return false;  // no area
        case ShapeType::chain_segment: return false;
        case ShapeType::polygon:
            return polygon_core_distance(g.polygon, inv_transform_point(xf, p)) <= g.polygon.radius;
        case ShapeType::count: break;
    }
    return false;
}

bool overlaps_aabb(const Geometry& g, const Transform& xf, const AABB& box) {
    if (g.type == ShapeType::circle) {
        const Vec2 c = transform_point(xf, g.circle.center);
        const float r = g.circle.radius;
        return distance_squared(clamp_to(box, c), c) <= r * r;
    }
    const Core c = world_core(g, xf);
    const Vec2 corners[4] = {box.lower, {box.upper.x, box.lower.y}, box.upper, {box.lower.x, box.upper.y}};
    return convex_distance(c.points, c.count, corners, 4) <= c.radius;
}

}  // namespace i2d
