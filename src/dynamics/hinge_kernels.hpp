// SPDX-License-Identifier: MIT
// The hinge kernels: warm start and solve of plain hinges (hinge_columns.hpp), W at a
// time, written once over a lane type like the contact kernels and compiled for each
// instruction set.
//
// Every lane performs exactly the operations of the scalar revolute joint
// (joint_revolute.cpp, joint_constraint.hpp) in the same order, so a hinge gives the same
// bits whichever path solves it, and whichever run of a colour it falls in: the anchors
// turned by the bodies' rotations in the step, the 2x2 point mass solved by its inverse
// determinant, the impulse with the rigid row's softness, and the guard that undoes a
// pass that would leave a body running away. Branches of the scalar code become blends
// that give the same bits, even for a NaN or the sign of a zero.
#pragma once

#include <cstdint>

#include "core/force_inline.hpp"
#include "dynamics/body_state.hpp"
#include "dynamics/contact_kernels.hpp"
#include "dynamics/hinge_columns.hpp"

namespace i2d {

/// One chunk of hinges: their fixed data, and the anchors turned by the bodies' rotations.
template <class L>
struct HingeLanes {
    using F = typename L::F;
    F ma, mb, ia, ib;
    F rax, ray, rbx, rby;

    I2D_FORCE_INLINE static HingeLanes load(const HingeColumns& h, int32_t k, const BodyLanes<L>& a,
                                            const BodyLanes<L>& b) {
        const F ax = L::load_unaligned(h.anchor_ax + k), ay = L::load_unaligned(h.anchor_ay + k);
        const F bx = L::load_unaligned(h.anchor_bx + k), by = L::load_unaligned(h.anchor_by + k);
        return {L::load_unaligned(h.inv_mass_a + k),
                L::load_unaligned(h.inv_mass_b + k),
                L::load_unaligned(h.inv_inertia_a + k),
                L::load_unaligned(h.inv_inertia_b + k),
                a.dqc * ax - a.dqs * ay,
                a.dqs * ax + a.dqc * ay,
                b.dqc * bx - b.dqs * by,
                b.dqs * bx + b.dqc * by};
    }
};

// -P on A at its anchor, +P on B at its anchor (apply_linear).
template <class L>
I2D_FORCE_INLINE void apply_hinge_impulse(Velocities<L>& v, const HingeLanes<L>& c, typename L::F px,
                                          typename L::F py) {
    v.vax = v.vax - c.ma * px;
    v.vay = v.vay - c.ma * py;
    v.wa = v.wa - c.ia * (c.rax * py - c.ray * px);
    v.vbx = v.vbx + c.mb * px;
    v.vby = v.vby + c.mb * py;
    v.wb = v.wb + c.ib * (c.rbx * py - c.rby * px);
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
                                    typename L::F px, typename L::F py) {
    using F = typename L::F;
    const typename L::M ok = hinge_within_limits<L>(v, pass);
    if (!L::all(ok)) {
        const F zero = L::splat(0.0f);
        v = Velocities<L>::select(ok, loaded, v);
        px = L::blend(ok, zero, px);
        py = L::blend(ok, zero, py);
        L::store_unaligned(h.angular_impulse + k, L::blend(ok, zero, L::load_unaligned(h.angular_impulse + k)));
        L::store_unaligned(h.reset + k, L::blend(ok, L::splat(1.0f), L::load_unaligned(h.reset + k)));
    }
    L::store_unaligned(h.impulse_x + k, px);
    L::store_unaligned(h.impulse_y + k, py);
    v.write_to(a, b);
    a.scatter(states, h.state_a + k);
    b.scatter(states, h.state_b + k);
}

template <class L>
I2D_FORCE_INLINE void warm_start_hinges(const HingeColumns& h, int32_t k, BodyState* states, const HingePass& pass) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, h.state_a + k);
    BodyLanes<L> b = BodyLanes<L>::gather(states, h.state_b + k);
    const HingeLanes<L> c = HingeLanes<L>::load(h, k, a, b);
    const Velocities<L> loaded = Velocities<L>::of(a, b);
    Velocities<L> v = loaded;
    const F px = L::load_unaligned(h.impulse_x + k), py = L::load_unaligned(h.impulse_y + k);
    apply_hinge_impulse(v, c, px, py);
    const F angular = L::load_unaligned(h.angular_impulse + k);
    v.wa = v.wa - c.ia * angular;
    v.wb = v.wb + c.ib * angular;
    finish_hinges<L>(h, k, states, pass, a, b, loaded, v, px, py);
}

template <class L>
I2D_FORCE_INLINE void solve_hinges(const HingeColumns& h, int32_t k, BodyState* states, const HingePass& pass) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, h.state_a + k);
    BodyLanes<L> b = BodyLanes<L>::gather(states, h.state_b + k);
    const HingeLanes<L> c = HingeLanes<L>::load(h, k, a, b);
    const Velocities<L> loaded = Velocities<L>::of(a, b);
    Velocities<L> v = loaded;
    const F zero = L::splat(0.0f);
    F bias_x = zero, bias_y = zero;
    if (pass.use_bias) {
        // current_separation: (dpB - dpA) + (centre B - centre A) + (rB - rA).
        const F rate = L::splat(pass.bias_rate);
        bias_x = rate * (((b.dpx - a.dpx) + L::load_unaligned(h.center_x + k)) + (c.rbx - c.rax));
        bias_y = rate * (((b.dpy - a.dpy) + L::load_unaligned(h.center_y + k)) + (c.rby - c.ray));
    }
    // relative_velocity: (vB + wB x rB) - (vA + wA x rA), w x r = (-w r.y, w r.x).
    const F cdot_x = ((v.vbx + (-v.wb) * c.rby) - (v.vax + (-v.wa) * c.ray)) + bias_x;
    const F cdot_y = ((v.vby + v.wb * c.rbx) - (v.vay + v.wa * c.rax)) + bias_y;
    // point_mass_matrix and solve22.
    const F m = c.ma + c.mb;
    const F k11 = (m + (c.ray * c.ray) * c.ia) + (c.rby * c.rby) * c.ib;
    const F k12 = (((-c.ray) * c.rax) * c.ia) - ((c.rby * c.rbx) * c.ib);
    const F k22 = (m + (c.rax * c.rax) * c.ia) + (c.rbx * c.rbx) * c.ib;
    const F det = k11 * k22 - k12 * k12;
    const F inv_det = L::blend(L::eq(det, zero), L::splat(1.0f) / det, zero);
    const F solved_x = inv_det * (k22 * cdot_x - k12 * cdot_y);
    const F solved_y = inv_det * (k11 * cdot_y - k12 * cdot_x);
    F px = L::load_unaligned(h.impulse_x + k), py = L::load_unaligned(h.impulse_y + k);
    const F minus_mass_scale = L::splat(-pass.mass_scale), impulse_scale = L::splat(pass.impulse_scale);
    const F ix = minus_mass_scale * solved_x - impulse_scale * px;
    const F iy = minus_mass_scale * solved_y - impulse_scale * py;
    px = px + ix;
    py = py + iy;
    apply_hinge_impulse(v, c, ix, iy);
    finish_hinges<L>(h, k, states, pass, a, b, loaded, v, px, py);
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
