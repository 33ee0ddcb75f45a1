// SPDX-License-Identifier: MIT
// The hinge kernels: warm start and solve of revolute joints (hinge_columns.hpp), W at a
// time, written once over a lane type like the contact kernels and compiled for each
// instruction set.
//
// Every lane performs exactly the operations of the scalar revolute joint
// (joint_revolute.cpp, joint_constraint.hpp) in the same order, so a hinge gives the same
// bits whichever path solves it, and whichever run of a colour it falls in: the spring,
// motor and limit rows on the relative angle, then the anchors turned by the bodies'
// rotations in the step, the 2x2 point mass solved by its inverse determinant, the
// impulse with the rigid row's softness, and the guard that undoes a pass that would
// leave a body running away. Branches of the scalar code become blends that give the
// same bits, even for a NaN or the sign of a zero; a row no lane has is skipped.
#pragma once

#include <cstdint>

#include "core/force_inline.hpp"
#include "dynamics/solver/body_state.hpp"
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/joint/hinge_columns.hpp"

namespace i2d {

/// One chunk of hinges: their masses and anchors as the contact kernels hold a contact's
/// (there is no normal), the anchors turned by the bodies' rotations.
template <class L>
struct HingeLanes {
    using F = typename L::F;
    PairLanes<L> masses;
    PointLanes<L> anchors;

    I2D_FORCE_INLINE static HingeLanes load(const HingeColumns& h, int32_t k, const BodyLanes<L>& a,
                                            const BodyLanes<L>& b) {
        const F ax = L::load_unaligned(h.anchor_ax + k), ay = L::load_unaligned(h.anchor_ay + k);
        const F bx = L::load_unaligned(h.anchor_bx + k), by = L::load_unaligned(h.anchor_by + k);
        const F zero = L::splat(0.0f);
        return {{L::load_unaligned(h.inv_mass_a + k), L::load_unaligned(h.inv_mass_b + k),
                 L::load_unaligned(h.inv_inertia_a + k), L::load_unaligned(h.inv_inertia_b + k), zero, zero},
                {a.dqc * ax - a.dqs * ay, a.dqs * ax + a.dqc * ay, b.dqc * bx - b.dqs * by, b.dqs * bx + b.dqc * by}};
    }
};

/// The accumulated impulses of a chunk.
template <class L>
struct HingeImpulses {
    typename L::F x, y, spring, motor, lower, upper;

    I2D_FORCE_INLINE static HingeImpulses load(const HingeColumns& h, int32_t k) {
        return {L::load_unaligned(h.impulse_x + k),      L::load_unaligned(h.impulse_y + k),
                L::load_unaligned(h.spring_impulse + k), L::load_unaligned(h.motor_impulse + k),
                L::load_unaligned(h.lower_impulse + k),  L::load_unaligned(h.upper_impulse + k)};
    }
    I2D_FORCE_INLINE void store(const HingeColumns& h, int32_t k) const {
        L::store_unaligned(h.impulse_x + k, x);
        L::store_unaligned(h.impulse_y + k, y);
        L::store_unaligned(h.spring_impulse + k, spring);
        L::store_unaligned(h.motor_impulse + k, motor);
        L::store_unaligned(h.lower_impulse + k, lower);
        L::store_unaligned(h.upper_impulse + k, upper);
    }
};

// apply_angular, on the lanes that have the row.
template <class L>
I2D_FORCE_INLINE void apply_hinge_spin(Velocities<L>& v, const HingeLanes<L>& c, typename L::M has,
                                       typename L::F impulse) {
    v.wa = L::blend(has, v.wa, v.wa - c.masses.ia * impulse);
    v.wb = L::blend(has, v.wb, v.wb + c.masses.ib * impulse);
}

// unwind_angle: into (-pi, pi], one turn at most (its input is within (-2 pi, 2 pi)).
template <class L>
I2D_FORCE_INLINE typename L::F unwind_lanes(typename L::F angle) {
    constexpr float pi = 3.14159265f, two_pi = 6.28318531f;
    const typename L::F wound = L::blend(L::gt(angle, L::splat(pi)), angle, angle - L::splat(two_pi));
    return L::blend(L::ge(L::splat(-pi), angle), wound, angle + L::splat(two_pi));
}

// joint_atan2, branch for branch: |x| as x < 0 ? -x : x (so -0 stays -0), 0 where both are 0.
template <class L>
I2D_FORCE_INLINE typename L::F atan2_lanes(typename L::F y, typename L::F x) {
    using F = typename L::F;
    const F zero = L::splat(0.0f);
    const F ax = L::blend(L::lt(x, zero), x, -x), ay = L::blend(L::lt(y, zero), y, -y);
    const typename L::M x_wider = L::gt(ax, ay);
    const F big = L::blend(x_wider, ay, ax), small = L::blend(x_wider, ax, ay);
    const F t = small / big, t2 = t * t;
    F r = ((((L::splat(0.0208351f) * t2 - L::splat(0.0851330f)) * t2 + L::splat(0.1801410f)) * t2 -
            L::splat(0.3302995f)) * t2 + L::splat(0.9998660f)) * t;
    r = L::blend(L::gt(ay, ax), r, L::splat(1.57079633f) - r);
    r = L::blend(L::lt(x, zero), r, L::splat(3.14159265f) - r);
    r = L::blend(L::lt(y, zero), r, -r);
    return L::blend(L::eq(big, zero), r, zero);
}

// current_angle: the step's start angle plus how far B turned relative to A.
template <class L>
I2D_FORCE_INLINE typename L::F hinge_angle(const HingeColumns& h, int32_t k, const BodyLanes<L>& a,
                                           const BodyLanes<L>& b) {
    const typename L::F y = a.dqc * b.dqs - a.dqs * b.dqc, x = a.dqc * b.dqc + a.dqs * b.dqs;
    return unwind_lanes<L>(L::load_unaligned(h.delta_angle + k) + atan2_lanes<L>(y, x));
}

// limit_impulse: `gap` inside the limit (negative past it), `cdot` the row's speed toward
// the inside; returns the impulse to apply and updates `accumulated`.
template <class L>
I2D_FORCE_INLINE typename L::F hinge_limit(typename L::F gap, typename L::F cdot, typename L::F mass,
                                           typename L::F& accumulated, const HingePass& pass) {
    using F = typename L::F;
    const F zero = L::splat(0.0f);
    const typename L::M inside = L::gt(gap, zero);
    const F push_bias = pass.use_bias ? L::splat(pass.bias_rate) * gap : zero;
    const F bias = L::blend(inside, push_bias, gap * L::splat(pass.inv_h));
    const F mass_scale = L::blend(inside, L::splat(pass.mass_scale), L::splat(1.0f));
    const F impulse_scale = L::blend(inside, L::splat(pass.impulse_scale), zero);
    const F impulse = ((-mass) * mass_scale) * (cdot + bias) - impulse_scale * accumulated;
    const F updated = L::max(accumulated + impulse, zero);
    const F applied = updated - accumulated;
    accumulated = updated;
    return applied;
}

// The spring, motor and limit rows (solve_revolute_rows), on the lanes that have them.
template <class L>
I2D_FORCE_INLINE void solve_hinge_rows(const HingeColumns& h, int32_t k, const BodyLanes<L>& a,
                                       const BodyLanes<L>& b, const HingeLanes<L>& c, Velocities<L>& v,
                                       HingeImpulses<L>& p, const HingePass& pass) {
    using F = typename L::F;
    using M = typename L::M;
    const F zero = L::splat(0.0f);
    const M spring = L::gt(L::load_unaligned(h.has_spring + k), zero);
    const M motor = L::gt(L::load_unaligned(h.has_motor + k), zero);
    const M limit = L::gt(L::load_unaligned(h.has_limit + k), zero);
    const bool any_spring = L::any(spring), any_motor = L::any(motor), any_limit = L::any(limit);
    if (!any_spring && !any_motor && !any_limit) {
        return;
    }
    const F mass = L::load_unaligned(h.axial_mass + k);
    const F angle = any_spring || any_limit ? hinge_angle<L>(h, k, a, b) : zero;
    if (any_spring) {
        const F error = unwind_lanes<L>(angle - L::load_unaligned(h.target_angle + k));
        const F impulse = (-mass) * (L::load_unaligned(h.spring_position_rate + k) * error +
                                     L::load_unaligned(h.spring_speed_scale + k) * (v.wb - v.wa)) -
                          L::load_unaligned(h.spring_impulse_scale + k) * p.spring;
        // spring_impulse: nothing in the relax pass for a spring that does not relax.
        const M acts = pass.use_bias ? spring : L::both(spring, L::gt(L::load_unaligned(h.spring_relaxes + k), zero));
        const F applied = L::blend(acts, zero, impulse);
        p.spring = L::blend(acts, p.spring, p.spring + impulse);
        apply_hinge_spin(v, c, spring, applied);
    }
    if (any_motor) {
        const F max_impulse = L::load_unaligned(h.max_motor_impulse + k);
        const F wanted = p.motor + mass * (L::load_unaligned(h.motor_speed + k) - (v.wb - v.wa));
        const F clamped = clamp_lanes<L>(wanted, -max_impulse, max_impulse);
        const F applied = clamped - p.motor;
        p.motor = L::blend(motor, p.motor, clamped);
        apply_hinge_spin(v, c, motor, applied);
    }
    if (any_limit) {
        F lower = p.lower, upper = p.upper;
        const F lower_applied =
            hinge_limit<L>(angle - L::load_unaligned(h.lower_angle + k), v.wb - v.wa, mass, lower, pass);
        p.lower = L::blend(limit, p.lower, lower);
        apply_hinge_spin(v, c, limit, lower_applied);
        const F upper_applied =
            hinge_limit<L>(L::load_unaligned(h.upper_angle + k) - angle, v.wa - v.wb, mass, upper, pass);
        p.upper = L::blend(limit, p.upper, upper);
        apply_hinge_spin(v, c, limit, -upper_applied);
    }
}

// |a| as the scalar guard takes it: max(a, -a) is exact, and NaN stays NaN.
template <class L>
I2D_FORCE_INLINE typename L::F magnitude(typename L::F a) {
    return L::max(a, -a);
}

// within_limits: the velocities' component sums under the runaway limits (NaN fails).
template <class L>
I2D_FORCE_INLINE typename L::M hinge_within_limits(const Velocities<L>& v, const HingePass& pass) {
    using F = typename L::F;
    const F speeds = (magnitude<L>(v.vax) + magnitude<L>(v.vay)) + (magnitude<L>(v.vbx) + magnitude<L>(v.vby));
    const F spins = magnitude<L>(v.wa) + magnitude<L>(v.wb);
    return L::both(L::ge(L::splat(pass.runaway_speed_sum), speeds), L::ge(L::splat(pass.runaway_spin_sum), spins));
}

// The end of a pass (guarded_pass): a lane that ran away takes back the velocities it
// loaded and gives up its impulses; then the velocities go back to the states that move.
template <class L>
I2D_FORCE_INLINE void finish_hinges(const HingeColumns& h, int32_t k, BodyState* states, const HingePass& pass,
                                    BodyLanes<L>& a, BodyLanes<L>& b, const Velocities<L>& loaded, Velocities<L> v,
                                    HingeImpulses<L> p) {
    const typename L::M ok = hinge_within_limits<L>(v, pass);
    if (!L::all(ok)) {
        const typename L::F zero = L::splat(0.0f);
        v = Velocities<L>::select(ok, loaded, v);
        // Every impulse a revolute joint has (it never uses JointImpulses' angular or axial).
        p = {L::blend(ok, zero, p.x),     L::blend(ok, zero, p.y),     L::blend(ok, zero, p.spring),
             L::blend(ok, zero, p.motor), L::blend(ok, zero, p.lower), L::blend(ok, zero, p.upper)};
    }
    p.store(h, k);
    v.write_to(a, b);
    a.scatter(states, h.state_a + k);
    b.scatter(states, h.state_b + k);
}

template <class L>
I2D_FORCE_INLINE void warm_start_hinges(const HingeColumns& h, int32_t k, BodyState* states, const HingePass& pass) {
    BodyLanes<L> a = BodyLanes<L>::gather(states, h.state_a + k);
    BodyLanes<L> b = BodyLanes<L>::gather(states, h.state_b + k);
    const HingeLanes<L> c = HingeLanes<L>::load(h, k, a, b);
    const Velocities<L> loaded = Velocities<L>::of(a, b);
    Velocities<L> v = loaded;
    const HingeImpulses<L> p = HingeImpulses<L>::load(h, k);
    // apply_linear: -P on A at its anchor, +P on B at its anchor, as a contact's impulse.
    apply_impulse(v, c.masses, c.anchors, p.x, p.y);
    // The rows' impulses whether or not the joint has the rows this step, in
    // warm_start_revolute's order.
    const typename L::F spin = ((p.spring + p.motor) + p.lower) - p.upper;
    v.wa = v.wa - c.masses.ia * spin;
    v.wb = v.wb + c.masses.ib * spin;
    finish_hinges<L>(h, k, states, pass, a, b, loaded, v, p);
}

template <class L>
I2D_FORCE_INLINE void solve_hinges(const HingeColumns& h, int32_t k, BodyState* states, const HingePass& pass) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, h.state_a + k);
    BodyLanes<L> b = BodyLanes<L>::gather(states, h.state_b + k);
    const HingeLanes<L> c = HingeLanes<L>::load(h, k, a, b);
    const Velocities<L> loaded = Velocities<L>::of(a, b);
    Velocities<L> v = loaded;
    HingeImpulses<L> p = HingeImpulses<L>::load(h, k);
    solve_hinge_rows<L>(h, k, a, b, c, v, p, pass);
    // The anchor row last: it is the one that must hold.
    const PointLanes<L>& r = c.anchors;
    const F zero = L::splat(0.0f);
    F bias_x = zero, bias_y = zero;
    if (pass.use_bias) {
        // current_separation: (dpB - dpA) + (centre B - centre A) + (rB - rA).
        const F rate = L::splat(pass.bias_rate);
        bias_x = rate * (((b.dpx - a.dpx) + L::load_unaligned(h.center_x + k)) + (r.rbx - r.rax));
        bias_y = rate * (((b.dpy - a.dpy) + L::load_unaligned(h.center_y + k)) + (r.rby - r.ray));
    }
    // relative_velocity: (vB + wB x rB) - (vA + wA x rA), w x r = (-w r.y, w r.x).
    const F cdot_x = ((v.vbx + (-v.wb) * r.rby) - (v.vax + (-v.wa) * r.ray)) + bias_x;
    const F cdot_y = ((v.vby + v.wb * r.rbx) - (v.vay + v.wa * r.rax)) + bias_y;
    // point_mass_matrix and solve22.
    const F m = c.masses.ma + c.masses.mb;
    const F k11 = (m + (r.ray * r.ray) * c.masses.ia) + (r.rby * r.rby) * c.masses.ib;
    const F k12 = (((-r.ray) * r.rax) * c.masses.ia) - ((r.rby * r.rbx) * c.masses.ib);
    const F k22 = (m + (r.rax * r.rax) * c.masses.ia) + (r.rbx * r.rbx) * c.masses.ib;
    const F det = k11 * k22 - k12 * k12;
    const F inv_det = L::blend(L::eq(det, zero), L::splat(1.0f) / det, zero);
    const F solved_x = inv_det * (k22 * cdot_x - k12 * cdot_y);
    const F solved_y = inv_det * (k11 * cdot_y - k12 * cdot_x);
    const F minus_mass_scale = L::splat(-pass.mass_scale), impulse_scale = L::splat(pass.impulse_scale);
    const F ix = minus_mass_scale * solved_x - impulse_scale * p.x;
    const F iy = minus_mass_scale * solved_y - impulse_scale * p.y;
    p.x = p.x + ix;
    p.y = p.y + iy;
    apply_impulse(v, c.masses, c.anchors, ix, iy);
    finish_hinges<L>(h, k, states, pass, a, b, loaded, v, p);
}

template <class L>
struct HingeKernelsOf {
    static void warm_start(const HingeColumns& h, int32_t first, int32_t count, BodyState* states,
                           const HingePass& pass) {
        for (int32_t k = first; k < first + count; k += L::width) {
            warm_start_hinges<L>(h, k, states, pass);
        }
    }
    static void solve(const HingeColumns& h, int32_t first, int32_t count, BodyState* states, const HingePass& pass) {
        for (int32_t k = first; k < first + count; k += L::width) {
            solve_hinges<L>(h, k, states, pass);
        }
    }
};

}  // namespace i2d
