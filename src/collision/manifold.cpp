// SPDX-License-Identifier: MIT
// Contact manifolds for circles and axis-aligned boxes (the seed's part 1, per ERRATA.md).
#include "collision/manifold.hpp"

#include <cmath>

namespace i2d {

namespace {

Manifold single_point(Vec2 normal, Vec2 surface_a, Vec2 surface_b, float penetration) {
    Manifold m;
    m.normal = normal;
    m.point_count = 1;
    m.points[0].point = 0.5f * (surface_a + surface_b);
    m.points[0].penetration = penetration;
    m.points[0].id = 0;
    return m;
}

// Two points on the contact edge: `depth` along the normal, `lo..hi` across it.
Manifold edge_points(Vec2 normal, float mid_along, float lo, float hi, float penetration, bool normal_is_x) {
    Manifold m;
    m.normal = normal;
    m.point_count = lo < hi ? 2 : 1;
    const float across[2] = {lo, hi};
    for (int32_t i = 0; i < m.point_count; ++i) {
        m.points[i].point = normal_is_x ? Vec2{mid_along, across[i]} : Vec2{across[i], mid_along};
        m.points[i].penetration = penetration;
        m.points[i].id = static_cast<uint32_t>(i);
    }
    return m;
}

}  // namespace

Manifold collide_circles(Vec2 center_a, float radius_a, Vec2 center_b, float radius_b) {
    const Vec2 d = center_b - center_a;
    const float dist_sq = length_squared(d);
    const float r = radius_a + radius_b;
    if (dist_sq > r * r) {
        return {};
    }
    const float dist = std::sqrt(dist_sq);
    // Coincident centres have no direction between them: any fixed axis works, and a
    // fixed one keeps the response the same from step to step.
    const Vec2 normal = dist > 0.0f ? (1.0f / dist) * d : Vec2{1.0f, 0.0f};
    return single_point(normal, center_a + radius_a * normal, center_b - radius_b * normal, r - dist);
}

// Separating-axis test on the two axes. The penetration on an axis is how far B must move
// along the chosen normal to separate, measured between the faces that meet, so it is
// right even when one box contains the other.
Manifold collide_aabbs(const AABB& a, const AABB& b) {
    const Vec2 d = center(b) - center(a);
    const bool b_right = d.x >= 0.0f, b_above = d.y >= 0.0f;
    const float pen_x = b_right ? a.upper.x - b.lower.x : b.upper.x - a.lower.x;
    const float pen_y = b_above ? a.upper.y - b.lower.y : b.upper.y - a.lower.y;
    if (pen_x < 0.0f || pen_y < 0.0f) {
        return {};
    }
    if (pen_x <= pen_y) {
        const float mid = b_right ? 0.5f * (a.upper.x + b.lower.x) : 0.5f * (a.lower.x + b.upper.x);
        const float lo = std::fmax(a.lower.y, b.lower.y), hi = std::fmin(a.upper.y, b.upper.y);
        return edge_points({b_right ? 1.0f : -1.0f, 0.0f}, mid, lo, hi, pen_x, true);
    }
    const float mid = b_above ? 0.5f * (a.upper.y + b.lower.y) : 0.5f * (a.lower.y + b.upper.y);
    const float lo = std::fmax(a.lower.x, b.lower.x), hi = std::fmin(a.upper.x, b.upper.x);
    return edge_points({0.0f, b_above ? 1.0f : -1.0f}, mid, lo, hi, pen_y, false);
}

namespace {

// Centre inside (or on) the box: leave through the nearest face. Ties go to the first
// of +x, -x, +y, -y so that the answer never flickers between equal faces.
Manifold circle_centre_inside_aabb(const AABB& a, Vec2 c, float radius) {
    float best = a.upper.x - c.x;
    Vec2 normal{1.0f, 0.0f};
    Vec2 face_point{a.upper.x, c.y};
    if (c.x - a.lower.x < best) {
        best = c.x - a.lower.x, normal = {-1.0f, 0.0f}, face_point = {a.lower.x, c.y};
    }
    if (a.upper.y - c.y < best) {
        best = a.upper.y - c.y, normal = {0.0f, 1.0f}, face_point = {c.x, a.upper.y};
    }
    if (c.y - a.lower.y < best) {
        best = c.y - a.lower.y, normal = {0.0f, -1.0f}, face_point = {c.x, a.lower.y};
    }
    return single_point(normal, face_point, c - radius * normal, radius + best);
}

}  // namespace

Manifold collide_aabb_circle(const AABB& a, Vec2 center_b, float radius_b) {
    const Vec2 closest = clamp_to(a, center_b);
    const Vec2 d = center_b - closest;
    const float dist_sq = length_squared(d);
    if (dist_sq > radius_b * radius_b) {
        return {};
    }
    const float dist = std::sqrt(dist_sq);
    if (dist == 0.0f) {
        return circle_centre_inside_aabb(a, center_b, radius_b);
    }
    const Vec2 normal = (1.0f / dist) * d;
    return single_point(normal, closest, center_b - radius_b * normal, radius_b - dist);
}

namespace {

AABB box_bounds(const Geometry& g, const Transform& xf) {
    // Bodies do not rotate yet: the box stays axis-aligned in world space.
    return {xf.p - g.box.half_extents, xf.p + g.box.half_extents};
}

Manifold circle_vs_circle(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b) {
    return collide_circles(transform_point(xf_a, a.circle.center), a.circle.radius,
                           transform_point(xf_b, b.circle.center), b.circle.radius);
}

Manifold box_vs_circle(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b) {
    return collide_aabb_circle(box_bounds(a, xf_a), transform_point(xf_b, b.circle.center), b.circle.radius);
}

Manifold box_vs_box(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b) {
    return collide_aabbs(box_bounds(a, xf_a), box_bounds(b, xf_b));
}

using CollideFn = Manifold (*)(const Geometry&, const Transform&, const Geometry&, const Transform&);

struct PairEntry {
    CollideFn fn;
    bool swapped;  // the function takes (B, A): the normal must be flipped back
};

constexpr int32_t kind_count = static_cast<int32_t>(ShapeType::count);

// One plain function per pair of kinds, each registered once in its primary order.
constexpr PairEntry pair_table[kind_count][kind_count] = {
    /* circle */ {{circle_vs_circle, false}, {box_vs_circle, true}},
    /* box    */ {{box_vs_circle, false}, {box_vs_box, false}},
};

}  // namespace

Manifold collide_shapes(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b) {
    const PairEntry& entry = pair_table[static_cast<int32_t>(a.type)][static_cast<int32_t>(b.type)];
    if (!entry.swapped) {
        return entry.fn(a, xf_a, b, xf_b);
    }
    Manifold m = entry.fn(b, xf_b, a, xf_a);
    m.normal = -m.normal;
    return m;
}

}  // namespace i2d
