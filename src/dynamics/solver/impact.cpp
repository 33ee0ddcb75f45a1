// SPDX-License-Identifier: MIT
// resolve_impact: the rigid contact impulse of one impact, by sequential impulses.
#include "dynamics/solver/impact.hpp"

#include "dynamics/constants.hpp"
#include "dynamics/solver/effective_mass.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

Vec2 point_velocity(const ImpactBody& body, Vec2 r) { return body.linear_velocity + cross(body.angular_velocity, r); }

// A takes -P at r_a, B takes +P at r_b.
void apply_impulse(ImpactBody& a, ImpactBody& b, Vec2 r_a, Vec2 r_b, Vec2 impulse) {
    a.linear_velocity -= a.inv_mass * impulse;
    a.angular_velocity -= a.inv_inertia * cross(r_a, impulse);
    b.linear_velocity += b.inv_mass * impulse;
    b.angular_velocity += b.inv_inertia * cross(r_b, impulse);
}

struct ImpactPoint {
    Vec2 r_a, r_b;
    float normal_mass = 0.0f, tangent_mass = 0.0f;
    float target_speed = 0.0f;  // the normal speed the impulse aims at, m/s
    float normal_impulse = 0.0f, tangent_impulse = 0.0f;
};

// The normal impulses of two points as one 2x2 linear complementarity problem, as the
// contact kernels solve it (solve_normal_block): totals x >= 0 with the points' normal
// speeds w = K (x - x_old) + v >= target and (w - target) x = 0, trying both, the first
// only, the second only, neither. False (nothing applied) when K is ill conditioned or
// no case fits; the caller then goes point by point.
bool solve_normal_pair(ImpactPoint (&points)[2], Vec2 normal, ImpactBody& a, ImpactBody& b) {
    constexpr float max_condition = 1000.0f;
    ImpactPoint& p1 = points[0];
    ImpactPoint& p2 = points[1];
    const float rn1a = cross(p1.r_a, normal), rn1b = cross(p1.r_b, normal);
    const float rn2a = cross(p2.r_a, normal), rn2b = cross(p2.r_b, normal);
    const float m = a.inv_mass + b.inv_mass;
    const float k11 = m + a.inv_inertia * rn1a * rn1a + b.inv_inertia * rn1b * rn1b;
    const float k22 = m + a.inv_inertia * rn2a * rn2a + b.inv_inertia * rn2b * rn2b;
    const float k12 = m + a.inv_inertia * rn1a * rn2a + b.inv_inertia * rn1b * rn2b;
    const float det = k11 * k22 - k12 * k12;
    if (!(k11 * k11 < max_condition * det)) {
        return false;
    }
    // What the points' speeds less their targets would be without any normal impulse.
    const float q1 = dot(point_velocity(b, p1.r_b) - point_velocity(a, p1.r_a), normal) - p1.target_speed -
                     (k11 * p1.normal_impulse + k12 * p2.normal_impulse);
    const float q2 = dot(point_velocity(b, p2.r_b) - point_velocity(a, p2.r_a), normal) - p2.target_speed -
                     (k12 * p1.normal_impulse + k22 * p2.normal_impulse);
    float x1 = 0.0f, x2 = 0.0f;
    const float both1 = -(k22 * q1 - k12 * q2) / det, both2 = -(k11 * q2 - k12 * q1) / det;
    const float first = -q1 / k11, second = -q2 / k22;
    if (both1 >= 0.0f && both2 >= 0.0f) {
        x1 = both1, x2 = both2;
    } else if (first >= 0.0f && k12 * first + q2 >= 0.0f) {
        x1 = first;
    } else if (second >= 0.0f && k12 * second + q1 >= 0.0f) {
        x2 = second;
    } else if (!(q1 >= 0.0f && q2 >= 0.0f)) {
        return false;
    }
    apply_impulse(a, b, p1.r_a, p1.r_b, (x1 - p1.normal_impulse) * normal);
    apply_impulse(a, b, p2.r_a, p2.r_b, (x2 - p2.normal_impulse) * normal);
    p1.normal_impulse = x1;
    p2.normal_impulse = x2;
    return true;
}

void solve_normal_point(ImpactPoint& p, Vec2 normal, ImpactBody& a, ImpactBody& b) {
    const float vn = dot(point_velocity(b, p.r_b) - point_velocity(a, p.r_a), normal);
    const float total = max_of(p.normal_impulse - p.normal_mass * (vn - p.target_speed), 0.0f);
    apply_impulse(a, b, p.r_a, p.r_b, (total - p.normal_impulse) * normal);
    p.normal_impulse = total;
}

}  // namespace

// Box2D's contact solve without softness or bias (contact_solver.hpp): the normal
// impulses, clamped to push only, towards the target speeds (two points together, as the
// contact kernels do, so that a box landing flat stays flat), then friction per point
// clamped to the Coulomb cone; a few sweeps, for a corner whose friction turns the body
// and so changes its normal speed. The target is what the restitution pass aims at:
// -e v_approach for an approach faster than the threshold, else no approach.
ImpactResult resolve_impact(const Manifold& manifold, float touching, const ImpactMaterial& material, ImpactBody& a,
                            ImpactBody& b) {
    const Vec2 normal = manifold.normal;
    const Vec2 tangent = left_perp(normal);
    ImpactPoint points[2];
    int32_t count = 0;
    ImpactResult result;
    for (int32_t i = 0; i < manifold.point_count; ++i) {
        const ManifoldPoint& mp = manifold.points[i];
        if (-mp.penetration > touching) {
            continue;  // a speculative point: the next step's contact has it
        }
        ImpactPoint& p = points[count++];
        p.r_a = mp.point - a.center;
        p.r_b = mp.point - b.center;
        p.normal_mass = effective_mass(a, b, p.r_a, p.r_b, normal);
        p.tangent_mass = effective_mass(a, b, p.r_a, p.r_b, tangent);
        const float approach = -dot(point_velocity(b, p.r_b) - point_velocity(a, p.r_a), normal);
        p.target_speed = approach > material.restitution_threshold ? material.restitution * approach : 0.0f;
        if (approach > result.approach_speed) {
            result.approach_speed = approach;
            result.point_index = i;
        }
    }
    if (result.point_index < 0) {
        return result;  // nothing touching approaches
    }
    for (int32_t iteration = 0; iteration < impact_iterations; ++iteration) {
        if (count < 2 || !solve_normal_pair(points, normal, a, b)) {
            for (int32_t i = 0; i < count; ++i) {
                solve_normal_point(points[i], normal, a, b);
            }
        }
        for (int32_t i = 0; i < count; ++i) {
            ImpactPoint& p = points[i];
            const float vt = dot(point_velocity(b, p.r_b) - point_velocity(a, p.r_a), tangent) - material.tangent_speed;
            const float limit = material.friction * p.normal_impulse;
            const float total = clamp(p.tangent_impulse - p.tangent_mass * vt, -limit, limit);
            apply_impulse(a, b, p.r_a, p.r_b, (total - p.tangent_impulse) * tangent);
            p.tangent_impulse = total;
        }
    }
    return result;
}

}  // namespace i2d
