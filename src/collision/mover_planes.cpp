// SPDX-License-Identifier: MIT
// The plane solver and the velocity clipper of the character mover (mover_planes.hpp).
#include "collision/mover_planes.hpp"

#include <cmath>

#include "math/math.hpp"

namespace i2d {

namespace {

/// A vector runs into a clipping plane when its part along the normal is below minus
/// this times its length: rounding of a projection (about 1e-7 relative) is not running in.
constexpr float clip_relative_tolerance = 1.0e-5f;

bool runs_into_none(Vec2 v, const CollisionPlane* planes, int32_t count, float tolerance) {
    for (int32_t i = 0; i < count; ++i) {
        if (planes[i].clip_velocity && dot(v, planes[i].plane.normal) < -tolerance) {
            return false;
        }
    }
    return true;
}

}  // namespace

// Each plane's constraint is offset + dot(n, d) >= 0; its push p (accumulated) moves d by
// p n. One sweep visits the planes in order and sets each push to what makes its own
// constraint hold exactly, clamped to [0, push_limit]: a push that is no longer needed
// is taken back, never below zero.
PlaneSolution solve_planes(Vec2 target_delta, CollisionPlane* planes, int32_t count) {
    PlaneSolution out;
    out.translation = target_delta;
    for (int32_t i = 0; i < count; ++i) {
        planes[i].push = 0.0f;
    }
    if (count <= 0) {
        return out;
    }
    Vec2 delta = target_delta;
    for (int32_t sweep = 1; sweep <= max_plane_sweeps; ++sweep) {
        float changed = 0.0f;
        for (int32_t i = 0; i < count; ++i) {
            CollisionPlane& p = planes[i];
            const float separation = p.plane.offset + dot(p.plane.normal, delta);
            const float total = clamp(p.push - separation, 0.0f, p.push_limit);
            const float change = total - p.push;
            p.push = total;
            delta += change * p.plane.normal;
            changed += std::fabs(change);
        }
        out.iteration_count = sweep;
        if (changed < plane_solve_tolerance) {
            break;
        }
    }
    out.translation = delta;
    return out;
}

// The cone C of directions that run into no clipping plane is closed and convex, so v has
// one nearest point in it. When v is outside, that point lies on the line of a plane v
// runs into (v less its part along that normal) or is zero: every candidate that runs
// into no plane is in C, and the nearest of them is the projection. Candidates are tried
// only for the planes v runs into, each checked against all planes.
Vec2 clip_vector(Vec2 vector, const CollisionPlane* planes, int32_t count) {
    const float tolerance = clip_relative_tolerance * length(vector);
    if (runs_into_none(vector, planes, count, tolerance)) {
        return vector;
    }
    Vec2 best;  // zero: always in C
    float best_distance = length(vector);
    for (int32_t i = 0; i < count; ++i) {
        if (!planes[i].clip_velocity) {
            continue;
        }
        const float into = dot(vector, planes[i].plane.normal);
        if (!(into < -tolerance) || -into >= best_distance) {
            continue;
        }
        const Vec2 candidate = vector - into * planes[i].plane.normal;
        if (runs_into_none(candidate, planes, count, tolerance)) {
            best = candidate;
            best_distance = -into;
        }
    }
    return best;
}

}  // namespace i2d
