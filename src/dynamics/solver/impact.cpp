// SPDX-License-Identifier: MIT
// resolve_impact, resolve_impacts: the rigid contact impulses of one impact, or of several at
// once, by sequential impulses.
#include "dynamics/solver/impact.hpp"

#include <limits>

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

// The point's normal impulse and its target, from the approach where it is now: -e times
// an approach faster than the threshold, else no approach.
ImpactPoint make_point(Vec2 point, const ImpactBody& a, const ImpactBody& b, Vec2 normal,
                       const ImpactMaterial& material, float& approach) {
    ImpactPoint p;
    p.r_a = point - a.center;
    p.r_b = point - b.center;
    p.normal_mass = effective_mass(a, b, p.r_a, p.r_b, normal);
    p.tangent_mass = effective_mass(a, b, p.r_a, p.r_b, left_perp(normal));
    approach = -dot(point_velocity(b, p.r_b) - point_velocity(a, p.r_a), normal);
    p.target_speed = approach > material.restitution_threshold ? material.restitution * approach : 0.0f;
    return p;
}

// One sweep over a contact's points: the normal impulses (two points as one block where
// it is well conditioned), then Coulomb friction per point.
void sweep_contact(ImpactPoint (&points)[2], int32_t count, Vec2 normal, const ImpactMaterial& material,
                   ImpactBody& a, ImpactBody& b) {
    const Vec2 tangent = left_perp(normal);
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

// A contact's points that take part (separation at most `touching`), and the fastest
// approach among them.
int32_t gather_points(const Manifold& manifold, float touching, const ImpactMaterial& material, const ImpactBody& a,
                      const ImpactBody& b, ImpactPoint (&points)[2], ImpactResult& result) {
    int32_t count = 0;
    for (int32_t i = 0; i < manifold.point_count; ++i) {
        const ManifoldPoint& mp = manifold.points[i];
        if (-mp.penetration > touching) {
            continue;  // a speculative point: the next step's contact has it
        }
        float approach = 0.0f;
        points[count++] = make_point(mp.point, a, b, manifold.normal, material, approach);
        if (approach > result.approach_speed) {
            result.approach_speed = approach;
            result.point_index = i;
        }
    }
    return count;
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
    ImpactPoint points[2];
    ImpactResult result;
    const int32_t count = gather_points(manifold, touching, material, a, b, points, result);
    if (result.point_index < 0) {
        return result;  // nothing touching approaches
    }
    for (int32_t iteration = 0; iteration < impact_iterations; ++iteration) {
        sweep_contact(points, count, manifold.normal, material, a, b);
    }
    return result;
}

// The same sweeps over every contact in turn, until the contacts that share a body agree:
// each sweep passes on what the others left, so a ball struck by two at once takes both
// impulses together, as the simultaneous solution has them (two balls meeting the apex of
// a rack at the same time leave it mirror images of each other).
void resolve_impacts(const ImpactContact* contacts, int32_t count, ImpactBody* bodies, ImpactResult* results) {
    constexpr int32_t most_contacts = max_simultaneous_impacts;
    ImpactPoint points[most_contacts][2];
    int32_t point_counts[most_contacts];
    for (int32_t k = 0; k < count; ++k) {
        const ImpactContact& c = contacts[k];
        results[k] = ImpactResult{};
        point_counts[k] = gather_points(c.manifold, std::numeric_limits<float>::max(), c.material,
                                        bodies[c.body_a], bodies[c.body_b], points[k], results[k]);
    }
    const int32_t iterations = count == 1 ? impact_iterations : simultaneous_impact_iterations;
    for (int32_t iteration = 0; iteration < iterations; ++iteration) {
        for (int32_t k = 0; k < count; ++k) {
            const ImpactContact& c = contacts[k];
            if (results[k].point_index >= 0) {
                sweep_contact(points[k], point_counts[k], c.manifold.normal, c.material, bodies[c.body_a],
                              bodies[c.body_b]);
            }
        }
    }
}

}  // namespace i2d
