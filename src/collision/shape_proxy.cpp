// SPDX-License-Identifier: MIT
// Shape proxies and the exact distance between their cores.
#include "collision/shape_proxy.hpp"

#include <cfloat>
#include <cmath>

#include "collision/distance.hpp"
#include "collision/hull.hpp"
#include "math/math.hpp"

namespace i2d {

ShapeProxy make_shape_proxy(const Geometry& g) {
    ShapeProxy p;
    switch (g.type) {
        case ShapeType::circle:
            p.points[0] = g.circle.center;
            p.count = 1;
            p.radius = g.circle.radius;
            break;
        case ShapeType::capsule:
            p.points[0] = g.capsule.center1;
            p.points[1] = g.capsule.center2;
            p.count = 2;
            p.radius = g.capsule.radius;
            break;
        case ShapeType::segment:
            p.points[0] = g.segment.point1;
            p.points[1] = g.segment.point2;
            p.count = 2;
            break;
        case ShapeType::chain_segment:
            p.points[0] = g.chain_segment.point1;
            p.points[1] = g.chain_segment.point2;
            p.count = 2;
            break;
        default:
            for (int32_t i = 0; i < g.polygon.count; ++i) {
                p.points[i] = g.polygon.vertices[i];
            }
            p.count = g.polygon.count;
            p.radius = g.polygon.radius;
            break;
    }
    return p;
}

ShapeProxy make_query_proxy(const Vec2* points, int32_t count, float radius) {
    ShapeProxy p;
    p.radius = radius;
    Hull hull;
    if (count >= 3 && compute_hull(points, count, hull) == HullStatus::ok) {
        for (int32_t i = 0; i < hull.count; ++i) {
            p.points[i] = hull.points[i];
        }
        p.count = hull.count;
        return p;
    }
    // Degenerate: the two points farthest apart carry the whole set.
    int32_t best_i = 0, best_j = 0;
    float best = -1.0f;
    for (int32_t i = 0; i < count; ++i) {
        for (int32_t j = i + 1; j < count; ++j) {
            const float d = distance_squared(points[i], points[j]);
            if (d > best) {
                best = d, best_i = i, best_j = j;
            }
        }
    }
    p.points[0] = points[best_i];
    p.points[1] = points[best_j];
    p.count = best > linear_slop * linear_slop ? 2 : 1;
    return p;
}

AABB proxy_aabb(const ShapeProxy& proxy) {
    AABB box{proxy.points[0], proxy.points[0]};
    for (int32_t i = 1; i < proxy.count; ++i) {
        box.lower = min(box.lower, proxy.points[i]);
        box.upper = max(box.upper, proxy.points[i]);
    }
    const Vec2 r{proxy.radius, proxy.radius};
    return {box.lower - r, box.upper + r};
}

ShapeProxy transformed(const ShapeProxy& proxy, const Transform& xf) {
    ShapeProxy out = proxy;
    for (int32_t i = 0; i < proxy.count; ++i) {
        out.points[i] = transform_point(xf, proxy.points[i]);
    }
    return out;
}

namespace {

int32_t edge_count(const ShapeProxy& p) { return p.count >= 3 ? p.count : (p.count == 2 ? 1 : 0); }

// Whether an edge normal of `a` separates it from `b` (touching is not separated). A
// segment has both sides as faces: its edge is walked both ways.
bool separated_by_edge_of(const ShapeProxy& a, const ShapeProxy& b) {
    if (a.count < 2) {
        return false;  // a point has no faces: the other set's edges decide
    }
    for (int32_t i = 0; i < a.count; ++i) {
        const Vec2 v = a.points[i];
        const Vec2 outward = right_perp(a.points[i + 1 == a.count ? 0 : i + 1] - v);
        float lowest = FLT_MAX;
        for (int32_t j = 0; j < b.count; ++j) {
            lowest = min_of(lowest, dot(outward, b.points[j] - v));
        }
        if (lowest > 0.0f) {
            return true;
        }
    }
    return false;
}

// Every vertex of `from` against every edge (or the single point) of `to`; keeps the
// closest pair in `best`, with point_a on the proxy the caller calls A.
void closest_vertex_edge(const ShapeProxy& from, const ShapeProxy& to, bool from_is_a, ProxyDistance& best,
                         float& best_sq) {
    const int32_t edges = edge_count(to);
    for (int32_t i = 0; i < from.count; ++i) {
        const Vec2 p = from.points[i];
        for (int32_t j = 0; j < (edges > 0 ? edges : 1); ++j) {
            const Vec2 q = edges == 0 ? to.points[0]
                                      : closest_point_on_segment(to.points[j], to.points[j + 1 == to.count ? 0 : j + 1], p);
            const float d_sq = distance_squared(p, q);
            if (d_sq < best_sq) {
                best_sq = d_sq;
                best.point_a = from_is_a ? p : q;
                best.point_b = from_is_a ? q : p;
            }
        }
    }
}

}  // namespace

ProxyDistance core_distance(const ShapeProxy& a, const ShapeProxy& b) {
    ProxyDistance out;
    if (a.count == 2 && b.count == 2) {
        // Two segments may cross without a vertex of one near the other.
        const SegmentDistance sd = segment_distance(a.points[0], a.points[1], b.points[0], b.points[1]);
        out.point_a = sd.closest1;
        out.point_b = sd.closest2;
        out.distance = std::sqrt(sd.distance_squared);
    } else {
        const bool apart = a.count < 3 && b.count < 3 ? true
                                                      : separated_by_edge_of(a, b) || separated_by_edge_of(b, a);
        // A point or segment against a polygon is inside it when no polygon edge separates.
        if (!apart) {
            out.point_a = out.point_b = a.points[0];
            out.normal = Vec2{1.0f, 0.0f};
            return out;
        }
        float best_sq = FLT_MAX;
        closest_vertex_edge(a, b, true, out, best_sq);
        closest_vertex_edge(b, a, false, out, best_sq);
        out.distance = std::sqrt(best_sq);
    }
    const Vec2 d = out.point_b - out.point_a;
    out.normal = out.distance > 0.0f ? (1.0f / out.distance) * d : Vec2{1.0f, 0.0f};
    return out;
}

// Apart (or just touching), each core point moves out by its radius along the normal.
// Overlapping, no normal is meaningful and both points are one: where the cores are
// apart, the middle of the stretch of the line between them that both shapes hold
// (non-empty, since the radii cover the gap); where the cores overlap too, the point
// core_distance gives, which lies in A's core.
SurfaceDistance surface_distance(const ShapeProxy& a, const Transform& xa, const ShapeProxy& b, const Transform& xb) {
    const ProxyDistance core = core_distance(transformed(a, xa), transformed(b, xb));
    SurfaceDistance out;
    const float reach = a.radius + b.radius;
    if (core.distance > 0.0f && core.distance >= reach) {
        out.normal = core.normal;
        out.point_a = core.point_a + a.radius * core.normal;
        out.point_b = core.point_b - b.radius * core.normal;
        out.distance = core.distance - reach;
        return out;
    }
    float along = 0.0f;  // from A's core point towards B's
    if (core.distance > 0.0f) {
        along = 0.5f * (max_of(0.0f, core.distance - b.radius) + min_of(core.distance, a.radius));
    }
    out.point_a = out.point_b = core.point_a + along * core.normal;
    return out;
}

// The target is a proxy of one point and no radius: its distance to the shape's surface
// is 0 exactly when the shape holds it.
Vec2 closest_point(const ShapeProxy& proxy, const Transform& xf, Vec2 target) {
    ShapeProxy point;
    point.points[0] = target;
    point.count = 1;
    const SurfaceDistance d = surface_distance(proxy, xf, point, Transform{});
    return d.distance > 0.0f ? d.point_a : target;
}

}  // namespace i2d
