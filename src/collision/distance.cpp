// SPDX-License-Identifier: MIT
// Segment-segment closest points (Ericson, Real-Time Collision Detection, 5.1.9) and a
// brute-force convex distance for the exact overlap tests.
#include "collision/distance.hpp"
#include "math/math.hpp"

#include <cfloat>
#include <cmath>


namespace i2d {

// Closest points of two segments. Ericson 5.1.9 minimises |p1 + s d1 - (p2 + t d2)|^2
// over the unit square by solving for s and clamping; for nearly parallel segments its
// denominator cancels and s loses most of its digits. Here the minimum is found by
// cases instead: a convex quadratic on the square has its minimum either inside (the
// segments cross: Ericson's unclamped solution, used only when it lies inside) or on an
// edge of the square, i.e. at an endpoint of one segment against the other segment.
// Endpoint fractions are exactly 0 or 1, which the polygon code relies on.
SegmentDistance segment_distance(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2) {
    const Vec2 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const float dd1 = dot(d1, d1), dd2 = dot(d2, d2);
    auto fraction = [](Vec2 point, Vec2 start, Vec2 dir, float dd) {
        return dd > 0.0f ? clamp(dot(point - start, dir) / dd, 0.0f, 1.0f) : 0.0f;
    };
    SegmentDistance candidates[5];
    int32_t count = 0;
    auto consider = [&](float s, float t) {
        const Vec2 c1 = p1 + s * d1, c2 = p2 + t * d2;
        candidates[count++] = {c1, c2, s, t, distance_squared(c1, c2)};
    };
    consider(0.0f, fraction(p1, p2, d2, dd2));
    consider(1.0f, fraction(q1, p2, d2, dd2));
    consider(fraction(p2, p1, d1, dd1), 0.0f);
    consider(fraction(q2, p1, d1, dd1), 1.0f);
    const float d12 = dot(d1, d2);
    const float denom = dd1 * dd2 - d12 * d12;
    if (denom > FLT_EPSILON * dd1 * dd2) {
        const float rd1 = dot(r, d1), rd2 = dot(r, d2);
        const float s = (d12 * rd2 - rd1 * dd2) / denom;
        const float t = (dd1 * rd2 - d12 * rd1) / denom;
        if (s > 0.0f && s < 1.0f && t > 0.0f && t < 1.0f) {
            consider(s, t);
        }
    }
    int32_t best = 0;
    for (int32_t i = 1; i < count; ++i) {
        if (candidates[i].distance_squared < candidates[best].distance_squared) {
            best = i;
        }
    }
    // Parallel overlapping segments tie between vertex-vertex and vertex-edge pairs; the
    // vertex-edge one describes the contact (an edge lies along the other), so prefer it.
    auto at_vertex = [](float f) { return f == 0.0f || f == 1.0f; };
    const float tie = candidates[best].distance_squared * (1.0f + 1e-5f) + FLT_MIN;
    if (at_vertex(candidates[best].fraction1) && at_vertex(candidates[best].fraction2)) {
        for (int32_t i = 0; i < count; ++i) {
            if (candidates[i].distance_squared <= tie &&
                !(at_vertex(candidates[i].fraction1) && at_vertex(candidates[i].fraction2))) {
                best = i;
                break;
            }
        }
    }
    return candidates[best];
}

Vec2 closest_point_on_segment(Vec2 a, Vec2 b, Vec2 p) {
    const Vec2 e = b - a;
    const float ee = dot(e, e);
    if (ee <= 0.0f) {
        return a;
    }
    return a + clamp(dot(p - a, e) / ee, 0.0f, 1.0f) * e;
}

namespace {

// True if some edge normal of `a` separates the two sets (closed: touching is not separated).
bool has_separating_edge(const Vec2* a, int32_t na, const Vec2* b, int32_t nb) {
    const int32_t edges = na >= 3 ? na : (na == 2 ? 2 : 0);
    for (int32_t i = 0; i < edges; ++i) {
        const Vec2 v = a[i];
        const Vec2 normal = right_perp(a[i + 1 == na ? 0 : i + 1] - v);
        float lowest = FLT_MAX;
        for (int32_t j = 0; j < nb; ++j) {
            lowest = min_of(lowest, dot(normal, b[j] - v));
        }
        // A 2-point set has both sides as faces; its reversed edge covers the other side.
        if (lowest > 0.0f) {
            return true;
        }
    }
    return false;
}

float vertex_edge_distance_sq(const Vec2* a, int32_t na, const Vec2* b, int32_t nb) {
    float best = FLT_MAX;
    for (int32_t i = 0; i < na; ++i) {
        if (nb == 1) {
            best = min_of(best, distance_squared(a[i], b[0]));
            continue;
        }
        for (int32_t j = 0; j < nb; ++j) {
            const Vec2 q = closest_point_on_segment(b[j], b[j + 1 == nb ? 0 : j + 1], a[i]);
            best = min_of(best, distance_squared(a[i], q));
        }
    }
    return best;
}

}  // namespace

// Two convex sets in the plane intersect unless an edge normal of one of them separates
// them (the separating axis theorem; for a segment its normal is its only face). When
// they are apart, the closest pair always involves a vertex of one and an edge (or
// vertex) of the other, so checking all such pairs gives the exact distance.
float convex_distance(const Vec2* a, int32_t count_a, const Vec2* b, int32_t count_b) {
    if (count_a <= 2 && count_b <= 2) {
        // Points and segments have no faces along their own direction: measure directly.
        const SegmentDistance sd = segment_distance(a[0], a[count_a - 1], b[0], b[count_b - 1]);
        return std::sqrt(sd.distance_squared);
    }
    if (!has_separating_edge(a, count_a, b, count_b) && !has_separating_edge(b, count_b, a, count_a)) {
        return 0.0f;
    }
    const float d = min_of(vertex_edge_distance_sq(a, count_a, b, count_b),
                              vertex_edge_distance_sq(b, count_b, a, count_a));
    return std::sqrt(d);
}

}  // namespace i2d
