// SPDX-License-Identifier: MIT
// The soft step's contact passes: prepare, warm start, solve (biased or relaxing),
// restitution.
#include "dynamics/contact_solver.hpp"

#include <cmath>

#include "math/math.hpp"

namespace i2d {

namespace {

// 1 / (invMassA + invMassB + (rA x d)^2 invIA + (rB x d)^2 invIB), or 0 when nothing moves.
float effective_mass(const ContactConstraint& c, Vec2 r_a, Vec2 r_b, Vec2 direction) {
    const float ra = cross(r_a, direction), rb = cross(r_b, direction);
    const float k = c.inv_mass_a + c.inv_mass_b + c.inv_inertia_a * ra * ra + c.inv_inertia_b * rb * rb;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

Vec2 relative_velocity(const BodyState& a, const BodyState& b, Vec2 r_a, Vec2 r_b) {
    return (b.linear_velocity + cross(b.angular_velocity, r_b)) - (a.linear_velocity + cross(a.angular_velocity, r_a));
}

void apply_impulse(const ContactConstraint& c, const ContactConstraintPoint& p, Vec2 impulse, BodyState& a,
                   BodyState& b) {
    a.linear_velocity -= c.inv_mass_a * impulse;
    a.angular_velocity -= c.inv_inertia_a * cross(p.anchor_a, impulse);
    b.linear_velocity += c.inv_mass_b * impulse;
    b.angular_velocity += c.inv_inertia_b * cross(p.anchor_b, impulse);
}

void apply_angular_impulse(const ContactConstraint& c, float impulse, BodyState& a, BodyState& b) {
    a.angular_velocity -= c.inv_inertia_a * impulse;
    b.angular_velocity += c.inv_inertia_b * impulse;
}

}  // namespace

void prepare_contacts(std::vector<ContactConstraint>& constraints, const std::vector<BodyState>& states) {
    for (ContactConstraint& c : constraints) {
        const BodyState& a = states[c.state_a];
        const BodyState& b = states[c.state_b];
        const Vec2 tangent = left_perp(c.normal);
        for (int32_t i = 0; i < c.point_count; ++i) {
            ContactConstraintPoint& p = c.points[i];
            p.normal_mass = effective_mass(c, p.anchor_a, p.anchor_b, c.normal);
            p.tangent_mass = effective_mass(c, p.anchor_a, p.anchor_b, tangent);
            p.relative_velocity = dot(relative_velocity(a, b, p.anchor_a, p.anchor_b), c.normal);
            p.start_speed = p.relative_velocity;
            p.max_normal_impulse = 0.0f;
        }
        const float k = c.inv_inertia_a + c.inv_inertia_b;
        c.rolling_mass = k > 0.0f ? 1.0f / k : 0.0f;
    }
}

void warm_start_contacts(const std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states) {
    for (const ContactConstraint& c : constraints) {
        BodyState& a = states[c.state_a];
        BodyState& b = states[c.state_b];
        const Vec2 tangent = left_perp(c.normal);
        for (int32_t i = 0; i < c.point_count; ++i) {
            const ContactConstraintPoint& p = c.points[i];
            apply_impulse(c, p, p.normal_impulse * c.normal + p.tangent_impulse * tangent, a, b);
        }
        apply_angular_impulse(c, c.rolling_impulse, a, b);
    }
}

namespace {

// Separation of a point now: as prepared, plus how far its two anchors moved apart
// along the normal since (anchors ride their bodies' motion and turn).
float current_separation(const ContactConstraintPoint& p, Vec2 normal, const BodyState& a, const BodyState& b) {
    const Vec2 moved = (b.delta_position - a.delta_position) +
                       (rotate(b.delta_rotation, p.anchor_b) - rotate(a.delta_rotation, p.anchor_a));
    return dot(moved, normal) + p.base_separation;
}

// How one point is solved this pass: impulse = -mass (mass_scale vn + bias) - impulse_scale x.
struct PointTerms {
    float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
};

// A gap allows approach up to closing it within the substep (speculative); overlap is
// pushed out softly, at most push_max_speed. Soft everywhere, so that the spring's
// damping also calms resting stacks: a loaded contact settles at the small overlap
// where push-out balances the load (load / (effective mass x omega^2)).
PointTerms point_terms(const ContactConstraint& c, float separation, float inv_h, const ContactSolverSettings& s,
                       bool use_bias) {
    if (separation > 0.0f) {
        return {separation * inv_h, 1.0f, 0.0f};
    }
    if (use_bias) {
        const Softness& soft = c.softness;
        return {max_of(soft.mass_scale * soft.bias_rate * separation, -s.push_max_speed), soft.mass_scale,
                soft.impulse_scale};
    }
    return {};
}

// Until a point first pushes, the impact speed of a pair that was approaching when the
// step began is tracked from its free motion: the start speed plus gravity and forces
// so far, carried over the remaining gap (v^2 + 2 a gap, what energy says). A bounce
// then keeps its energy instead of losing up to a substep's worth of fall. Speed that
// other contacts gave the pair within the step does not count, nor does a pair at rest
// that another contact sets moving bounce: simultaneous impacts have no defined
// outcome, and bouncing them would create energy.
void track_impact(const ContactConstraint& c, ContactConstraintPoint& p, float separation, float elapsed) {
    if (p.start_speed >= 0.0f || p.max_normal_impulse != 0.0f) {
        return;
    }
    const float free_speed = p.start_speed - c.approach_acceleration * elapsed;
    p.relative_velocity = -std::sqrt(free_speed * free_speed + 2.0f * c.approach_acceleration * max_of(separation, 0.0f));
}

void set_normal_impulse(ContactConstraint& c, ContactConstraintPoint& p, float impulse, BodyState& a, BodyState& b) {
    p.max_normal_impulse = max_of(p.max_normal_impulse, impulse - p.normal_impulse);
    apply_impulse(c, p, (impulse - p.normal_impulse) * c.normal, a, b);
    p.normal_impulse = impulse;
}

void solve_normal_point(ContactConstraint& c, ContactConstraintPoint& p, const PointTerms& t, BodyState& a,
                        BodyState& b) {
    const float vn = dot(relative_velocity(a, b, p.anchor_a, p.anchor_b), c.normal);
    const float impulse = -p.normal_mass * (t.mass_scale * vn + t.bias) - t.impulse_scale * p.normal_impulse;
    set_normal_impulse(c, p, max_of(p.normal_impulse + impulse, 0.0f), a, b);
}

// Both points of a two-point manifold at once, as a 2x2 linear complementarity problem
// (Box2D 2.4's block solver, after Catto's GDC talks, extended to soft terms): find
// accumulated impulses x >= 0 with w = K (x - (1 - impulse_scale) x_old) + mass_scale vn
// + bias >= 0 and x_i w_i = 0, trying the four cases (both push, one, neither). For one
// point this is exactly the single-point rule. Solving the points one after the other
// instead lets the first take more than its share, which turns a resting box and makes
// tall stacks lean. Returns false when K is too ill-conditioned (points nearly
// coincident) or no case fits (round-off at the boundaries): then one by one.
bool solve_normal_block(ContactConstraint& c, const PointTerms t[2], BodyState& a, BodyState& b) {
    ContactConstraintPoint& p1 = c.points[0];
    ContactConstraintPoint& p2 = c.points[1];
    const Vec2 n = c.normal;
    const float rn1a = cross(p1.anchor_a, n), rn1b = cross(p1.anchor_b, n);
    const float rn2a = cross(p2.anchor_a, n), rn2b = cross(p2.anchor_b, n);
    const float m = c.inv_mass_a + c.inv_mass_b;
    const float k11 = m + c.inv_inertia_a * rn1a * rn1a + c.inv_inertia_b * rn1b * rn1b;
    const float k22 = m + c.inv_inertia_a * rn2a * rn2a + c.inv_inertia_b * rn2b * rn2b;
    const float k12 = m + c.inv_inertia_a * rn1a * rn2a + c.inv_inertia_b * rn1b * rn2b;
    const float det = k11 * k22 - k12 * k12;
    constexpr float max_condition = 1000.0f;
    if (!(k11 * k11 < max_condition * det)) {
        return false;
    }
    const float kept1 = (1.0f - t[0].impulse_scale) * p1.normal_impulse;
    const float kept2 = (1.0f - t[1].impulse_scale) * p2.normal_impulse;
    const float vn1 = dot(relative_velocity(a, b, p1.anchor_a, p1.anchor_b), n);
    const float vn2 = dot(relative_velocity(a, b, p2.anchor_a, p2.anchor_b), n);
    const float q1 = t[0].mass_scale * vn1 + t[0].bias - (k11 * kept1 + k12 * kept2);
    const float q2 = t[1].mass_scale * vn2 + t[1].bias - (k12 * kept1 + k22 * kept2);

    float x1 = 0.0f, x2 = 0.0f;
    const float inv_det = 1.0f / det;
    const float both1 = -inv_det * (k22 * q1 - k12 * q2), both2 = -inv_det * (k11 * q2 - k12 * q1);
    if (both1 >= 0.0f && both2 >= 0.0f) {
        x1 = both1, x2 = both2;  // both points push
    } else if (-q1 / k11 >= 0.0f && k12 * (-q1 / k11) + q2 >= 0.0f) {
        x1 = -q1 / k11;  // only the first pushes; the second separates
    } else if (-q2 / k22 >= 0.0f && k12 * (-q2 / k22) + q1 >= 0.0f) {
        x2 = -q2 / k22;  // only the second pushes
    } else if (!(q1 >= 0.0f && q2 >= 0.0f)) {
        return false;
    }
    set_normal_impulse(c, p1, x1, a, b);
    set_normal_impulse(c, p2, x2, a, b);
    return true;
}

// Returns the normal impulses' sum, which bounds the rolling resistance torque.
float solve_normal(ContactConstraint& c, BodyState& a, BodyState& b, float inv_h, const ContactSolverSettings& s,
                   bool use_bias, float elapsed) {
    PointTerms terms[2];
    for (int32_t i = 0; i < c.point_count; ++i) {
        ContactConstraintPoint& p = c.points[i];
        const float separation = current_separation(p, c.normal, a, b);
        terms[i] = point_terms(c, separation, inv_h, s, use_bias);
        if (use_bias) {
            track_impact(c, p, separation, elapsed);
        }
    }
    if (c.point_count != 2 || !solve_normal_block(c, terms, a, b)) {
        for (int32_t i = 0; i < c.point_count; ++i) {
            solve_normal_point(c, c.points[i], terms[i], a, b);
        }
    }
    float total = 0.0f;
    for (int32_t i = 0; i < c.point_count; ++i) {
        total += c.points[i].normal_impulse;
    }
    return total;
}

// Coulomb friction towards the surfaces' relative speed (zero but for conveyor belts).
void solve_friction(ContactConstraint& c, BodyState& a, BodyState& b) {
    const Vec2 tangent = left_perp(c.normal);
    for (int32_t i = 0; i < c.point_count; ++i) {
        ContactConstraintPoint& p = c.points[i];
        const float vt = dot(relative_velocity(a, b, p.anchor_a, p.anchor_b), tangent) - c.tangent_speed;
        const float max_friction = c.friction * p.normal_impulse;
        const float old = p.tangent_impulse;
        p.tangent_impulse = clamp(old - p.tangent_mass * vt, -max_friction, max_friction);
        apply_impulse(c, p, (p.tangent_impulse - old) * tangent, a, b);
    }
}

// A torque opposing the relative spin, bounded by arm x normal impulse.
void solve_rolling(ContactConstraint& c, BodyState& a, BodyState& b, float normal_total) {
    if (c.rolling_resistance == 0.0f) {
        return;
    }
    const float max_torque = c.rolling_resistance * normal_total;
    const float old = c.rolling_impulse;
    const float spin = b.angular_velocity - a.angular_velocity;
    c.rolling_impulse = clamp(old - c.rolling_mass * spin, -max_torque, max_torque);
    apply_angular_impulse(c, c.rolling_impulse - old, a, b);
}

}  // namespace

void solve_contacts(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states, float inv_h,
                    const ContactSolverSettings& settings, bool use_bias, float elapsed) {
    for (ContactConstraint& c : constraints) {
        BodyState& a = states[c.state_a];
        BodyState& b = states[c.state_b];
        const float normal_total = solve_normal(c, a, b, inv_h, settings, use_bias, elapsed);
        solve_friction(c, a, b);
        solve_rolling(c, a, b, normal_total);
    }
}

float separation_of(const ContactConstraint& c, const ContactConstraintPoint& p, const std::vector<BodyState>& states) {
    return current_separation(p, c.normal, states[c.state_a], states[c.state_b]);
}

namespace {

// Slow impacts do not bounce (resting contacts would never settle), nor do points that
// never pushed (a speculative gap that did not close).
bool bounces(const ContactConstraint& c, const ContactConstraintPoint& p, float threshold) {
    return c.restitution != 0.0f && p.relative_velocity < -threshold && p.max_normal_impulse != 0.0f;
}

// Bouncing points aim at vn = -e v_impact (bias e v_impact on a rigid point); the other
// points that pushed during the step keep their bodies from moving into each other.
void restitution_pass(ContactConstraint& c, BodyState& a, BodyState& b, float threshold) {
    PointTerms terms[2];
    bool active[2] = {false, false};
    for (int32_t i = 0; i < c.point_count; ++i) {
        const ContactConstraintPoint& p = c.points[i];
        active[i] = p.max_normal_impulse != 0.0f;
        terms[i].bias = bounces(c, p, threshold) ? c.restitution * p.relative_velocity : 0.0f;
    }
    // Both points together, or a face bouncing off a face would start to spin.
    if (c.point_count == 2 && active[0] && active[1] && solve_normal_block(c, terms, a, b)) {
        return;
    }
    for (int32_t i = 0; i < c.point_count; ++i) {
        if (active[i]) {
            solve_normal_point(c, c.points[i], terms[i], a, b);
        }
    }
}

}  // namespace

// Only when something bounces, and then over every contact that pushed, a few times: a
// ball bouncing off a row of touching balls must push the whole row, not bounce as if
// its neighbour were free (that would create energy).
void apply_restitution(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states,
                       const ContactSolverSettings& settings) {
    bool any = false;
    for (const ContactConstraint& c : constraints) {
        for (int32_t i = 0; i < c.point_count; ++i) {
            any = any || bounces(c, c.points[i], settings.restitution_threshold);
        }
    }
    constexpr int32_t restitution_iterations = 4;
    for (int32_t iteration = 0; any && iteration < restitution_iterations; ++iteration) {
        for (ContactConstraint& c : constraints) {
            restitution_pass(c, states[c.state_a], states[c.state_b], settings.restitution_threshold);
        }
    }
}

}  // namespace i2d
