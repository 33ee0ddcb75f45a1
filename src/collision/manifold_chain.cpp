// SPDX-License-Identifier: MIT
// Manifolds against chain segments: one-sided, and smooth across the chain's seams.
//
// A box sliding along a floor of separate segments catches on the seams ("ghost
// collisions"): at the shared point the separating axis test may pick the box's side
// face, or the vertex's own direction, and push the box backwards or up. A chain segment
// knows its neighbours (the ghost points), which decides which normals it may give (Box2D's
// chain shapes; the test below is simpler than Box2D's, with the same aim):
// - its own face normal, always;
// - at an end where the chain bends away from the free side (a convex corner), any normal
//   between its face normal and the neighbour's, which no segment's face covers;
// - nothing else: at a flat or concave seam the neighbour's face already holds the body,
//   so a polygon gets a contact on this segment's face instead (its incident edge
//   clipped to the segment), and a circle none.
// A shape whose centre lies behind the segment (the left of point1 -> point2) gets no
// contact at all: that is what makes the chain one-sided. Unless the segment holds it:
// a shape that touched the free side and was then pushed through (crushed against a wall
// by a spinning blade, say) keeps a contact on the segment's face, which pushes it back.
// The caller knows which shapes are held (their contact had points the step before).
#include <cmath>

#include "collision/hull.hpp"
#include "collision/manifold.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

/// A normal within this cosine of the face normal counts as the face normal.
constexpr float face_normal_cos = 0.9999f;
/// Bends smaller than this (sine of the angle) count as flat.
constexpr float flat_bend_sine = 1.0e-4f;

struct WorldChainSegment {
    Vec2 ghost1, point1, point2, ghost2;
    Vec2 normal;  // unit, to the free side
};

WorldChainSegment to_world(const ChainSegment& c, const Transform& xf) {
    WorldChainSegment w{transform_point(xf, c.ghost1), transform_point(xf, c.point1), transform_point(xf, c.point2),
                        transform_point(xf, c.ghost2), Vec2{}};
    w.normal = normalize(right_perp(w.point2 - w.point1));
    return w;
}

bool behind(const WorldChainSegment& s, Vec2 centre) { return dot(centre - s.point1, s.normal) < 0.0f; }

// Whether the chain bends away from the free side between edges d0 and d1.
bool convex_bend(Vec2 d0, Vec2 d1) { return cross(normalize(d0), normalize(d1)) > flat_bend_sine; }

bool admissible(const WorldChainSegment& s, Vec2 n) {
    if (dot(n, s.normal) >= face_normal_cos) {
        return true;
    }
    const Vec2 edge = s.point2 - s.point1;
    if (convex_bend(s.point1 - s.ghost1, edge)) {
        const Vec2 previous = normalize(right_perp(s.point1 - s.ghost1));
        if (cross(previous, n) >= 0.0f && cross(n, s.normal) >= 0.0f) {
            return true;
        }
    }
    if (convex_bend(edge, s.ghost2 - s.point2)) {
        const Vec2 next = normalize(right_perp(s.ghost2 - s.point2));
        if (cross(s.normal, n) >= 0.0f && cross(n, next) >= 0.0f) {
            return true;
        }
    }
    return false;
}

// The polygon (world vertices) against the segment's face alone: its edge that faces
// the segment most, clipped to the segment's extent, points within `speculative`.
Manifold face_contact(const WorldChainSegment& s, const Polygon& b, const Transform& xf_b, float speculative) {
    const Vec2 n = s.normal;
    int32_t incident = 0;
    float lowest = dot(rotate(xf_b.q, b.normals[0]), n);
    for (int32_t i = 1; i < b.count; ++i) {
        const float d = dot(rotate(xf_b.q, b.normals[i]), n);
        if (d < lowest) {
            lowest = d, incident = i;
        }
    }
    const int32_t next = incident + 1 == b.count ? 0 : incident + 1;
    Vec2 ends[2] = {transform_point(xf_b, b.vertices[incident]), transform_point(xf_b, b.vertices[next])};
    const int32_t vertex_of[2] = {incident, next};
    const Vec2 edge = s.point2 - s.point1;
    const float length_sq = dot(edge, edge);
    float along[2] = {dot(ends[0] - s.point1, edge) / length_sq, dot(ends[1] - s.point1, edge) / length_sq};
    Manifold m;
    m.normal = n;
    if ((along[0] < 0.0f && along[1] < 0.0f) || (along[0] > 1.0f && along[1] > 1.0f)) {
        return m;
    }
    // Clip the incident edge to the segment's extent [0, 1].
    for (int32_t k = 0; k < 2; ++k) {
        const float bound = along[k] < 0.0f ? 0.0f : (along[k] > 1.0f ? 1.0f : along[k]);
        if (bound != along[k]) {
            const float t = (bound - along[k]) / (along[1 - k] - along[k]);
            ends[k] = lerp(ends[k], ends[1 - k], t);
            along[k] = bound;
        }
    }
    for (int32_t k = 0; k < 2; ++k) {
        const float separation = dot(ends[k] - s.point1, n) - b.radius;
        if (separation > speculative) {
            continue;
        }
        ManifoldPoint& p = m.points[m.point_count++];
        p.point = ends[k] - (b.radius + 0.5f * separation) * n;
        p.penetration = -separation;
        p.id = make_feature_id(0, vertex_of[k]);
    }
    return m;
}

// A circle held by the segment: the point of it deepest below the face, while its centre
// lies within the segment's extent (beyond it the neighbouring segment holds it).
Manifold held_circle_contact(const WorldChainSegment& s, Vec2 centre, float radius) {
    const Vec2 edge = s.point2 - s.point1;
    const float along = dot(centre - s.point1, edge) / dot(edge, edge);
    if (!(along >= 0.0f && along <= 1.0f)) {
        return {};
    }
    const float separation = dot(centre - s.point1, s.normal) - radius;
    Manifold m;
    m.normal = s.normal;
    m.point_count = 1;
    m.points[0].point = centre - (radius + 0.5f * separation) * s.normal;
    m.points[0].penetration = -separation;
    m.points[0].id = make_feature_id(0, 0);
    return m;
}

}  // namespace

Manifold collide_chain_segment_circle(const ChainSegment& a, const Transform& xf_a, const Circle& b,
                                      const Transform& xf_b, float speculative, bool held) {
    const WorldChainSegment s = to_world(a, xf_a);
    const Vec2 centre = transform_point(xf_b, b.center);
    if (behind(s, centre)) {
        return held ? held_circle_contact(s, centre, b.radius) : Manifold{};
    }
    const Manifold m = collide_segment_circle(Segment{a.point1, a.point2}, xf_a, b, xf_b, speculative);
    return m.point_count == 0 || admissible(s, m.normal) ? m : Manifold{};
}

Manifold collide_chain_segment_polygon(const ChainSegment& a, const Transform& xf_a, const Polygon& b,
                                       const Transform& xf_b, float speculative, bool held, float slop) {
    const WorldChainSegment s = to_world(a, xf_a);
    if (behind(s, transform_point(xf_b, b.centroid))) {
        return held ? face_contact(s, b, xf_b, speculative) : Manifold{};
    }
    const Manifold m = collide_segment_polygon(Segment{a.point1, a.point2}, xf_a, b, xf_b, speculative, slop);
    return m.point_count == 0 || admissible(s, m.normal) ? m : face_contact(s, b, xf_b, speculative);
}

Manifold collide_chain_segment_capsule(const ChainSegment& a, const Transform& xf_a, const Capsule& b,
                                       const Transform& xf_b, float speculative, bool held, float slop) {
    return collide_chain_segment_polygon(a, xf_a, make_capsule_polygon(b.center1, b.center2, b.radius), xf_b,
                                         speculative, held, slop);
}

Manifold collide_held_by_chain(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b,
                               float speculative, float slop) {
    const bool chain_first = a.type == ShapeType::chain_segment;
    const Geometry& chain = chain_first ? a : b;
    const Geometry& other = chain_first ? b : a;
    const Transform& xf_chain = chain_first ? xf_a : xf_b;
    const Transform& xf_other = chain_first ? xf_b : xf_a;
    Manifold m;
    switch (other.type) {
        case ShapeType::circle:
            m = collide_chain_segment_circle(chain.chain_segment, xf_chain, other.circle, xf_other, speculative, true);
            break;
        case ShapeType::capsule:
            m = collide_chain_segment_capsule(chain.chain_segment, xf_chain, other.capsule, xf_other, speculative,
                                              true, slop);
            break;
        case ShapeType::polygon:
            m = collide_chain_segment_polygon(chain.chain_segment, xf_chain, other.polygon, xf_other, speculative,
                                              true, slop);
            break;
        default: return {};  // segments and chains never collide
    }
    if (!chain_first) {
        m.normal = -m.normal;
    }
    return m;
}

}  // namespace i2d
