// SPDX-License-Identifier: MIT
// JointSolver: the common part of preparing a joint, and the dispatch to its kind.
#include "dynamics/solver/joint_solver.hpp"

#include <cfloat>
#include <cmath>

#include "core/prefetch.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// Where a kind's anchors sit and what angle counts as zero. The motor joint aims B's
// origin at its offset point of A; the mouse joint's A plays no part.
struct JointFrame {
    Vec2 local_anchor_a, local_anchor_b;
    float reference_angle = 0.0f;
};

JointFrame frame_of(const JointDef& d) {
    switch (d.type) {
        case JointType::revolute: return {d.local_anchor_a, d.local_anchor_b, d.revolute.reference_angle};
        case JointType::prismatic: return {d.local_anchor_a, d.local_anchor_b, d.prismatic.reference_angle};
        case JointType::weld: return {d.local_anchor_a, d.local_anchor_b, d.weld.reference_angle};
        case JointType::motor: return {d.motor.linear_offset, Vec2{}, d.motor.angular_offset};
        default: return {d.local_anchor_a, d.local_anchor_b, 0.0f};
    }
}

// The constraints lie in solve order, but each reads its kind's settings (limits, motor,
// spring target) from the joint pool, in no order: a cache miss per joint per pass unless
// asked for a few joints ahead.
constexpr int32_t prefetch_settings_ahead = 4;

// Prepare and store read each constraint's joint (its first two lines: joint.hpp), and
// prepare reads the first two lines of its bodies, in solve order, which jumps through
// both pools: in rain, prepare stalled on those misses for 6 % of the step.
constexpr int32_t prefetch_joints_ahead = 8;
constexpr int32_t prefetch_joint_bodies_ahead = 4;

I2D_FORCE_INLINE void prefetch_joint(const std::vector<JointConstraint>& constraints, const Pool<Joint>& joints,
                                     int32_t k, int32_t end) {
    const int32_t ahead = k + prefetch_joints_ahead;
    if (ahead < end) {
        prefetch_lines(&joints[constraints[std::size_t(ahead)].joint], 2);
    }
}

// The joint was asked for prefetch_joints_ahead constraints earlier, so it is close.
I2D_FORCE_INLINE void prefetch_joint_bodies(const std::vector<JointConstraint>& constraints,
                                            const Pool<Joint>& joints, const Pool<Body>& bodies, int32_t k,
                                            int32_t end) {
    const int32_t ahead = k + prefetch_joint_bodies_ahead;
    if (ahead < end) {
        const JointDef& d = joints[constraints[std::size_t(ahead)].joint].def;
        prefetch_lines(&bodies[d.body_a], 2);
        prefetch_lines(&bodies[d.body_b], 2);
    }
}

// The address only: the kind comes from the constraint, so that asking ahead reads
// nothing from the joint pool itself.
I2D_FORCE_INLINE const void* kind_settings(const JointConstraint& c) {
    const JointDef* d = c.def;
    switch (c.type) {
        case JointType::revolute: return &d->revolute;
        case JointType::prismatic: return &d->prismatic;
        case JointType::distance: return &d->distance;
        case JointType::weld: return &d->weld;
        case JointType::wheel: return &d->wheel;
        case JointType::motor: return &d->motor;
        case JointType::mouse: return &d->mouse;
        default: return d;
    }
}

// A revolute joint none of whose rows a tree's exact pass holds: its whole pass is the
// hinge kernels'.
bool is_lane_hinge(const JointConstraint& c) { return c.type == JointType::revolute && c.exact_rows == 0; }

// A revolute joint reads its settings in the pass only when it has rows and a tree holds
// it: the hinge kernels read theirs from the columns.
I2D_FORCE_INLINE bool reads_settings(const JointConstraint& c) {
    return c.type != JointType::revolute || (c.rows != 0 && !is_lane_hinge(c));
}

I2D_FORCE_INLINE void prefetch_settings(const std::vector<JointConstraint>& constraints, int32_t k, int32_t end) {
    const int32_t ahead = k + prefetch_settings_ahead;
    if (ahead < end && reads_settings(constraints[std::size_t(ahead)])) {
        const char* settings = static_cast<const char*>(kind_settings(constraints[std::size_t(ahead)]));
        prefetch_line(settings);
        prefetch_line(settings + 63);  // a kind's settings may straddle two lines
    }
}

// The columns of HingeColumns that hold floats, in its order.
constexpr std::size_t hinge_float_columns = 30;

// A side the joint can move: a dynamic body that is awake.
bool can_move(const Body& b) { return b.type == BodyType::dynamic && b.awake_index != null_index; }

}  // namespace

void JointSolver::lay_out(const int32_t* ordered, int32_t count) {
    breaking_seen_.store(false, std::memory_order_relaxed);
    const std::size_t n = std::size_t(count);
    constraints_.resize(n);
    for (int32_t k = 0; k < count; ++k) {
        constraints_[std::size_t(k)].joint = ordered[k];
    }
    lane_hinge_.resize(n);
    hinge_states_.resize(2 * n);
    hinge_values_.resize(hinge_float_columns * n);
    float* column = hinge_values_.data();
    const auto next = [&column, n]() {
        float* c = column;
        column += n;
        return c;
    };
    hinges_.state_a = hinge_states_.data();
    hinges_.state_b = hinge_states_.data() + n;
    hinges_.inv_mass_a = next();
    hinges_.inv_mass_b = next();
    hinges_.inv_inertia_a = next();
    hinges_.inv_inertia_b = next();
    hinges_.anchor_ax = next();
    hinges_.anchor_ay = next();
    hinges_.anchor_bx = next();
    hinges_.anchor_by = next();
    hinges_.center_x = next();
    hinges_.center_y = next();
    hinges_.has_spring = next();
    hinges_.has_motor = next();
    hinges_.has_limit = next();
    hinges_.delta_angle = next();
    hinges_.axial_mass = next();
    hinges_.spring_position_rate = next();
    hinges_.spring_speed_scale = next();
    hinges_.spring_impulse_scale = next();
    hinges_.spring_relaxes = next();
    hinges_.target_angle = next();
    hinges_.motor_speed = next();
    hinges_.max_motor_impulse = next();
    hinges_.lower_angle = next();
    hinges_.upper_angle = next();
    hinges_.impulse_x = next();
    hinges_.impulse_y = next();
    hinges_.spring_impulse = next();
    hinges_.motor_impulse = next();
    hinges_.lower_impulse = next();
    hinges_.upper_impulse = next();
}

void JointSolver::load_hinge(const JointStep& step, int32_t k, const JointConstraint& c) {
    const std::size_t i = std::size_t(k);
    const JointImpulses& p = c.impulses;
    hinges_.state_a[i] = c.state_a;
    hinges_.state_b[i] = c.state_b;
    hinges_.inv_mass_a[i] = c.inv_mass_a;
    hinges_.inv_mass_b[i] = c.inv_mass_b;
    hinges_.inv_inertia_a[i] = c.inv_inertia_a;
    hinges_.inv_inertia_b[i] = c.inv_inertia_b;
    hinges_.anchor_ax[i] = c.anchor_a.x;
    hinges_.anchor_ay[i] = c.anchor_a.y;
    hinges_.anchor_bx[i] = c.anchor_b.x;
    hinges_.anchor_by[i] = c.anchor_b.y;
    hinges_.center_x[i] = c.delta_center.x;
    hinges_.center_y[i] = c.delta_center.y;
    const RevoluteSettings& s = c.def->revolute;
    const auto flag = [](bool on) { return on ? 1.0f : 0.0f; };
    hinges_.has_spring[i] = flag((c.rows & spring_row) != 0);
    hinges_.has_motor[i] = flag((c.rows & motor_row) != 0);
    hinges_.has_limit[i] = flag((c.rows & limit_row) != 0);
    hinges_.delta_angle[i] = c.delta_angle;
    hinges_.axial_mass[i] = c.axial_mass;
    hinges_.spring_position_rate[i] = c.spring.position_rate;
    hinges_.spring_speed_scale[i] = c.spring.speed_scale;
    hinges_.spring_impulse_scale[i] = c.spring.impulse_scale;
    hinges_.spring_relaxes[i] = flag(c.spring.relaxes);
    hinges_.target_angle[i] = s.target_angle;
    hinges_.motor_speed[i] = s.motor_speed;
    hinges_.max_motor_impulse[i] = step.h * s.max_motor_torque;
    hinges_.lower_angle[i] = s.lower_angle;
    hinges_.upper_angle[i] = s.upper_angle;
    hinges_.impulse_x[i] = p.linear.x;
    hinges_.impulse_y[i] = p.linear.y;
    hinges_.spring_impulse[i] = p.spring;
    hinges_.motor_impulse[i] = p.motor;
    hinges_.lower_impulse[i] = p.lower;
    hinges_.upper_impulse[i] = p.upper;
}

void JointSolver::prepare_one(const JointStep& step, JointConstraint& c, const Joint& joint, const Pool<Body>& bodies,
                              int32_t fixed_state) const {
    const JointDef& d = joint.def;
    const Body& a = bodies[d.body_a];
    const Body& b = bodies[d.body_b];
    const bool mouse = d.type == JointType::mouse;
    c.def = &d;
    c.type = d.type;
    c.breakable = d.force_threshold < FLT_MAX || d.torque_threshold < FLT_MAX;
    c.moves_a = !mouse && can_move(a);
    c.moves_b = can_move(b);
    // Kinematic bodies are read from their own state (they move); static and sleeping
    // ones, and the mouse joint's A, from the fixed one.
    c.state_a = !mouse && a.awake_index != null_index ? a.awake_index : fixed_state;
    c.state_b = b.awake_index != null_index ? b.awake_index : fixed_state;
    c.inv_mass_a = c.moves_a ? a.inv_mass : 0.0f;
    c.inv_inertia_a = c.moves_a ? a.inv_inertia : 0.0f;
    c.inv_mass_b = c.moves_b ? b.inv_mass : 0.0f;
    c.inv_inertia_b = c.moves_b ? b.inv_inertia : 0.0f;
    const JointFrame f = frame_of(d);
    c.anchor_a = mouse ? Vec2{} : rotate(a.transform.q, f.local_anchor_a - a.local_center);
    c.anchor_b = rotate(b.transform.q, f.local_anchor_b - b.local_center);
    c.delta_center = b.center - (mouse ? d.mouse.target : a.center);
    // The exact angle costs a tenth of a plain hinge's step: only the kinds that read it.
    const bool reads_angle = d.type == JointType::prismatic || d.type == JointType::weld ||
                             d.type == JointType::motor ||
                             (d.type == JointType::revolute && (d.revolute.enable_limit || d.revolute.enable_spring));
    c.delta_angle =
        reads_angle ? unwind_angle(exact_relative_angle(a.transform.q, b.transform.q) - f.reference_angle) : 0.0f;
    // Only the sliding kinds have an axis: reading another kind's would cost a cache line.
    c.axis = Vec2{};
    if (d.type == JointType::prismatic) {
        c.axis = rotate(a.transform.q, d.prismatic.local_axis_a);
    } else if (d.type == JointType::wheel) {
        c.axis = rotate(a.transform.q, d.wheel.local_axis_a);
    }
    c.impulses = joint.impulses;
    switch (d.type) {
        case JointType::revolute: prepare_revolute(c, step); break;
        case JointType::prismatic: prepare_prismatic(c, step); break;
        case JointType::distance: prepare_distance(c, step); break;
        case JointType::weld: prepare_weld(c, step); break;
        case JointType::wheel: prepare_wheel(c, step); break;
        case JointType::motor: prepare_motor(c, step); break;
        case JointType::mouse: prepare_mouse(c, step); break;
        default: break;
    }
}

void JointSolver::prepare(const JointStep& step, const Pool<Joint>& joints, const Pool<Body>& bodies,
                          int32_t fixed_state, int32_t begin, int32_t end) {
    for (int32_t k = begin; k < end; ++k) {
        prefetch_joint(constraints_, joints, k, end);
        prefetch_joint_bodies(constraints_, joints, bodies, k, end);
        JointConstraint& c = constraints_[std::size_t(k)];
        prepare_one(step, c, joints[c.joint], bodies, fixed_state);
        const bool hinge = is_lane_hinge(c);
        lane_hinge_[std::size_t(k)] = hinge ? 1 : 0;
        if (hinge) {
            load_hinge(step, k, c);
        }
    }
}

int32_t JointSolver::hinge_run_end(int32_t begin, int32_t end) const {
    int32_t k = begin;
    while (k < end && lane_hinge_[std::size_t(k)] != 0) {
        ++k;
    }
    return k;
}

HingePass JointSolver::hinge_pass(const JointStep& step, bool use_bias) {
    const Softness soft = rigid_pass(step, use_bias);
    return {step.inv_h, soft.bias_rate,         soft.mass_scale,       soft.impulse_scale,
            use_bias,   step.runaway_speed_sum, step.runaway_spin_sum};
}

void JointSolver::run_hinges(HingeKernel ContactKernels::*kernel, int32_t begin, int32_t end, BodyState* states,
                             const HingePass& pass, bool independent) const {
    const ContactKernels& scalar = scalar_contact_kernels();
    const ContactKernels& wide = independent ? *kernels_ : scalar;
    const int32_t whole = (end - begin) / wide.width * wide.width;
    if (whole > 0) {
        (wide.*kernel)(hinges_, begin, whole, states, pass);
    }
    if (begin + whole < end) {
        (scalar.*kernel)(hinges_, begin + whole, end - begin - whole, states, pass);
    }
}

// Each kind runs its pass through guarded_pass (joint_constraint.hpp) in its own file, so
// that the bodies' velocities stay in registers from load to store: passed to a kind's
// functions by reference, they went through memory between the call and the guard, a
// third of a joint_grid step's joint time.
void JointSolver::warm_start(const JointStep& step, int32_t begin, int32_t end, BodyState* states, bool independent) {
    const HingePass pass = hinge_pass(step, true);
    for (int32_t k = begin; k < end; ++k) {
        if (lane_hinge_[std::size_t(k)] != 0) {
            const int32_t run_end = hinge_run_end(k, end);
            run_hinges(&ContactKernels::warm_start_hinges, k, run_end, states, pass, independent);
            k = run_end - 1;
            continue;
        }
        JointConstraint& c = constraints_[std::size_t(k)];
        switch (c.type) {
            case JointType::revolute: warm_start_revolute(c, states, step); break;
            case JointType::prismatic: warm_start_prismatic(c, states, step); break;
            case JointType::distance: warm_start_distance(c, states, step); break;
            case JointType::weld: warm_start_weld(c, states, step); break;
            case JointType::wheel: warm_start_wheel(c, states, step); break;
            case JointType::motor: warm_start_motor(c, states, step); break;
            case JointType::mouse: warm_start_mouse(c, states, step); break;
            default: break;
        }
    }
}

void JointSolver::solve(const JointStep& step, int32_t begin, int32_t end, BodyState* states, bool use_bias,
                        bool independent) {
    const HingePass pass = hinge_pass(step, use_bias);
    for (int32_t k = begin; k < end; ++k) {
        if (lane_hinge_[std::size_t(k)] != 0) {
            const int32_t run_end = hinge_run_end(k, end);
            run_hinges(&ContactKernels::solve_hinges, k, run_end, states, pass, independent);
            k = run_end - 1;
            continue;
        }
        prefetch_settings(constraints_, k, end);
        JointConstraint& c = constraints_[std::size_t(k)];
        switch (c.type) {
            case JointType::revolute: solve_revolute(c, states, step, use_bias); break;
            case JointType::prismatic: solve_prismatic(c, states, step, use_bias); break;
            case JointType::distance: solve_distance(c, states, step, use_bias); break;
            case JointType::weld: solve_weld(c, states, step, use_bias); break;
            case JointType::wheel: solve_wheel(c, states, step, use_bias); break;
            case JointType::motor: solve_motor(c, states, step, use_bias); break;
            case JointType::mouse: solve_mouse(c, states, step, use_bias); break;
            default: break;
        }
    }
}

// The impulses the hinge's kernels left in the columns: all a revolute joint has (a pass
// the guard undid left them zero).
void JointSolver::take_hinge_impulses(int32_t k, JointConstraint& c) const {
    const std::size_t i = std::size_t(k);
    c.impulses.linear = {hinges_.impulse_x[i], hinges_.impulse_y[i]};
    c.impulses.spring = hinges_.spring_impulse[i];
    c.impulses.motor = hinges_.motor_impulse[i];
    c.impulses.lower = hinges_.lower_impulse[i];
    c.impulses.upper = hinges_.upper_impulse[i];
}

namespace {

bool passes_threshold(const Joint& joint) {
    return length(joint.reaction_force) > joint.def.force_threshold ||
           std::fabs(joint.reaction_torque) > joint.def.torque_threshold;
}

}  // namespace

void JointSolver::store(const JointStep& step, Pool<Joint>& joints, const BodyState* states, int32_t begin,
                        int32_t end) {
    bool breaking = false;
    for (int32_t k = begin; k < end; ++k) {
        prefetch_joint(constraints_, joints, k, end);
        JointConstraint& c = constraints_[std::size_t(k)];
        if (lane_hinge_[std::size_t(k)] != 0) {
            take_hinge_impulses(k, c);
        }
        Joint& joint = joints[c.joint];
        joint.impulses = c.impulses;
        const JointReaction r = joint_reaction(c, load_bodies(c, states), step.inv_h);
        joint.reaction_force = r.force;
        joint.reaction_torque = r.torque;
        joint.motor_output = r.motor;
        breaking = breaking || (c.breakable && passes_threshold(joint));
    }
    if (breaking) {
        breaking_seen_.store(true, std::memory_order_relaxed);
    }
}

void JointSolver::report_breaking(const Pool<Joint>& joints, const IdEncoder& ids,
                                  std::vector<JointEvent>& out) const {
    if (!breaking_seen_.load(std::memory_order_relaxed)) {
        return;
    }
    for (const JointConstraint& c : constraints_) {
        const Joint& joint = joints[c.joint];
        if (c.breakable && passes_threshold(joint)) {
            out.push_back({ids.joint_id(c.joint, joints.generation(c.joint)), joint.def.user_data});
        }
    }
}

}  // namespace i2d
