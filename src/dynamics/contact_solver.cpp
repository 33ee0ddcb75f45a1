// SPDX-License-Identifier: MIT
// Sequential impulses with restitution and Coulomb friction; the seed's positional correction.
#include "dynamics/contact_solver.hpp"

#include <algorithm>
#include <cmath>

#include "math/math.hpp"

namespace i2d {

namespace {

bool precedes(const ContactConstraint& l, const ContactConstraint& r) {
    return l.key_a != r.key_a ? l.key_a < r.key_a : l.key_b < r.key_b;
}

}  // namespace

void sort_contacts(std::vector<ContactConstraint>& contacts) {
    std::sort(contacts.begin(), contacts.end(), precedes);
}

// A merge of two sorted lists: linear in their lengths, no hashing.
void carry_impulses(std::vector<ContactConstraint>& contacts, const std::vector<ContactConstraint>& previous) {
    size_t j = 0;
    for (ContactConstraint& c : contacts) {
        while (j < previous.size() && precedes(previous[j], c)) {
            ++j;
        }
        if (j == previous.size()) {
            return;
        }
        const ContactConstraint& old = previous[j];
        if (old.key_a != c.key_a || old.key_b != c.key_b) {
            continue;
        }
        for (int32_t i = 0; i < c.point_count; ++i) {
            for (int32_t k = 0; k < old.point_count; ++k) {
                if (old.points[k].id == c.points[i].id) {
                    c.points[i].normal_impulse = old.points[k].normal_impulse;
                    c.points[i].tangent_impulse = old.points[k].tangent_impulse;
                }
            }
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
