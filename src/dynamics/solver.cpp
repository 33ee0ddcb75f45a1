// SPDX-License-Identifier: MIT
// The soft step: gather, colour, substep, write back.
#include "dynamics/solver.hpp"

#include <cmath>

#include "dynamics/constants.hpp"
#include "dynamics/contact_set.hpp"
#include "dynamics/island.hpp"
#include "dynamics/shape_bounds.hpp"
#include "dynamics/softness.hpp"
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

// Gravity and force over mass of a body the solver moves; zero for fixed ones (and
// finite whatever the force, for the restitution estimate that uses it).
Vec2 free_acceleration(const Body& b, Vec2 gravity) {
    if (b.type != BodyType::dynamic || b.inv_mass == 0.0f) {
        return {};
    }
    const Vec2 a = b.gravity_scale * gravity + b.inv_mass * b.force;
    return is_finite(a) ? a : Vec2{};
}

}  // namespace

void Solver::step(float time_step, int32_t substep_count) {
    const float h = time_step / float(substep_count);
    const float inv_h = float(substep_count) / time_step;
    gather_bodies();
    prepare_contacts();
    const WorldDef& s = links_.settings;
    // Stiffness is capped at a quarter of the substep rate, beyond which the implicit
    // spring stops being accurate; contacts with a fixed body get twice the frequency.
    const float hertz = min_of(s.contact_hertz, 0.25f / h);
    const Softness soft = make_softness(hertz, s.contact_damping_ratio, h);
    const Softness fixed_soft = make_softness(2.0f * hertz, s.contact_damping_ratio, h);
    SolvePass pass{inv_h,
                   s.contact_push_max_speed,
                   0.0f,
                   true,
                   friction_anchor_share * inv_h,
                   {soft.bias_rate, soft.mass_scale, soft.impulse_scale},
                   {fixed_soft.bias_rate, fixed_soft.mass_scale, fixed_soft.impulse_scale}};
    BodyState* states = states_.data();
    for (int32_t i = 0; i < substep_count; ++i) {
        integrate_velocities(h);
        contact_solver_.warm_start(states);
        pass.elapsed = float(i + 1) * h;
        pass.use_bias = true;
        contact_solver_.solve(states, pass);
        integrate_positions(h);
        pass.use_bias = false;
        contact_solver_.solve(states, pass);
    }
    // One more relax at the end: the velocities a step ends with are the ones the next
    // step starts from (and the ones sleep tests). One sweep per substep leaves a tall
    // stack's last velocities unconverged, and the residue kept a 100-row pyramid
    // vibrating and wandering at centimetres per second; the second sweep lets it rest.
    contact_solver_.solve(states, pass);
    contact_solver_.apply_restitution(states, s.restitution_threshold);
    contact_solver_.store(links_.contacts.pool(), states, s.contact_slop);
    finalize_bodies(time_step);
}

// One state per awake body in awake order, then the shared fixed state.
void Solver::gather_bodies() {
    const std::vector<int32_t>& awake = links_.islands.awake_bodies();
    const std::size_t count = awake.size();
    states_.resize(count + 1);
    motions_.resize(count + 1);
    for (std::size_t k = 0; k < count; ++k) {
        const Body& b = links_.bodies[awake[k]];
        const bool dynamic = b.type == BodyType::dynamic;
        states_[k] = BodyState{b.linear_velocity, b.angular_velocity, dynamic ? 1.0f : 0.0f, Vec2{}, Rot{}};
        BodyMotion& m = motions_[k];
        m.force = b.force;
        m.torque = b.torque;
        m.inv_mass = b.inv_mass;
        m.inv_inertia = b.inv_inertia;
        m.gravity_scale = b.gravity_scale;
        m.linear_damping = b.linear_damping;
        m.angular_damping = b.angular_damping;
        m.free_acceleration = free_acceleration(b, links_.settings.gravity);
        m.is_dynamic = dynamic;
    }
    states_[count] = BodyState{};
    motions_[count] = BodyMotion{};
}

void Solver::prepare_contacts() {
    color_contacts();
    const ContactLayout layout{links_.contacts.pool(), ordered_contacts_.data(), color_starts_.data(),
                               ConstraintColors::count, states_.data(),      motions_.data(),
                               int32_t(states_.size()) - 1};
    contact_solver_.prepare(layout);
}

// A colour for every awake contact the solver will see, then the contacts laid out
// colour by colour (a counting sort that keeps awake order), the order they are solved
// in. Within a colour, whose contacts are independent, two-point contacts come first,
// so that SIMD blocks hold one kind and blocks of single points skip the second; the
// overflow colour is solved in sequence and keeps awake order. A body the contact
// cannot move (static, kinematic, asleep) takes no colour slot.
void Solver::color_contacts() {
    const uint64_t version = links_.contacts.layout_version();
    const int32_t awake_bodies = int32_t(links_.islands.awake_bodies().size());
    if (colored_ && version == colored_version_ && awake_bodies == colored_body_count_) {
        return;  // nothing the colours depend on changed: a resting pile keeps them
    }
    colored_ = true;
    colored_version_ = version;
    colored_body_count_ = awake_bodies;
    const std::vector<int32_t>& awake = links_.contacts.awake();
    const Pool<Contact>& contacts = links_.contacts.pool();
    colors_.reset(awake_bodies);
    contact_colors_.resize(awake.size());
    color_starts_.assign(ConstraintColors::count + 1, 0);
    for (std::size_t k = 0; k < awake.size(); ++k) {
        const Contact& contact = contacts[awake[k]];
        int32_t color = -1;
        if ((contact.flags & contact_sensor) == 0 && contact.point_count != 0) {
            color = colors_.assign((contact.flags & contact_moves_a) ? contact.state_a : ConstraintColors::null_state,
                                   (contact.flags & contact_moves_b) ? contact.state_b : ConstraintColors::null_state);
            ++color_starts_[std::size_t(color) + 1];
        }
        contact_colors_[k] = int8_t(color);
    }
    for (int32_t color = 0; color < ConstraintColors::count; ++color) {
        color_starts_[std::size_t(color) + 1] += color_starts_[std::size_t(color)];
    }
    ordered_contacts_.resize(std::size_t(color_starts_[ConstraintColors::count]));
    std::vector<int32_t>& next = scratch_starts_;
    next.assign(color_starts_.begin(), color_starts_.end() - 1);
    for (int32_t pass = 0; pass < 2; ++pass) {
        const int32_t points = 2 - pass;
        for (std::size_t k = 0; k < awake.size(); ++k) {
            const int32_t color = contact_colors_[k];
            const bool in_sequence = color == ConstraintColors::overflow;
            if (color >= 0 && (in_sequence ? pass == 0 : contacts[awake[k]].point_count == points)) {
                ordered_contacts_[std::size_t(next[std::size_t(color)]++)] = awake[k];
            }
        }
    }
}

// Gravity, forces and damping for dynamic bodies; the speed limit for every moving body
// (kinematic ones too: a caller may set any finite velocity).
void Solver::integrate_velocities(float h) {
    const Vec2 gravity = links_.settings.gravity;
    const float max_speed = links_.settings.maximum_linear_speed;
    const float max_spin = max_rotation_per_substep / h;
    const std::size_t count = states_.size() - 1;
    for (std::size_t k = 0; k < count; ++k) {
        const BodyMotion& m = motions_[k];
        BodyState& s = states_[k];
        Vec2 v = s.linear_velocity;
        float w = s.angular_velocity;
        if (m.is_dynamic) {
            v += h * (m.gravity_scale * gravity + m.inv_mass * m.force);
            w += h * m.inv_inertia * m.torque;
            // Implicit damping: stable for any damping and step, v -> v / (1 + h c).
            v = (1.0f / (1.0f + h * m.linear_damping)) * v;
            w = (1.0f / (1.0f + h * m.angular_damping)) * w;
        }
        // NaN-safe: an overflow anywhere above fails this test too.
        s.linear_velocity = length_squared(v) <= max_speed * max_speed
                                ? v
                                : limited_velocity(m, s.linear_velocity, gravity, h, max_speed);
        // At most a quarter turn per substep: faster spins alias and tunnel.
        s.angular_velocity = w >= -max_spin && w <= max_spin ? w : (w > 0.0f ? max_spin : -max_spin);
    }
}

void Solver::integrate_positions(float h) {
    const std::size_t count = states_.size() - 1;
    for (std::size_t k = 0; k < count; ++k) {
        BodyState& s = states_[k];
        s.delta_position += h * s.linear_velocity;
        if (s.angular_velocity != 0.0f) {
            s.delta_rotation = integrate_rotation(s.delta_rotation, h * s.angular_velocity);
        }
    }
}

void Solver::finalize_bodies(float time_step) {
    const std::size_t count = states_.size() - 1;
    if (links_.settings.enable_sleep) {
        links_.islands.begin_rest_times();
    }
    for (std::size_t k = 0; k < count; ++k) {
        finalize_body(int32_t(k), time_step);
    }
}

// The body's new pose (bodies that did not turn keep their rotation's exact bits), its
// shapes' bounds, its rest time and its move event.
void Solver::finalize_body(int32_t k, float time_step) {
    const BodyState& s = states_[std::size_t(k)];
    const int32_t index = links_.islands.awake_bodies()[std::size_t(k)];
    Body& b = links_.bodies[index];
    const Transform start = b.transform;
    b.linear_velocity = s.linear_velocity;
    b.angular_velocity = s.angular_velocity;
    b.center += s.delta_position;
    if (s.delta_rotation.c != 1.0f || s.delta_rotation.s != 0.0f) {
        b.transform.q = normalize(mul_rot(s.delta_rotation, b.transform.q));
    }
    b.transform.p = b.center - rotate(b.transform.q, b.local_center);
    b.force = {};
    b.torque = 0.0f;
    // Fattened for the next step too, assuming the same time step (the world checks).
    update_shape_bounds(b, links_.shapes, links_.broad_phase, time_step * b.linear_velocity, true);

    const WorldDef& settings = links_.settings;
    if (settings.enable_sleep) {
        // A body rests while its fastest point (spin x extent) and its centre stay slow.
        const float threshold = settings.sleep_speed_threshold;
        const bool resting = b.enable_sleep && length(b.linear_velocity) <= threshold &&
                             std::fabs(b.angular_velocity) * b.max_extent <= threshold;
        b.sleep_time = resting ? b.sleep_time + time_step : 0.0f;
        links_.islands.note_rest_time(index, b.sleep_time);
        if (b.type == BodyType::kinematic) {
            share_kinematic_rest(index);
        }
    }
    const bool moved = !(b.transform.p == start.p && b.transform.q.c == start.q.c && b.transform.q.s == start.q.s);
    b.move_event = null_index;
    if (moved) {
        EventRecorder& events = links_.events;
        b.move_event = int32_t(events.current.body_moves.size());
        events.current.body_moves.push_back(
            {b.transform, events.ids.body_id(index, links_.bodies.generation(index)), b.user_data, false});
    }
}

// A moving kinematic body keeps what it touches awake: the islands it touches rest no
// longer than it does.
void Solver::share_kinematic_rest(int32_t body) {
    const float rest = links_.bodies[body].sleep_time;
    const Pool<Contact>& contacts = links_.contacts.pool();
    links_.contacts.visit_contacts(body, [&](int32_t contact, int32_t other) {
        const Contact& c = contacts[contact];
        const Body& o = links_.bodies[other];
        if ((c.flags & contact_sensor) == 0 && c.point_count > 0 && o.type == BodyType::dynamic &&
            o.awake_index != null_index) {
            links_.islands.note_rest_time(other, rest);
        }
    });
}

}  // namespace i2d
