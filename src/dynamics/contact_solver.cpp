// SPDX-License-Identifier: MIT
// Sequential impulses with restitution and Coulomb friction; the seed's positional correction.
#include "dynamics/contact_solver.hpp"

#include <cmath>

#include "math/math.hpp"

namespace i2d {

void gather_constraints(const Pool<Contact>& contacts, std::vector<ContactConstraint>& out) {
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
        c.normal = contact.manifold.normal;
        c.friction = contact.friction;
        c.restitution = contact.restitution;
        c.point_count = contact.manifold.point_count;
        for (int32_t p = 0; p < c.point_count; ++p) {
            c.points[p].penetration = contact.manifold.points[p].penetration;
            c.points[p].normal_impulse = contact.impulses[p].normal;
            c.points[p].tangent_impulse = contact.impulses[p].tangent;
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

void prepare_contacts(std::vector<ContactConstraint>& contacts, Pool<Body>& bodies, const SolverSettings& settings) {
    for (ContactConstraint& c : contacts) {
        const Body& a = bodies[c.body_a];
        const Body& b = bodies[c.body_b];
        c.inv_mass_a = a.inv_mass;
        c.inv_mass_b = b.inv_mass;
        c.inv_mass_sum = a.inv_mass + b.inv_mass;
        const float vn = dot(b.linear_velocity - a.linear_velocity, c.normal);
        // Slow impacts do not bounce: resting contacts would otherwise never settle.
        const float target = vn < -settings.restitution_threshold ? -c.restitution * vn : 0.0f;
        for (int32_t i = 0; i < c.point_count; ++i) {
            c.points[i].target_normal_speed = target;
        }
    }
}

void warm_start_contacts(const std::vector<ContactConstraint>& contacts, Pool<Body>& bodies) {
    for (const ContactConstraint& c : contacts) {
        const Vec2 tangent = left_perp(c.normal);
        Vec2& va = bodies[c.body_a].linear_velocity;
        Vec2& vb = bodies[c.body_b].linear_velocity;
        for (int32_t i = 0; i < c.point_count; ++i) {
            const Vec2 impulse = c.points[i].normal_impulse * c.normal + c.points[i].tangent_impulse * tangent;
            va -= c.inv_mass_a * impulse;
            vb += c.inv_mass_b * impulse;
        }
    }
}

namespace {

void solve_contact(ContactConstraint& c, Vec2& va, Vec2& vb) {
    if (c.inv_mass_sum == 0.0f) {
        return;
    }
    const float inv_k = 1.0f / c.inv_mass_sum;
    const Vec2 tangent = left_perp(c.normal);
    for (int32_t i = 0; i < c.point_count; ++i) {
        ContactPointConstraint& p = c.points[i];

        const float vn = dot(vb - va, c.normal);
        const float old_normal = p.normal_impulse;
        p.normal_impulse = std::fmax(old_normal - (vn - p.target_normal_speed) * inv_k, 0.0f);
        const Vec2 jn = (p.normal_impulse - old_normal) * c.normal;
        va -= c.inv_mass_a * jn;
        vb += c.inv_mass_b * jn;

        // Coulomb: friction can hold at most mu times what the normal pushes.
        const float vt = dot(vb - va, tangent);
        const float max_friction = c.friction * p.normal_impulse;
        const float old_tangent = p.tangent_impulse;
        p.tangent_impulse = clamp(old_tangent - vt * inv_k, -max_friction, max_friction);
        const Vec2 jt = (p.tangent_impulse - old_tangent) * tangent;
        va -= c.inv_mass_a * jt;
        vb += c.inv_mass_b * jt;
    }
}

}  // namespace

void solve_contact_velocities(std::vector<ContactConstraint>& contacts, Pool<Body>& bodies,
                              const SolverSettings& settings) {
    for (int32_t iteration = 0; iteration < settings.velocity_iterations; ++iteration) {
        for (ContactConstraint& c : contacts) {
            solve_contact(c, bodies[c.body_a].linear_velocity, bodies[c.body_b].linear_velocity);
        }
    }
}

void correct_contact_positions(const std::vector<ContactConstraint>& contacts, Pool<Body>& bodies,
                               const SolverSettings& settings) {
    for (const ContactConstraint& c : contacts) {
        if (c.inv_mass_sum == 0.0f) {
            continue;
        }
        // The deepest point, once per pair: correcting per point would push twice.
        float depth = 0.0f;
        for (int32_t i = 0; i < c.point_count; ++i) {
            depth = std::fmax(depth, c.points[i].penetration);
        }
        const float share = std::fmax(depth - settings.contact_slop, 0.0f) / c.inv_mass_sum * settings.correction_percent;
        if (share == 0.0f) {
            continue;
        }
        const Vec2 correction = share * c.normal;
        Body& a = bodies[c.body_a];
        Body& b = bodies[c.body_b];
        a.center -= c.inv_mass_a * correction;
        a.transform.p -= c.inv_mass_a * correction;
        b.center += c.inv_mass_b * correction;
        b.transform.p += c.inv_mass_b * correction;
    }
}

}  // namespace i2d
