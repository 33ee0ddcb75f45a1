// SPDX-License-Identifier: MIT
// The soft step: dense body states and contact constraints are gathered from the awake
// set, substepped, and written back.
#include <cmath>

#include "dynamics/constants.hpp"
#include "dynamics/world.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// The float update overflowed or broke the speed limit: redo it in double, where no
// finite float input can overflow, then scale down to the limit. Rare, so off the fast path.
Vec2 limited_velocity(const BodyMotion& m, Vec2 v, Vec2 gravity, float h, float max_speed) {
    double ax = 0.0, ay = 0.0, damping_factor = 1.0;
    if (m.is_dynamic) {
        ax = double(h) * (double(m.gravity_scale) * gravity.x + double(m.inv_mass) * m.force.x);
        ay = double(h) * (double(m.gravity_scale) * gravity.y + double(m.inv_mass) * m.force.y);
        damping_factor = 1.0 / (1.0 + double(h) * m.linear_damping);
    }
    const double vx = (v.x + ax) * damping_factor;
    const double vy = (v.y + ay) * damping_factor;
    const double speed = std::sqrt(vx * vx + vy * vy);
    const double scale = speed > max_speed ? max_speed / speed : 1.0;
    return {float(vx * scale), float(vy * scale)};
}

}  // namespace

// Gravity and force over mass of a body the solver moves; zero for fixed ones (and
// finite whatever the force, for the restitution estimate that uses it).
Vec2 World::free_acceleration(const Body& b, float inv_mass) const {
    if (b.type != BodyType::dynamic || inv_mass == 0.0f) {
        return {};
    }
    const Vec2 a = b.gravity_scale * settings.gravity + inv_mass * b.force;
    return is_finite(a) ? a : Vec2{};
}

void World::solve(float time_step, int32_t substep_count) {
    const float h = time_step / float(substep_count);
    const float inv_h = float(substep_count) / time_step;
    gather_bodies();
    gather_constraints(h);
    prepare_contacts(constraints_, states_);
    const ContactSolverSettings contact_settings{settings.contact_push_max_speed, settings.restitution_threshold};
    for (int32_t i = 0; i < substep_count; ++i) {
        integrate_velocities(h);
        warm_start_contacts(constraints_, states_);
        const float elapsed = float(i + 1) * h;
        solve_contacts(constraints_, states_, inv_h, contact_settings, true, elapsed);
        integrate_positions(h);
        solve_contacts(constraints_, states_, inv_h, contact_settings, false, elapsed);
    }
    apply_restitution(constraints_, states_, contact_settings);
    store_impulses();
    finalize_bodies();
}

// One state per awake body in awake order, then the shared fixed state.
void World::gather_bodies() {
    const std::size_t count = awake_bodies_.size();
    states_.resize(count + 1);
    motions_.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const Body& b = bodies[awake_bodies_[k]];
        states_[k] = BodyState{b.linear_velocity, b.angular_velocity, Vec2{}, Rot{}};
        BodyMotion& m = motions_[k];
        m.force = b.force;
        m.torque = b.torque;
        m.inv_mass = b.inv_mass;
        m.inv_inertia = b.inv_inertia;
        m.gravity_scale = b.gravity_scale;
        m.linear_damping = b.linear_damping;
        m.angular_damping = b.angular_damping;
        m.is_dynamic = b.type == BodyType::dynamic;
    }
    states_[count] = BodyState{};
}

// Contacts with a static or kinematic body are twice as stiff (Box2D v3's choice): the
// fixed side cannot give, so the pair has half the mass to move and settles as fast.
// Stiffness is capped at a quarter of the substep rate, beyond which the implicit
// spring stops being accurate. Constraints are laid out colour by colour (a counting
// sort that keeps awake order within a colour), which is the order they are solved in.
void World::gather_constraints(float h) {
    const float hertz = min_of(settings.contact_hertz, 0.25f / h);
    const Softness soft = make_softness(hertz, settings.contact_damping_ratio, h);
    const Softness fixed_soft = make_softness(2.0f * hertz, settings.contact_damping_ratio, h);
    color_constraints();
    constraints_.resize(std::size_t(color_starts_[ConstraintColors::count]));
    for (std::size_t k = 0; k < awake_contacts_.size(); ++k) {
        const int32_t color = contact_colors_[k];
        if (color >= 0) {
            constraints_[std::size_t(color_starts_[color]++)] = make_constraint(awake_contacts_[k], soft, fixed_soft);
        }
    }
}

// A colour for every awake contact the solver will see, and where each colour starts.
// A body outside the awake set (static, or asleep until the next wake) is fixed, and so
// is a kinematic one: contacts never move it.
void World::color_constraints() {
    colors_.reset(int32_t(awake_bodies_.size()));
    contact_colors_.resize(awake_contacts_.size());
    color_starts_.assign(ConstraintColors::count + 1, 0);
    const auto moving_state = [](const Body& b) {
        return b.awake_index != null_index && b.type == BodyType::dynamic ? b.awake_index : ConstraintColors::null_state;
    };
    for (std::size_t k = 0; k < awake_contacts_.size(); ++k) {
        const Contact& contact = contacts[awake_contacts_[k]];
        int32_t color = -1;
        if ((contact.flags & contact_sensor) == 0 && contact.manifold.point_count != 0) {
            color = colors_.assign(moving_state(bodies[contact.edges[0].body]),
                                   moving_state(bodies[contact.edges[1].body]));
            ++color_starts_[color + 1];
        }
        contact_colors_[k] = int8_t(color);
    }
    for (int32_t color = 0; color < ConstraintColors::count; ++color) {
        color_starts_[color + 1] += color_starts_[color];
    }
}

ContactConstraint World::make_constraint(int32_t index, const Softness& soft, const Softness& fixed_soft) const {
    const Contact& contact = contacts[index];
    const int32_t fixed_state = int32_t(awake_bodies_.size());
    ContactConstraint c;
    c.contact = index;
    const Body& a = bodies[contact.edges[0].body];
    const Body& b = bodies[contact.edges[1].body];
    // A body outside the awake set (static, or asleep until the next wake) is fixed.
    c.state_a = a.awake_index != null_index ? a.awake_index : fixed_state;
    c.state_b = b.awake_index != null_index ? b.awake_index : fixed_state;
    c.inv_mass_a = c.state_a != fixed_state ? a.inv_mass : 0.0f;
    c.inv_mass_b = c.state_b != fixed_state ? b.inv_mass : 0.0f;
    c.inv_inertia_a = c.state_a != fixed_state ? a.inv_inertia : 0.0f;
    c.inv_inertia_b = c.state_b != fixed_state ? b.inv_inertia : 0.0f;
    c.softness = c.inv_mass_a == 0.0f || c.inv_mass_b == 0.0f ? fixed_soft : soft;
    c.normal = contact.manifold.normal;
    const Vec2 relative_acceleration = free_acceleration(b, c.inv_mass_b) - free_acceleration(a, c.inv_mass_a);
    c.approach_acceleration = max_of(-dot(relative_acceleration, c.normal), 0.0f);
    c.friction = contact.friction;
    c.restitution = contact.restitution;
    c.tangent_speed = contact.tangent_speed;
    c.rolling_resistance = contact.rolling_resistance;
    c.rolling_impulse = contact.rolling_impulse;
    c.point_count = contact.manifold.point_count;
    for (int32_t i = 0; i < c.point_count; ++i) {
        const ManifoldPoint& mp = contact.manifold.points[i];
        ContactConstraintPoint& p = c.points[i];
        p.anchor_a = mp.point - a.center;
        p.anchor_b = mp.point - b.center;
        p.base_separation = -mp.penetration - dot(p.anchor_b - p.anchor_a, c.normal);
        p.normal_impulse = contact.impulses[i].normal;
        p.tangent_impulse = contact.impulses[i].tangent;
    }
    return c;
}

// Gravity, forces and damping for dynamic bodies; the speed limit for every moving body
// (kinematic ones too: a caller may set any finite velocity).
void World::integrate_velocities(float h) {
    const float max_speed = settings.maximum_linear_speed;
    const float max_spin = max_rotation_per_substep / h;
    for (std::size_t k = 0; k < motions_.size(); ++k) {
        const BodyMotion& m = motions_[k];
        BodyState& s = states_[k];
        Vec2 v = s.linear_velocity;
        float w = s.angular_velocity;
        if (m.is_dynamic) {
            v += h * (m.gravity_scale * settings.gravity + m.inv_mass * m.force);
            w += h * m.inv_inertia * m.torque;
            // Implicit damping: stable for any damping and step, v -> v / (1 + h c).
            v = (1.0f / (1.0f + h * m.linear_damping)) * v;
            w = (1.0f / (1.0f + h * m.angular_damping)) * w;
        }
        // NaN-safe: an overflow anywhere above fails this test too.
        s.linear_velocity = length_squared(v) <= max_speed * max_speed
                                ? v
                                : limited_velocity(m, s.linear_velocity, settings.gravity, h, max_speed);
        // At most a quarter turn per substep: faster spins alias and tunnel.
        s.angular_velocity = w >= -max_spin && w <= max_spin ? w : (w > 0.0f ? max_spin : -max_spin);
    }
}

void World::integrate_positions(float h) {
    for (std::size_t k = 0; k < motions_.size(); ++k) {
        BodyState& s = states_[k];
        s.delta_position += h * s.linear_velocity;
        if (s.angular_velocity != 0.0f) {
            s.delta_rotation = integrate_rotation(s.delta_rotation, h * s.angular_velocity);
        }
    }
}

void World::store_impulses() {
    for (const ContactConstraint& c : constraints_) {
        Contact& contact = contacts[c.contact];
        for (int32_t i = 0; i < c.point_count; ++i) {
            contact.impulses[i] = {c.points[i].normal_impulse, c.points[i].tangent_impulse};
        }
        contact.rolling_impulse = c.rolling_impulse;
    }
}

// Bodies that did not turn keep their rotation's exact bits.
void World::finalize_bodies() {
    for (std::size_t k = 0; k < motions_.size(); ++k) {
        const BodyState& s = states_[k];
        Body& b = bodies[awake_bodies_[k]];
        b.linear_velocity = s.linear_velocity;
        b.angular_velocity = s.angular_velocity;
        b.center += s.delta_position;
        if (s.delta_rotation.c != 1.0f || s.delta_rotation.s != 0.0f) {
            b.transform.q = normalize(mul_rot(s.delta_rotation, b.transform.q));
        }
        b.transform.p = b.center - rotate(b.transform.q, b.local_center);
    }
}

}  // namespace i2d
