// SPDX-License-Identifier: MIT
// Conservative advancement on the exact core distance (see toi.hpp).
#include "collision/toi.hpp"

#include <cmath>

#include "collision/collision_constants.hpp"
#include "collision/overlap_exit.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

/// Most distance evaluations per time of impact. Each one is safe, so running out
/// returns a time before the impact: a spinning body may stop a little early, never late.
constexpr int32_t max_toi_iterations = 64;

// Farthest core point from the centre of mass: how fast a turn can move the core.
float core_extent(const ShapeProxy& p, Vec2 local_center) {
    float extent_sq = 0.0f;
    for (int32_t i = 0; i < p.count; ++i) {
        extent_sq = max_of(extent_sq, distance_squared(p.points[i], local_center));
    }
    return std::sqrt(extent_sq);
}

/// Turns this close to half a revolution leave the interpolated rotation's speed
/// unbounded; the bound stops growing there (rad). Steps turn less than this unless
/// they take several quarter turns in a row.
constexpr float max_bounded_turn = 3.1f;

// The fastest the sweep's rotation turns, rad per unit of t. The rotation is a normalised
// linear interpolation: for a whole turn phi it turns fastest half way, at
// 2 tan(phi / 2) (not phi: a bound of phi would step past impacts of fast spinners).
float sweep_turn_rate(const Sweep& s) {
    const float phi = min_of(std::fabs(get_angle(inv_mul_rot(s.q1, s.q2))), max_bounded_turn);
    const float half = 0.5f * phi;
    return 2.0f * std::sin(half) / std::cos(half);
}

}  // namespace

Sweep still_sweep(const Transform& xf, Vec2 local_center) {
    const Vec2 c = transform_point(xf, local_center);
    return Sweep{local_center, c, c, xf.q, xf.q};
}

Transform sweep_transform(const Sweep& s, float t) {
    Transform xf;
    const Vec2 c = lerp(s.c1, s.c2, t);
    xf.q = normalize(Rot{s.q1.c + t * (s.q2.c - s.q1.c), s.q1.s + t * (s.q2.s - s.q1.s)});
    xf.p = c - rotate(xf.q, s.local_center);
    return xf;
}

ToiResult time_of_impact(const ShapeProxy& a, const Sweep& sweep_a, const ShapeProxy& b, const Sweep& sweep_b,
                         float max_fraction, float target, float tolerance) {
    const float spin_bound = sweep_turn_rate(sweep_a) * core_extent(a, sweep_a.local_center) +
                             sweep_turn_rate(sweep_b) * core_extent(b, sweep_b.local_center);
    const Vec2 relative_travel = (sweep_b.c2 - sweep_b.c1) - (sweep_a.c2 - sweep_a.c1);
    ToiResult result;
    float t = 0.0f;
    for (int32_t iteration = 0; iteration < max_toi_iterations; ++iteration) {
        const ProxyDistance d =
            core_distance(transformed(a, sweep_transform(sweep_a, t)), transformed(b, sweep_transform(sweep_b, t)));
        result.normal = d.normal;
        result.point_a = d.point_a;
        result.point_b = d.point_b;
        result.fraction = t;
        if (d.distance < target + tolerance) {
            result.state = t == 0.0f ? ToiState::overlapped : ToiState::hit;
            return result;
        }
        const float approach = spin_bound - dot(relative_travel, d.normal);
        // Receding along the closest points' normal and not turning: never closer.
        const float next = approach > 0.0f ? t + (d.distance - target) / approach : max_fraction;
        if (!(next < max_fraction)) {
            result.state = ToiState::separated;
            result.fraction = max_fraction;
            return result;
        }
        t = next;
    }
    // Out of iterations: every advance so far was safe, so t is not past the impact.
    result.state = ToiState::hit;
    result.fraction = t;
    return result;
}

CastHit shape_cast(const ShapeProxy& shape, const Transform& xf, const ShapeProxy& moving, Vec2 translation,
                   float max_fraction, float slop) {
    const ShapeProxy placed = transformed(shape, xf);
    const Sweep fixed{Vec2{}, Vec2{}, Vec2{}, Rot{}, Rot{}};
    const Sweep moved{Vec2{}, Vec2{}, translation, Rot{}, Rot{}};
    const float target = placed.radius + moving.radius;
    const ToiResult r = time_of_impact(placed, fixed, moving, moved, max_fraction, target, 0.25f * slop);
    CastHit hit;
    if (r.state == ToiState::separated) {
        return hit;
    }
    hit.hit = true;
    hit.fraction = r.fraction;
    if (r.state == ToiState::overlapped) {
        // Inside at the start: the closest points say nothing of overlapping cores, nor
        // does the translation (it may be 1e-30 m). The overlap itself gives the normal,
        // the way the proxy leaves the shape soonest, and a point inside both.
        const OverlapExit exit = overlap_exit(placed, moving, -translation);
        hit.normal = exit.normal;
        hit.point = exit.point;
        return hit;
    }
    const float gap = length(r.point_b - r.point_a);
    // Touching after the start: conservative advancement stops with the cores apart, so
    // their closest points give the normal (the translation only if the gap rounded to 0).
    hit.normal = gap > 0.0f ? r.normal : -normalize(translation);
    hit.point = r.point_a + placed.radius * hit.normal;
    return hit;
}

}  // namespace i2d
