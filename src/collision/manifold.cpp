// SPDX-License-Identifier: MIT
// Contact manifolds: the seed's world-space circle and AABB tests (per ERRATA.md), the
// round shapes (circles, capsules, segments) and the pair table.
#include "collision/manifold.hpp"

#include <cfloat>
#include <cmath>

#include "collision/distance.hpp"
#include "collision/hull.hpp"
#include "math/math.hpp"

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
        const float lo = max_of(a.lower.y, b.lower.y), hi = min_of(a.upper.y, b.upper.y);
        return edge_points({b_right ? 1.0f : -1.0f, 0.0f}, mid, lo, hi, pen_x, true);
    }
    const float mid = b_above ? 0.5f * (a.upper.y + b.lower.y) : 0.5f * (a.lower.y + b.upper.y);
    const float lo = max_of(a.lower.x, b.lower.x), hi = min_of(a.upper.x, b.upper.x);
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

// ---- Round shapes: circles, capsules and segments ------------------------------------

Manifold collide_circles(const Circle& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                         float speculative) {
    const Transform xf = inv_mul_transforms(xf_a, xf_b);
    const Vec2 center_b = transform_point(xf, b.center);
    const Vec2 d = center_b - a.center;
    const float distance = length(d);
    if (distance - a.radius - b.radius > speculative) {
        return {};
    }
    // Coincident centres: any fixed axis, the same every time.
    const Vec2 normal = distance > 0.0f ? (1.0f / distance) * d : Vec2{1.0f, 0.0f};
    return to_world(single_contact(a.center, center_b, normal, distance, a.radius, b.radius, 0), xf_a);
}

Manifold collide_capsule_circle(const Capsule& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                                float speculative) {
    const Transform xf = inv_mul_transforms(xf_a, xf_b);
    const Vec2 center_b = transform_point(xf, b.center);
    const Vec2 closest = closest_point_on_segment(a.center1, a.center2, center_b);
    const Vec2 d = center_b - closest;
    const float distance = length(d);
    if (distance - a.radius - b.radius > speculative) {
        return {};
    }
    // A centre on the core: leave sideways, through the capsule's left face.
    Vec2 normal = distance > 0.0f ? (1.0f / distance) * d : left_perp(normalize(a.center2 - a.center1));
    if (length_squared(normal) == 0.0f) {
        normal = {1.0f, 0.0f};
    }
    return to_world(single_contact(closest, center_b, normal, distance, a.radius, b.radius, 0), xf_a);
}

Manifold collide_segment_circle(const Segment& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                                float speculative) {
    return collide_capsule_circle(Capsule{a.point1, a.point2, 0.0f}, xf_a, b, xf_b, speculative);
}

namespace {

// Two points for capsules lying along each other (after Box2D v3's b2CollideCapsules):
// pick the reference core by the separating-axis test on the two core normals, clip the
// other core to the reference core's extent, and keep both clipped points when one of
// them is about as close as the closest points (else the cores only meet at a corner and
// one point is right). Works in A's local frame with p1 at the origin.
struct CoreSegment {
    Vec2 p, q, u;  // ends and unit direction
    float length = 0.0f;
};

// Largest separation of `other` from the line of `ref`, and the side's normal.
float side_separation(const CoreSegment& ref, const CoreSegment& other, Vec2& out_normal) {
    const Vec2 n = left_perp(ref.u);
    const float sp = dot(other.p - ref.p, n), sq = dot(other.q - ref.p, n);
    const float positive = min_of(sp, sq), negative = min_of(-sp, -sq);
    out_normal = positive > negative ? n : -n;
    return max_of(positive, negative);
}

// Clips `other` to the slab of `ref` (0..length along ref.u). Only ends beyond the slab
// move; the fraction is taken along other's own direction.
void clip_to_slab(const CoreSegment& ref, const CoreSegment& other, Vec2& out_p, Vec2& out_q) {
    const float fp = dot(other.p - ref.p, ref.u), fq = dot(other.q - ref.p, ref.u);
    out_p = other.p, out_q = other.q;
    if (fp < 0.0f && fq > 0.0f) {
        out_p = lerp(other.p, other.q, -fp / (fq - fp));
    } else if (fq < 0.0f && fp > 0.0f) {
        out_q = lerp(other.q, other.p, -fq / (fp - fq));
    }
    if (fp > ref.length && fq < ref.length) {
        out_p = lerp(other.p, other.q, (fp - ref.length) / (fp - fq));
    } else if (fq > ref.length && fp < ref.length) {
        out_q = lerp(other.q, other.p, (fq - ref.length) / (fq - fp));
    }
}

bool outside_slab(const CoreSegment& ref, const CoreSegment& other) {
    const float fp = dot(other.p - ref.p, ref.u), fq = dot(other.q - ref.p, ref.u);
    return (fp <= 0.0f && fq <= 0.0f) || (fp >= ref.length && fq >= ref.length);
}

Manifold clip_capsules(const CoreSegment& a, float ra, const CoreSegment& b, float rb, float distance,
                       float speculative, float slop) {
    Manifold m;
    if (outside_slab(a, b) || outside_slab(b, a)) {
        return m;
    }
    Vec2 normal_a, normal_b;
    const float sep_a = side_separation(a, b, normal_a);
    const float sep_b = side_separation(b, a, normal_b);
    // Prefer A unless B is clearly better, so the reference does not flicker on ties.
    const bool flip = sep_b > sep_a + 0.1f * slop;
    const CoreSegment& ref = flip ? b : a;
    const CoreSegment& inc = flip ? a : b;
    const Vec2 ref_normal = flip ? normal_b : normal_a;  // from the reference toward the other
    const float r_ref = flip ? rb : ra, r_inc = flip ? ra : rb;
    Vec2 cp, cq;
    clip_to_slab(ref, inc, cp, cq);
    const float sp = dot(cp - ref.p, ref_normal), sq = dot(cq - ref.p, ref_normal);
    // The deepest clipped end must be as close as the closest points: otherwise the
    // closest point of the reference core is an end cap and one point is right. Box2D
    // allows a whole slop here; the tight tolerance keeps the reported depth exact at the
    // cost of switching to one point a little earlier.
    if (min_of(sp, sq) > distance + 0.01f * slop) {
        return m;
    }
    m.normal = flip ? -ref_normal : ref_normal;
    const Vec2 ends[2] = {cp, cq};
    const float seps[2] = {sp, sq};
    for (int32_t i = 0; i < 2; ++i) {
        const float penetration = r_ref + r_inc - seps[i];
        if (penetration < -speculative) {
            continue;  // beyond the margin; a larger one keeps this real point of the incident core
        }
        ManifoldPoint& mp = m.points[m.point_count++];
        mp.point = ends[i] + (0.5f * (r_ref - r_inc - seps[i])) * ref_normal;
        mp.penetration = penetration;
        mp.id = make_feature_id(0, i, flip);
    }
    if (m.point_count == 0) {
        return Manifold{};
    }
    return m;
}

CoreSegment core_segment(Vec2 p, Vec2 q) {
    CoreSegment s{p, q, {}, length(q - p)};
    s.u = s.length > 0.0f ? (1.0f / s.length) * (q - p) : Vec2{1.0f, 0.0f};
    return s;
}

}  // namespace

// Closest points of the two cores (Ericson 5.1.9, in distance.cpp), then the two-point
// clip when the cores lie along each other, else one point between the closest points.
Manifold collide_capsules(const Capsule& a, const Transform& xf_a, const Capsule& b, const Transform& xf_b,
                          float speculative, float slop) {
    // A's frame shifted to its first centre keeps precision for capsules far from their body.
    const Vec2 origin = a.center1;
    const Transform frame{transform_point(xf_a, origin), xf_a.q};
    const Transform xf = inv_mul_transforms(frame, xf_b);
    const CoreSegment core_a = core_segment(Vec2{}, a.center2 - origin);
    const CoreSegment core_b = core_segment(transform_point(xf, b.center1), transform_point(xf, b.center2));
    const SegmentDistance sd = segment_distance(core_a.p, core_a.q, core_b.p, core_b.q);
    const float max_distance = a.radius + b.radius + speculative;
    if (sd.distance_squared > max_distance * max_distance) {
        return {};
    }
    const float distance = std::sqrt(sd.distance_squared);
    Manifold m;
    if (core_a.length > slop && core_b.length > slop) {
        m = clip_capsules(core_a, a.radius, core_b, b.radius, distance, speculative, slop);
    }
    if (m.point_count == 0) {
        Vec2 normal = distance > 0.0f ? (1.0f / distance) * (sd.closest2 - sd.closest1) : left_perp(core_a.u);
        const uint32_t id = make_feature_id(sd.fraction1 == 0.0f ? 0 : 1, sd.fraction2 == 0.0f ? 0 : 1);
        m = single_contact(sd.closest1, sd.closest2, normal, distance, a.radius, b.radius, id);
    }
    return to_world(m, frame);
}

Manifold collide_segment_capsule(const Segment& a, const Transform& xf_a, const Capsule& b, const Transform& xf_b,
                                 float speculative, float slop) {
    return collide_capsules(Capsule{a.point1, a.point2, 0.0f}, xf_a, b, xf_b, speculative, slop);
}

Manifold collide_polygon_capsule(const Polygon& a, const Transform& xf_a, const Capsule& b, const Transform& xf_b,
                                 float speculative, float slop) {
    return collide_polygons(a, xf_a, make_capsule_polygon(b.center1, b.center2, b.radius), xf_b, speculative, slop);
}

Manifold collide_segment_polygon(const Segment& a, const Transform& xf_a, const Polygon& b, const Transform& xf_b,
                                 float speculative, float slop) {
    return collide_polygons(make_capsule_polygon(a.point1, a.point2, 0.0f), xf_a, b, xf_b, speculative, slop);
}

// ---- The pair table (Box2D contact.c's s_registers, Jolt's CollisionDispatch) --------

namespace {

using CollideFn = Manifold (*)(const Geometry&, const Transform&, const Geometry&, const Transform&, float, float);

// Adapters from the tagged Geometry to the typed functions, one per primary pair; `spec`
// is the speculative margin and `slop` the tie-break length, passed through to the
// functions that take them.
Manifold circle_circle(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                       float) {
    return collide_circles(a.circle, xa, b.circle, xb, spec);
}
Manifold capsule_circle(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                        float) {
    return collide_capsule_circle(a.capsule, xa, b.circle, xb, spec);
}
Manifold segment_circle(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                        float) {
    return collide_segment_circle(a.segment, xa, b.circle, xb, spec);
}
Manifold polygon_circle(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                        float) {
    return collide_polygon_circle(a.polygon, xa, b.circle, xb, spec);
}
Manifold capsule_capsule(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                         float slop) {
    return collide_capsules(a.capsule, xa, b.capsule, xb, spec, slop);
}
Manifold segment_capsule(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                         float slop) {
    return collide_segment_capsule(a.segment, xa, b.capsule, xb, spec, slop);
}
Manifold polygon_capsule(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                         float slop) {
    return collide_polygon_capsule(a.polygon, xa, b.capsule, xb, spec, slop);
}
Manifold segment_polygon(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                         float slop) {
    return collide_segment_polygon(a.segment, xa, b.polygon, xb, spec, slop);
}
Manifold polygon_polygon(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                         float slop) {
    return collide_polygons(a.polygon, xa, b.polygon, xb, spec, slop);
}
Manifold chain_circle(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                      float) {
    return collide_chain_segment_circle(a.chain_segment, xa, b.circle, xb, spec);
}
Manifold chain_capsule(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                       float slop) {
    return collide_chain_segment_capsule(a.chain_segment, xa, b.capsule, xb, spec, false, slop);
}
Manifold chain_polygon(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, float spec,
                       float slop) {
    return collide_chain_segment_polygon(a.chain_segment, xa, b.polygon, xb, spec, false, slop);
}
// Segments and chains are static geometry: two of them never need a contact.
Manifold segment_segment(const Geometry&, const Transform&, const Geometry&, const Transform&, float, float) {
    return {};
}

struct PairEntry {
    CollideFn fn;
    bool swapped;  // the function takes (B, A): the normal must be flipped back
};

constexpr int32_t kind_count = static_cast<int32_t>(ShapeType::count);

// Row: A's kind, column: B's kind, in the order circle, capsule, segment, polygon, chain
// segment. Each pair has one function, registered once as primary and once swapped.
constexpr PairEntry pair_table[kind_count][kind_count] = {
    /* circle  */ {{circle_circle, false}, {capsule_circle, true}, {segment_circle, true}, {polygon_circle, true},
                   {chain_circle, true}},
    /* capsule */ {{capsule_circle, false}, {capsule_capsule, false}, {segment_capsule, true}, {polygon_capsule, true},
                   {chain_capsule, true}},
    /* segment */ {{segment_circle, false}, {segment_capsule, false}, {segment_segment, false}, {segment_polygon, false},
                   {segment_segment, false}},
    /* polygon */ {{polygon_circle, false}, {polygon_capsule, false}, {segment_polygon, true}, {polygon_polygon, false},
                   {chain_polygon, true}},
    /* chain   */ {{chain_circle, false}, {chain_capsule, false}, {segment_segment, false}, {chain_polygon, false},
                   {segment_segment, false}},
};

}  // namespace

Manifold collide_shapes(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b,
                        float speculative, float slop) {
    const PairEntry& entry = pair_table[static_cast<int32_t>(a.type)][static_cast<int32_t>(b.type)];
    if (!entry.swapped) {
        return entry.fn(a, xf_a, b, xf_b, speculative, slop);
    }
    Manifold m = entry.fn(b, xf_b, a, xf_a, speculative, slop);
    m.normal = -m.normal;
    return m;
}

}  // namespace i2d
