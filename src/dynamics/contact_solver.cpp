// SPDX-License-Identifier: MIT
// Sequential impulses with angular terms, restitution, Coulomb friction, warm starting;
// the seed's positional correction per contact point.
#include "dynamics/contact_solver.hpp"
#include "math/math.hpp"

#include <cmath>


namespace i2d {

void gather_constraints(const Pool<Contact>& contacts, const Pool<Body>& bodies,
                        std::vector<ContactConstraint>& out) {
    out.clear();
    for (int32_t i = 0; i < contacts.capacity(); ++i) {
        if (!contacts.is_live(i)) {
            continue;
        }
        const Contact& contact = contacts[i];
        if ((contact.flags & contact_touching) == 0 || (contact.flags & contact_sensor) != 0) {
            continue;
        }
        ContactConstraint c;
        c.contact = i;
        c.body_a = contact.edges[0].body;
        c.body_b = contact.edges[1].body;
        const Body& a = bodies[c.body_a];
        const Body& b = bodies[c.body_b];
        c.normal = contact.manifold.normal;
        c.friction = contact.friction;
        c.restitution = contact.restitution;
        c.point_count = contact.manifold.point_count;
        for (int32_t p = 0; p < c.point_count; ++p) {
            ContactPointConstraint& cp = c.points[p];
            const Vec2 point = contact.manifold.points[p].point;
            cp.anchor_a = point - a.center;
            cp.anchor_b = point - b.center;
            cp.local_anchor_a = inv_rotate(a.transform.q, cp.anchor_a);
            cp.local_anchor_b = inv_rotate(b.transform.q, cp.anchor_b);
            cp.penetration = contact.manifold.points[p].penetration;
            cp.normal_impulse = contact.impulses[p].normal;
            cp.tangent_impulse = contact.impulses[p].tangent;
        }
        out.push_back(c);
    }
}

void scatter_impulses(const std::vector<ContactConstraint>& constraints, Pool<Contact>& contacts) {
    for (const ContactConstraint& c : constraints) {
        Contact& contact = contacts[c.contact];
        for (int32_t p = 0; p < c.point_count; ++p) {
            contact.impulses[p] = {c.points[p].normal_impulse, c.points[p].tangent_impulse};
        }
    }
}

namespace {

// 1 / (invMassA + invMassB + (rA x d)^2 invIA + (rB x d)^2 invIB), or 0 when nothing moves.
float effective_mass(const ContactConstraint& c, Vec2 r_a, Vec2 r_b, Vec2 direction) {
    const float ra = cross(r_a, direction), rb = cross(r_b, direction);
    const float k = c.inv_mass_a + c.inv_mass_b + c.inv_inertia_a * ra * ra + c.inv_inertia_b * rb * rb;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

Vec2 relative_velocity(const Body& a, const Body& b, Vec2 r_a, Vec2 r_b) {
    return (b.linear_velocity + cross(b.angular_velocity, r_b)) - (a.linear_velocity + cross(a.angular_velocity, r_a));
}

void apply_impulse(const ContactConstraint& c, const ContactPointConstraint& p, Vec2 impulse, Body& a, Body& b) {
    a.linear_velocity -= c.inv_mass_a * impulse;
    a.angular_velocity -= c.inv_inertia_a * cross(p.anchor_a, impulse);
    b.linear_velocity += c.inv_mass_b * impulse;
    b.angular_velocity += c.inv_inertia_b * cross(p.anchor_b, impulse);
}

}  // namespace

void prepare_contacts(std::vector<ContactConstraint>& constraints, const Pool<Body>& bodies,
                      const SolverSettings& settings) {
    for (ContactConstraint& c : constraints) {
        const Body& a = bodies[c.body_a];
        const Body& b = bodies[c.body_b];
        c.inv_mass_a = a.inv_mass;
        c.inv_mass_b = b.inv_mass;
        c.inv_inertia_a = a.inv_inertia;
        c.inv_inertia_b = b.inv_inertia;
        const Vec2 tangent = left_perp(c.normal);
        for (int32_t i = 0; i < c.point_count; ++i) {
            ContactPointConstraint& p = c.points[i];
            p.normal_mass = effective_mass(c, p.anchor_a, p.anchor_b, c.normal);
            p.tangent_mass = effective_mass(c, p.anchor_a, p.anchor_b, tangent);
            const float vn = dot(relative_velocity(a, b, p.anchor_a, p.anchor_b), c.normal);
            // Slow impacts do not bounce: resting contacts would otherwise never settle.
            p.target_normal_speed = vn < -settings.restitution_threshold ? -c.restitution * vn : 0.0f;
        }
    }
}

void warm_start_contacts(const std::vector<ContactConstraint>& constraints, Pool<Body>& bodies) {
    for (const ContactConstraint& c : constraints) {
        const Vec2 tangent = left_perp(c.normal);
        Body& a = bodies[c.body_a];
        Body& b = bodies[c.body_b];
        for (int32_t i = 0; i < c.point_count; ++i) {
            const ContactPointConstraint& p = c.points[i];
            apply_impulse(c, p, p.normal_impulse * c.normal + p.tangent_impulse * tangent, a, b);
        }
    }
}

namespace {

void solve_friction(ContactConstraint& c, Body& a, Body& b) {
    const Vec2 tangent = left_perp(c.normal);
    for (int32_t i = 0; i < c.point_count; ++i) {
        ContactPointConstraint& p = c.points[i];
        // Coulomb: friction can hold at most mu times what the normal pushes.
        const float vt = dot(relative_velocity(a, b, p.anchor_a, p.anchor_b), tangent);
        const float max_friction = c.friction * p.normal_impulse;
        const float old_tangent = p.tangent_impulse;
        p.tangent_impulse = clamp(old_tangent - p.tangent_mass * vt, -max_friction, max_friction);
        apply_impulse(c, p, (p.tangent_impulse - old_tangent) * tangent, a, b);
    }
}

void solve_normal_point(ContactConstraint& c, ContactPointConstraint& p, Body& a, Body& b) {
    const float vn = dot(relative_velocity(a, b, p.anchor_a, p.anchor_b), c.normal);
    const float old_normal = p.normal_impulse;
    p.normal_impulse = max_of(old_normal - p.normal_mass * (vn - p.target_normal_speed), 0.0f);
    apply_impulse(c, p, (p.normal_impulse - old_normal) * c.normal, a, b);
}

// Both points of a two-point manifold at once, as a 2x2 linear complementarity problem
// (Box2D 2.4's block solver, after Catto's GDC talks): find accumulated impulses x >= 0
// with relative normal velocities vn = K x + b >= 0 and x_i vn_i = 0, trying the four
// cases (both pushing, only one, neither). Solving the points one after the other
// instead lets each undo part of the other, which turns a resting box and makes tall
// stacks sway. Returns false when K is too ill-conditioned to invert (points nearly
// coincident); the caller then solves the points one by one.
bool solve_normal_block(ContactConstraint& c, Body& a, Body& b) {
    ContactPointConstraint& p1 = c.points[0];
    ContactPointConstraint& p2 = c.points[1];
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
    const float x1_old = p1.normal_impulse, x2_old = p2.normal_impulse;
    const float vn1 = dot(relative_velocity(a, b, p1.anchor_a, p1.anchor_b), n);
    const float vn2 = dot(relative_velocity(a, b, p2.anchor_a, p2.anchor_b), n);
    // vn = K x + bias with the old impulses taken out: bias = vn_now - target - K x_old.
    const float b1 = vn1 - p1.target_normal_speed - (k11 * x1_old + k12 * x2_old);
    const float b2 = vn2 - p2.target_normal_speed - (k12 * x1_old + k22 * x2_old);

    float x1 = 0.0f, x2 = 0.0f;
    const float inv_det = 1.0f / det;
    const float both1 = -inv_det * (k22 * b1 - k12 * b2), both2 = -inv_det * (k11 * b2 - k12 * b1);
    if (both1 >= 0.0f && both2 >= 0.0f) {
        x1 = both1, x2 = both2;  // both points push
    } else if (-b1 / k11 >= 0.0f && k12 * (-b1 / k11) + b2 >= 0.0f) {
        x1 = -b1 / k11;  // only the first pushes; the second separates
    } else if (-b2 / k22 >= 0.0f && k12 * (-b2 / k22) + b1 >= 0.0f) {
        x2 = -b2 / k22;  // only the second pushes
    } else if (b1 >= 0.0f && b2 >= 0.0f) {
        // neither pushes: both separate on their own
    } else {
        return false;  // no case fits (round-off at the boundaries): one by one
    }
    apply_impulse(c, p1, (x1 - x1_old) * n, a, b);
    apply_impulse(c, p2, (x2 - x2_old) * n, a, b);
    p1.normal_impulse = x1;
    p2.normal_impulse = x2;
    return true;
}

// Friction first, so that it uses the normal impulses of the previous iteration, then
// the normal constraint, which has the last word on penetration (Box2D's order).
void solve_contact(ContactConstraint& c, Body& a, Body& b) {
    solve_friction(c, a, b);
    if (c.point_count == 2 && solve_normal_block(c, a, b)) {
        return;
    }
    for (int32_t i = 0; i < c.point_count; ++i) {
        solve_normal_point(c, c.points[i], a, b);
    }
}

}  // namespace

void solve_contact_velocities(std::vector<ContactConstraint>& constraints, Pool<Body>& bodies,
                              const SolverSettings& settings) {
    for (int32_t iteration = 0; iteration < settings.velocity_iterations; ++iteration) {
        for (ContactConstraint& c : constraints) {
            solve_contact(c, bodies[c.body_a], bodies[c.body_b]);
        }
    }
}

namespace {

// Moves a body by a position impulse at an anchor; bodies that cannot move keep their
// exact bits (a static body's transform never changes).
void displace(Body& body, float inv_mass, float inv_inertia, Vec2 anchor, Vec2 impulse) {
    if (inv_mass != 0.0f) {
        body.center += inv_mass * impulse;
    }
    if (inv_inertia != 0.0f) {
        body.transform.q = integrate_rotation(body.transform.q, inv_inertia * cross(anchor, impulse));
    }
    if (inv_mass != 0.0f || inv_inertia != 0.0f) {
        body.transform.p = body.center - rotate(body.transform.q, body.local_center);
    }
}

}  // namespace

void correct_contact_positions(const std::vector<ContactConstraint>& constraints, Pool<Body>& bodies,
                               const SolverSettings& settings) {
    for (const ContactConstraint& c : constraints) {
        Body& a = bodies[c.body_a];
        Body& b = bodies[c.body_b];
        for (int32_t i = 0; i < c.point_count; ++i) {
            const ContactPointConstraint& p = c.points[i];
            const Vec2 r_a = rotate(a.transform.q, p.local_anchor_a);
            const Vec2 r_b = rotate(b.transform.q, p.local_anchor_b);
            // Both anchors met at the contact point when it was found; how far they moved
            // apart along the normal since then has undone that much penetration.
            const float penetration = p.penetration - dot((b.center + r_b) - (a.center + r_a), c.normal);
            const float excess = max_of(penetration - settings.contact_slop, 0.0f);
            const float mass = effective_mass(c, r_a, r_b, c.normal);
            if (excess == 0.0f || mass == 0.0f) {
                continue;
            }
            const Vec2 impulse = (settings.correction_percent * excess * mass) * c.normal;
            displace(a, c.inv_mass_a, c.inv_inertia_a, r_a, -impulse);
            displace(b, c.inv_mass_b, c.inv_inertia_b, r_b, impulse);
        }
    }
}

}  // namespace i2d
