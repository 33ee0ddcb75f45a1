// SPDX-License-Identifier: MIT
// Double-precision brute-force geometry for the collision tests: every shape as a convex
// core (1, 2 or n world points) grown by a radius, and distances, depths and random
// shapes built from that form without the library's algorithms.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "collision/hull.hpp"
#include "collision/shapes.hpp"
#include "test_rng.hpp"

namespace brute {

struct P {
    double x = 0.0, y = 0.0;
};
inline P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
inline P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
inline P operator*(double s, P a) { return {s * a.x, s * a.y}; }
inline double dot(P a, P b) { return a.x * b.x + a.y * b.y; }
inline double cross(P a, P b) { return a.x * b.y - a.y * b.x; }
inline double len(P a) { return std::sqrt(dot(a, a)); }
inline P unit(P a) { return (1.0 / len(a)) * a; }
inline P p(i2d::Vec2 v) { return {v.x, v.y}; }

// Closed intervals: boxes that only touch overlap.
inline bool boxes_overlap(const i2d::AABB& a, const i2d::AABB& b) {
    return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

inline bool same_box(const i2d::AABB& a, const i2d::AABB& b) {
    return a.lower.x == b.lower.x && a.lower.y == b.lower.y && a.upper.x == b.upper.x && a.upper.y == b.upper.y;
}

inline P to_world(const i2d::Transform& xf, i2d::Vec2 v) {
    const double c = xf.q.c, s = xf.q.s;
    return {c * v.x - s * v.y + xf.p.x, s * v.x + c * v.y + xf.p.y};
}

/// A shape's core in world space (counter-clockwise when 3 or more points) and its radius.
struct Core {
    std::vector<P> pts;
    double radius = 0.0;
};

inline Core core_of(const i2d::Geometry& g, const i2d::Transform& xf) {
    Core c;
    switch (g.type) {
        case i2d::ShapeType::circle:
            c.pts = {to_world(xf, g.circle.center)};
            c.radius = g.circle.radius;
            break;
        case i2d::ShapeType::capsule:
            c.pts = {to_world(xf, g.capsule.center1), to_world(xf, g.capsule.center2)};
            c.radius = g.capsule.radius;
            break;
        case i2d::ShapeType::segment:
            c.pts = {to_world(xf, g.segment.point1), to_world(xf, g.segment.point2)};
            break;
        case i2d::ShapeType::chain_segment:
            c.pts = {to_world(xf, g.chain_segment.point1), to_world(xf, g.chain_segment.point2)};
            break;
        case i2d::ShapeType::polygon:
            for (int32_t i = 0; i < g.polygon.count; ++i) {
                c.pts.push_back(to_world(xf, g.polygon.vertices[i]));
            }
            c.radius = g.polygon.radius;
            break;
        case i2d::ShapeType::count: break;
    }
    return c;
}

inline double point_segment(P q, P a, P b) {
    const P e = b - a;
    const double ee = dot(e, e);
    const double t = ee > 0.0 ? std::clamp(dot(q - a, e) / ee, 0.0, 1.0) : 0.0;
    return len(q - (a + t * e));
}

// Proper or touching crossing of two segments, by orientations.
inline bool segments_cross(P a, P b, P c, P d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) && ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0)) &&
           !(d1 == 0 && d2 == 0);  // collinear pairs are measured by distances instead
}

// Outward normals of the core's faces: a polygon's edges, a segment's two sides.
inline std::vector<P> face_normals(const std::vector<P>& v) {
    std::vector<P> out;
    const size_t n = v.size();
    if (n < 2) {
        return out;
    }
    const size_t edges = n == 2 ? 2 : n;
    for (size_t i = 0; i < edges; ++i) {
        const P e = v[(i + 1) % n] - v[i];
        out.push_back(unit(P{e.y, -e.x}));
    }
    return out;
}

/// Euclidean distance between two cores (0 when they intersect).
inline double core_gap(const std::vector<P>& a, const std::vector<P>& b) {
    double best = DBL_MAX;
    auto edges_of = [](const std::vector<P>& v, size_t i) { return std::make_pair(v[i], v[(i + 1) % v.size()]); };
    for (const P& q : a) {
        for (size_t j = 0; j < b.size(); ++j) {
            auto e = edges_of(b, j);
            best = std::min(best, point_segment(q, e.first, e.second));
        }
    }
    for (const P& q : b) {
        for (size_t j = 0; j < a.size(); ++j) {
            auto e = edges_of(a, j);
            best = std::min(best, point_segment(q, e.first, e.second));
        }
    }
    // Intersecting: edges cross, or one core holds a point of the other.
    for (size_t i = 0; i < a.size(); ++i) {
        for (size_t j = 0; j < b.size(); ++j) {
            auto ea = edges_of(a, i);
            auto eb = edges_of(b, j);
            if (a.size() > 1 && b.size() > 1 && segments_cross(ea.first, ea.second, eb.first, eb.second)) {
                return 0.0;
            }
        }
    }
    auto inside = [](const std::vector<P>& poly, P q) {
        if (poly.size() < 3) {
            return false;
        }
        for (size_t i = 0; i < poly.size(); ++i) {
            if (cross(poly[(i + 1) % poly.size()] - poly[i], q - poly[i]) < 0.0) {
                return false;
            }
        }
        return true;
    };
    if (inside(a, b[0]) || inside(b, a[0])) {
        return 0.0;
    }
    return best;
}

/// Penetration depth of two sharp convex polygons (>= 3 points each) by trying every
/// face normal of both as the push direction for B: the smallest push that separates.
/// Negative when some axis separates them. out_axis receives the best direction.
inline double polygon_depth(const std::vector<P>& a, const std::vector<P>& b, P* out_axis = nullptr,
                            std::vector<std::pair<double, P>>* all = nullptr) {
    std::vector<P> axes = face_normals(a);
    for (const P& n : face_normals(b)) {
        axes.push_back(-1.0 * n);
    }
    double best = DBL_MAX;
    for (const P& u : axes) {
        double max_a = -DBL_MAX, min_b = DBL_MAX;
        for (const P& q : a) max_a = std::max(max_a, dot(u, q));
        for (const P& q : b) min_b = std::min(min_b, dot(u, q));
        const double d = max_a - min_b;
        if (all) all->push_back({d, u});
        if (d < best) {
            best = d;
            if (out_axis) *out_axis = u;
        }
    }
    return best;
}

/// Signed distance from a point to a rounded core: negative inside.
inline double signed_distance(const Core& c, P q) {
    double outside = DBL_MAX;
    const size_t n = c.pts.size();
    if (n == 1) {
        outside = len(q - c.pts[0]);
    } else {
        for (size_t i = 0; i < (n == 2 ? 1 : n); ++i) {
            outside = std::min(outside, point_segment(q, c.pts[i], c.pts[(i + 1) % n]));
        }
    }
    if (n >= 3) {
        double deepest = -DBL_MAX;
        for (size_t i = 0; i < n; ++i) {
            const P e = c.pts[(i + 1) % n] - c.pts[i];
            deepest = std::max(deepest, cross(q - c.pts[i], e) / len(e));  // > 0 outside the edge
        }
        if (deepest <= 0.0) {
            return deepest - c.radius;
        }
    }
    return outside - c.radius;
}

// ---- Random shapes -------------------------------------------------------------------

inline i2d::Rot random_rot(TestRng& rng) {
    const float a = rng.uniform(-3.14159f, 3.14159f);
    return {std::cos(a), std::sin(a)};
}

inline i2d::Transform random_transform(TestRng& rng, float spread) {
    return {{rng.uniform(-spread, spread), rng.uniform(-spread, spread)}, random_rot(rng)};
}

/// A random convex polygon: 3..8 points on a jittered ellipse, or a box.
inline i2d::Polygon random_polygon(TestRng& rng, float radius) {
    if (rng.below(4) == 0) {
        i2d::Polygon box = i2d::make_offset_box(rng.uniform(0.1f, 1.0f), rng.uniform(0.1f, 1.0f),
                                                {rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f)}, random_rot(rng));
        box.radius = radius;
        return box;
    }
    for (;;) {
        const int32_t n = 3 + rng.below(6);
        const float rx = rng.uniform(0.2f, 1.2f), ry = rng.uniform(0.2f, 1.2f);
        i2d::Vec2 pts[8];
        for (int32_t i = 0; i < n; ++i) {
            const float a = rng.uniform(0.0f, 6.2831853f);
            pts[i] = {rx * std::cos(a), ry * std::sin(a)};
        }
        i2d::Hull hull;
        if (i2d::compute_hull(pts, n, hull) == i2d::HullStatus::ok) {
            return i2d::make_polygon(hull, radius);
        }
    }
}

/// The kinds random_geometry makes: every ShapeType before chain_segment. A chain segment
/// takes its neighbours' ghost points and is not a shape on its own (tests/physics/
/// test_chain.cpp and tests/api/test_api_chains.c test chains).
constexpr int32_t random_kind_count = int32_t(i2d::ShapeType::chain_segment);

inline i2d::Geometry random_geometry(TestRng& rng, i2d::ShapeType type) {
    i2d::Geometry g;
    g.type = type;
    switch (type) {
        case i2d::ShapeType::circle:
            g.circle = {{rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f)}, rng.uniform(0.1f, 1.0f)};
            break;
        case i2d::ShapeType::capsule: {
            const i2d::Vec2 c{rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f)};
            const float a = rng.uniform(0.0f, 6.2831853f), l = rng.uniform(0.05f, 1.0f);
            const i2d::Vec2 h{l * std::cos(a), l * std::sin(a)};
            g.capsule = {c - h, c + h, rng.uniform(0.05f, 0.6f)};
            break;
        }
        case i2d::ShapeType::segment: {
            const i2d::Vec2 c{rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f)};
            const float a = rng.uniform(0.0f, 6.2831853f), l = rng.uniform(0.05f, 1.5f);
            const i2d::Vec2 h{l * std::cos(a), l * std::sin(a)};
            g.segment = {c - h, c + h};
            break;
        }
        case i2d::ShapeType::polygon:
            g.polygon = random_polygon(rng, rng.below(2) == 0 ? 0.0f : rng.uniform(0.02f, 0.4f));
            break;
        case i2d::ShapeType::chain_segment:  // neighbour-dependent: not a random single shape
        case i2d::ShapeType::count: break;
    }
    return g;
}

}  // namespace brute
