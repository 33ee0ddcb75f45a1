// SPDX-License-Identifier: MIT
// BodyPass: gathering, integrating and finalizing the awake bodies.
#include "dynamics/solver/body_pass.hpp"

#include <cmath>

#include "core/prefetch.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// The awake list jumps through the body pool: gather and finalize ask for the bodies this
// far ahead, and finalize, once a body is close, for its first shape, which refitting its
// bounds reads (in rain, 40 % of the refit waited for that shape).
constexpr int32_t prefetch_bodies_ahead = 8;
constexpr int32_t prefetch_shapes_ahead = 4;
// A shape's lines as far as a polygon's vertices (a body is read whole).
constexpr std::size_t shape_lines_read = 4;

I2D_FORCE_INLINE void prefetch_awake_body(const Pool<Body>& bodies, const std::vector<int32_t>& awake, int32_t k,
                                          int32_t end) {
    if (k + prefetch_bodies_ahead < end) {
        prefetch_object(bodies[awake[std::size_t(k + prefetch_bodies_ahead)]]);
    }
}

I2D_FORCE_INLINE void prefetch_first_shape(const Pool<Body>& bodies, const Pool<Shape>& shapes,
                                           const std::vector<int32_t>& awake, int32_t k, int32_t end) {
    if (k + prefetch_shapes_ahead < end) {
        const int32_t shape = bodies[awake[std::size_t(k + prefetch_shapes_ahead)]].head_shape;
        if (shape != null_index) {
            prefetch_lines(&shapes[shape], shape_lines_read);
        }
    }
}

// The float update overflowed or broke the speed limit: redo it in double, where no
// finite float input can overflow, then scale down to the limit. Rare, so off the fast path.
Vec2 limited_velocity(const BodyMotion& m, Vec2 v, Vec2 gravity, float h, float max_speed) {
    double ax = 0.0, ay = 0.0, damping_factor = 1.0;
    if (m.is_dynamic) {
        ax = double(h) * (double(m.gravity_scale) * gravity.x + double(m.inv_mass) * m.force.x);
        ay = double(h) * (double(m.gravity_scale) * gravity.y + double(m.inv_mass) * m.force.y);
        damping_factor = 1.0 / (1.0 + double(h) * m.linear_damping);
    }
    return held_to_length((v.x + ax) * damping_factor, (v.y + ay) * damping_factor, max_speed);
}

// Gravity and force over mass of a body the solver moves; zero for fixed ones. Only the
// restitution estimate reads it, which squares it times a gap: each component is held
// to `limit` (what takes a body from rest to the speed cap within the step; more would
// not move it further), so that the estimate stays finite whatever the force.
Vec2 free_acceleration(const Body& b, Vec2 gravity, float limit) {
    if (b.type != BodyType::dynamic || b.inv_mass == 0.0f) {
        return {};
    }
    const Vec2 a = b.gravity_scale * gravity + b.inv_mass * b.force;
    if (!is_finite(a)) {
        return {};
    }
    return {max_of(-limit, min_of(a.x, limit)), max_of(-limit, min_of(a.y, limit))};
}

// Whether the body's fastest point went far relative to its thinnest shape: then it may
// have passed through something thin, and the continuous stage sweeps it.
bool is_fast(const Body& b, const BodyState& s, float time_step) {
    if (b.type != BodyType::dynamic) {
        return false;
    }
    return is_fast_travel(b, length(s.delta_position) + time_step * std::fabs(s.angular_velocity) * b.max_extent);
}

}  // namespace

void BodyPass::begin(int32_t awake_count) {
    const std::size_t awake = std::size_t(awake_count);
    states_.resize(awake + 1);
    motions_.resize(awake + 1);
    states_[awake] = BodyState{};
    motions_[awake] = BodyMotion{};
    final_flags_.resize(awake);
    rest_islands_.resize(awake);
    rest_times_.resize(awake);
}

void BodyPass::clear_results() {
    fast_bodies_.clear();
    non_finite_bodies_.clear();
}

void BodyPass::gather(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin, int32_t end,
                      int32_t) {
    const std::vector<int32_t>& awake = pass.links_.islands.awake_bodies();
    const Vec2 gravity = step.settings.gravity;
    const float acceleration_limit = step.settings.maximum_linear_speed / step.time_step;
    const float h = step.substep;
    const IntegrationTerms terms = integration_terms(step);
    for (int32_t k = begin; k < end; ++k) {
        prefetch_awake_body(pass.links_.bodies, awake, k, end);
        const Body& b = pass.links_.bodies[awake[std::size_t(k)]];
        const bool dynamic = b.type == BodyType::dynamic;
        pass.states_[std::size_t(k)] =
            BodyState{b.linear_velocity, b.angular_velocity, dynamic ? 1.0f : 0.0f, Vec2{}, Rot{}};
        BodyMotion& m = pass.motions_[std::size_t(k)];
        m.force = b.force;
        m.torque = b.torque;
        m.inv_mass = b.inv_mass;
        m.inv_inertia = b.inv_inertia;
        m.gravity_scale = b.gravity_scale;
        m.linear_damping = b.linear_damping;
        m.linear_damping_factor = 1.0f / (1.0f + h * b.linear_damping);
        m.angular_damping_factor = 1.0f / (1.0f + h * b.angular_damping);
        m.free_acceleration = free_acceleration(b, gravity, acceleration_limit);
        m.start_linear_velocity = b.linear_velocity;
        m.start_angular_velocity = b.angular_velocity;
        m.is_dynamic = dynamic;
        pass.integrate_velocity(k, terms);
    }
}

void BodyPass::integrate_velocities(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin,
                                    int32_t end, int32_t) {
    const IntegrationTerms terms = integration_terms(step);
    for (int32_t k = begin; k < end; ++k) {
        pass.integrate_velocity(k, terms);
    }
}

BodyPass::IntegrationTerms BodyPass::integration_terms(const StepContext& step) {
    return {step.substep, step.settings.gravity, step.settings.maximum_linear_speed, step.max_spin()};
}

// Gravity, forces and damping for dynamic bodies; the speed limit for every moving body
// (kinematic ones too: a caller may set any finite velocity).
void BodyPass::integrate_velocity(int32_t k, const IntegrationTerms& t) {
    const float h = t.h;
    const Vec2 gravity = t.gravity;
    const float max_speed = t.max_speed;
    const float max_spin = t.max_spin;
    const BodyMotion& m = motions_[std::size_t(k)];
    BodyState& s = states_[std::size_t(k)];
    Vec2 v = s.linear_velocity;
    float w = s.angular_velocity;
    if (m.is_dynamic) {
        v += h * (m.gravity_scale * gravity + m.inv_mass * m.force);
        w += h * m.inv_inertia * m.torque;
        // Implicit damping: stable for any damping and step.
        v = m.linear_damping_factor * v;
        w = m.angular_damping_factor * w;
    }
    // NaN-safe: an overflow anywhere above fails this test too.
    s.linear_velocity =
        length_squared(v) <= max_speed * max_speed ? v : limited_velocity(m, s.linear_velocity, gravity, h, max_speed);
    // At most a quarter turn per substep: faster spins alias and tunnel. A NaN passes
    // through, to be quarantined, rather than becoming a full spin.
    s.angular_velocity = w > max_spin ? max_spin : (w < -max_spin ? -max_spin : w);
}

void BodyPass::integrate_positions(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin,
                                   int32_t end, int32_t) {
    const float h = step.substep;
    for (int32_t k = begin; k < end; ++k) {
        BodyState& s = pass.states_[std::size_t(k)];
        s.delta_position += h * s.linear_velocity;
        if (s.angular_velocity != 0.0f) {
            s.delta_rotation = integrate_rotation(s.delta_rotation, h * s.angular_velocity);
        }
    }
}

void BodyPass::finalize(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin, int32_t end,
                        int32_t) {
    const WorldDef& settings = step.settings;
    const FinalTerms terms{step.time_step, settings.enable_sleep, settings.enable_continuous};
    const std::vector<int32_t>& awake = pass.links_.islands.awake_bodies();
    for (int32_t k = begin; k < end; ++k) {
        prefetch_awake_body(pass.links_.bodies, awake, k, end);
        prefetch_first_shape(pass.links_.bodies, pass.links_.shapes, awake, k, end);
        pass.finalize_body(terms, k);
    }
}

// The body's new pose (bodies that did not turn keep their rotation's exact bits), its
// shapes' bounds and its rest time. What reaches beyond the body waits in its slots for
// finish().
void BodyPass::finalize_body(const FinalTerms& terms, int32_t k) {
    const int32_t index = links_.islands.awake_bodies()[std::size_t(k)];
    Body& b = links_.bodies[index];
    // A state that overflowed is not written: the body stays where the step found it,
    // at rest, and the world quarantines it (no NaN reaches the bounds or the trees).
    static const BodyState at_rest{};
    const BodyState& solved = states_[std::size_t(k)];
    const bool finite = is_finite(solved.linear_velocity) && is_finite(solved.angular_velocity) &&
                        is_finite(b.center + solved.delta_position) && is_finite(solved.delta_rotation);
    const BodyState& s = finite ? solved : at_rest;
    const Transform start = b.transform;
    b.linear_velocity = s.linear_velocity;
    b.angular_velocity = s.angular_velocity;
    b.center0 = b.center;
    b.rotation0 = start.q;
    b.center += s.delta_position;
    if (s.delta_rotation.c != 1.0f || s.delta_rotation.s != 0.0f) {
        b.transform.q = normalize(mul_rot(s.delta_rotation, b.transform.q));
    }
    b.transform.p = b.center - rotate(b.transform.q, b.local_center);
    b.force = {};
    b.torque = 0.0f;
    // Fattened for the next step too, assuming the same time step (the world checks).
    const float time_step = terms.time_step;
    uint8_t flags = refit_shape_bounds(b, links_.shapes, time_step * b.linear_velocity, true,
                                       turn_reach(b, time_step)) ? proxies_enlarged : 0;

    if (terms.enable_sleep) {
        // A body rests while its fastest point (spin x extent) and its centre stay slow.
        const float threshold = b.sleep_threshold;
        const bool resting = b.enable_sleep && length(b.linear_velocity) <= threshold &&
                             std::fabs(b.angular_velocity) * b.max_extent <= threshold;
        b.sleep_time = resting ? b.sleep_time + time_step : 0.0f;
        rest_islands_[std::size_t(k)] = links_.islands.rest_slot(index);
        rest_times_[std::size_t(k)] = b.sleep_time;
        flags |= b.type == BodyType::kinematic ? kinematic_rest : 0;
    }
    const bool moved = !(b.transform.p == start.p && b.transform.q.c == start.q.c && b.transform.q.s == start.q.s);
    flags |= moved ? body_moved : 0;
    flags |= terms.enable_continuous && is_fast(b, s, time_step) ? fast_body : 0;
    flags |= finite ? 0 : non_finite_state;
    final_flags_[std::size_t(k)] = flags;
}

void BodyPass::finish(const StepContext& step) {
    const std::vector<int32_t>& awake = links_.islands.awake_bodies();
    const bool sleep = step.settings.enable_sleep;
    fast_bodies_.clear();
    non_finite_bodies_.clear();
    for (std::size_t k = 0; k < awake.size(); ++k) {
        const uint8_t flags = final_flags_[k];
        if (sleep) {
            links_.islands.note_rest_time_in_slot(rest_islands_[k], rest_times_[k]);
        }
        if (flags & fast_body) {
            fast_bodies_.push_back(awake[k]);
        }
        if (flags & non_finite_state) {
            non_finite_bodies_.push_back(awake[k]);
        }
        if (flags & kinematic_rest) {
            share_kinematic_rest(awake[k]);
        }
    }
    for (const std::vector<ProxyMove>& part : moves_) {
        for (const ProxyMove& move : part) {
            links_.broad_phase.move_proxy(move.key, move.fat_aabb, move.ahead_aabb);
        }
    }
}

// Walking each moved body's shapes for the ones the final pass enlarged (a read of each
// shape, scattered through the pool) was a third of what finish() did on one thread
// while the other workers waited: rain's falling ragdolls move 5,000 proxies a step.
void BodyPass::gather_moves(const StepContext&, BodyPass& pass, const NoStageArg&, int32_t begin, int32_t end,
                            int32_t) {
    const std::vector<int32_t>& awake = pass.links_.islands.awake_bodies();
    const int64_t count = int64_t(awake.size());
    for (int32_t part = begin; part < end; ++part) {
        std::vector<ProxyMove>& moves = pass.moves_[part];
        moves.clear();
        const int64_t last = count * (part + 1) / move_parts;
        for (int64_t k = count * part / move_parts; k < last; ++k) {
            if (pass.final_flags_[std::size_t(k)] & proxies_enlarged) {
                take_enlarged_shapes(pass.links_.bodies[awake[std::size_t(k)]], pass.links_.shapes,
                                     [&moves](const Shape& shape) {
                                         moves.push_back({shape.proxy_key, shape.fat_aabb, shape.ahead_aabb});
                                     });
            }
        }
    }
}

// A moving kinematic body keeps what it touches or holds by a joint awake: those islands
// rest no longer than it does.
void BodyPass::share_kinematic_rest(int32_t body) {
    const float rest = links_.bodies[body].sleep_time;
    const Pool<Contact>& contacts = links_.contacts.pool();
    links_.contacts.visit_contacts(body, [&](int32_t contact, int32_t other) {
        const Contact& c = contacts[contact];
        const Body& o = links_.bodies[other];
        if (is_solvable(c) && o.type == BodyType::dynamic && o.awake_index != null_index) {
            links_.islands.note_rest_time(other, rest);
        }
    });
    links_.joints.visit_joints(body, [&](int32_t, int32_t other) {
        const Body& o = links_.bodies[other];
        if (o.type == BodyType::dynamic && o.awake_index != null_index) {
            links_.islands.note_rest_time(other, rest);
        }
    });
}

}  // namespace i2d
