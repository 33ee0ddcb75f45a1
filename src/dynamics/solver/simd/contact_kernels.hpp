// SPDX-License-Identifier: MIT
// The contact kernels of the soft step, written once over a lane type (lanes_*.hpp) and
// compiled for each instruction set: warm start, solve (with push-out) or relax, and the
// restitution pass, W contacts at a time.
//
// The physics is the contact solver's (contact_solver.hpp says what and why); this file
// is its arithmetic. Every lane performs the same operations in the same order whatever
// the lane type, with no fused multiply-add and no approximate reciprocal, so that a
// world gives the same bits on the scalar, SSE2 and AVX2 paths. Choices that differ per
// contact (speculative or overlapping, the 2x2 block case, a second point or not,
// whether rolling resistance applies) blend both outcomes per lane, and whatever does
// not apply to a lane leaves its bits alone (not even the sign of a zero changes), so
// that a block may skip work no lane needs and still give every lane the same bits: a
// block of single points skips point 2, a block where no point is still approaching
// skips the impact tracking, and a block skips what none of its lanes uses (its
// BlockUses: rolling, moving surfaces, impact speeds, the largest push). The lane types
// live in anonymous namespaces, so each translation unit's kernels are its own.
#pragma once

#include <cstdint>

#include "core/force_inline.hpp"
#include "dynamics/solver/body_state.hpp"
#include "dynamics/solver/simd/contact_block.hpp"

namespace i2d {

template <class L>
struct BodyLanes {
    typename L::F vx, vy, w, moves, dpx, dpy, dqc, dqs;

    I2D_FORCE_INLINE static BodyLanes gather(const BodyState* states, const int32_t* index) {
        typename L::F f[8];
        L::gather(states, index, f);
        return {f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7]};
    }
    I2D_FORCE_INLINE void scatter(BodyState* states, const int32_t* index) const {
        L::scatter(states, index, vx, vy, w, moves);
    }
};

/// The bodies' velocities while a block is solved.
template <class L>
struct Velocities {
    using F = typename L::F;
    F vax, vay, wa, vbx, vby, wb;

    I2D_FORCE_INLINE static Velocities of(const BodyLanes<L>& a, const BodyLanes<L>& b) {
        return {a.vx, a.vy, a.w, b.vx, b.vy, b.w};
    }
    I2D_FORCE_INLINE static Velocities select(typename L::M m, const Velocities& if_false, const Velocities& if_true) {
        return {L::blend(m, if_false.vax, if_true.vax), L::blend(m, if_false.vay, if_true.vay),
                L::blend(m, if_false.wa, if_true.wa),   L::blend(m, if_false.vbx, if_true.vbx),
                L::blend(m, if_false.vby, if_true.vby), L::blend(m, if_false.wb, if_true.wb)};
    }
    I2D_FORCE_INLINE void write_to(BodyLanes<L>& a, BodyLanes<L>& b) const {
        a.vx = vax, a.vy = vay, a.w = wa;
        b.vx = vbx, b.vy = vby, b.w = wb;
    }
};

/// The constraint's fixed data in lanes.
template <class L>
struct PairLanes {
    using F = typename L::F;
    F ma, mb, ia, ib, nx, ny;

    template <int W>
    I2D_FORCE_INLINE static PairLanes load(const ContactBlock<W>& c) {
        return {L::load(c.inv_mass_a),    L::load(c.inv_mass_b), L::load(c.inv_inertia_a),
                L::load(c.inv_inertia_b), L::load(c.normal_x),   L::load(c.normal_y)};
    }
    // The tangent is left_perp(normal).
    I2D_FORCE_INLINE F tx() const { return -ny; }
    I2D_FORCE_INLINE F ty() const { return nx; }
};

/// One contact point's anchors in lanes.
template <class L>
struct PointLanes {
    using F = typename L::F;
    F rax, ray, rbx, rby;

    template <int W>
    I2D_FORCE_INLINE static PointLanes load(const ContactPointLanes<W>& p) {
        return {L::load(p.anchor_ax), L::load(p.anchor_ay), L::load(p.anchor_bx), L::load(p.anchor_by)};
    }
};

template <class L>
I2D_FORCE_INLINE typename L::M nonzero(typename L::F a) {
    return L::either(L::lt(a, L::splat(0.0f)), L::gt(a, L::splat(0.0f)));
}

// 1 / k where k > 0, else 0: the mass of a row from its inverse, 0 for a row that no body
// can move along.
template <class L>
I2D_FORCE_INLINE typename L::F positive_inverse(typename L::F k) {
    return L::blend(L::gt(k, L::splat(0.0f)), L::splat(0.0f), L::splat(1.0f) / k);
}

template <class L>
I2D_FORCE_INLINE typename L::M all_lanes() {
    return L::eq(L::splat(0.0f), L::splat(0.0f));
}

// a < lo ? lo : (a > hi ? hi : a)
template <class L>
I2D_FORCE_INLINE typename L::F clamp_lanes(typename L::F a, typename L::F lo, typename L::F hi) {
    return L::blend(L::lt(a, lo), L::blend(L::gt(a, hi), a, hi), lo);
}

// (vB + wB x rB) - (vA + wA x rA), along (dx, dy); w x r = (-w r.y, w r.x).
template <class L>
I2D_FORCE_INLINE typename L::F relative_speed(const Velocities<L>& v, const PointLanes<L>& p, typename L::F dx,
                                              typename L::F dy) {
    const typename L::F rvx = (v.vbx + (-v.wb) * p.rby) - (v.vax + (-v.wa) * p.ray);
    const typename L::F rvy = (v.vby + v.wb * p.rbx) - (v.vay + v.wa * p.rax);
    return rvx * dx + rvy * dy;
}

// A takes -P at its anchor, B takes +P at its anchor.
template <class L>
I2D_FORCE_INLINE void apply_impulse(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L>& p, typename L::F px,
                                    typename L::F py) {
    v.vax = v.vax - c.ma * px;
    v.vay = v.vay - c.ma * py;
    v.wa = v.wa - c.ia * (p.rax * py - p.ray * px);
    v.vbx = v.vbx + c.mb * px;
    v.vby = v.vby + c.mb * py;
    v.wb = v.wb + c.ib * (p.rbx * py - p.rby * px);
}

/// How one point is solved this pass: impulse = -mass (mass_scale vn + bias) - impulse_scale x.
template <class L>
struct PointTerms {
    typename L::F bias, mass_scale, impulse_scale;
};

/// A point's accumulated normal impulse and its largest change this step.
template <class L>
struct PointImpulse {
    typename L::F normal, max_normal;

    I2D_FORCE_INLINE static PointImpulse select(typename L::M m, const PointImpulse& if_false,
                                                const PointImpulse& if_true) {
        return {L::blend(m, if_false.normal, if_true.normal), L::blend(m, if_false.max_normal, if_true.max_normal)};
    }
};

// The new accumulated normal impulse: the change is applied and the largest change kept.
template <class L>
I2D_FORCE_INLINE void set_normal_impulse(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L>& p,
                                         PointImpulse<L>& x, typename L::F impulse) {
    const typename L::F change = impulse - x.normal;
    x.max_normal = L::max(x.max_normal, change);
    apply_impulse(v, c, p, change * c.nx, change * c.ny);
    x.normal = impulse;
}

template <class L>
I2D_FORCE_INLINE void solve_normal_point(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L>& p,
                                         typename L::F normal_mass, const PointTerms<L>& t, PointImpulse<L>& x) {
    using F = typename L::F;
    const F vn = relative_speed(v, p, c.nx, c.ny);
    const F impulse = (-normal_mass) * (t.mass_scale * vn + t.bias) - t.impulse_scale * x.normal;
    set_normal_impulse(v, c, p, x, L::max(x.normal + impulse, L::splat(0.0f)));
}

/// Both points of a two-point manifold as one 2x2 linear complementarity problem: find
/// x >= 0 with w = K (x - (1 - impulse_scale) x_old) + mass_scale vn + bias >= 0 and
/// x_i w_i = 0, trying both, first only, second only, neither. Returns per lane whether
/// both points took part, K was well conditioned and a case fitted; the other lanes keep
/// their inputs, for the caller to solve point by point.
template <class L>
I2D_FORCE_INLINE typename L::M solve_normal_block(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L> p[2],
                                                  const typename L::F mass[2], const PointTerms<L> t[2],
                                                  PointImpulse<L> x[2], typename L::M both_points) {
    using F = typename L::F;
    using M = typename L::M;
    constexpr float max_condition = 1000.0f;
    const F zero = L::splat(0.0f), one = L::splat(1.0f);
    const F rn1a = p[0].rax * c.ny - p[0].ray * c.nx, rn1b = p[0].rbx * c.ny - p[0].rby * c.nx;
    const F rn2a = p[1].rax * c.ny - p[1].ray * c.nx, rn2b = p[1].rbx * c.ny - p[1].rby * c.nx;
    const F m = c.ma + c.mb;
    const F k11 = m + c.ia * rn1a * rn1a + c.ib * rn1b * rn1b;
    const F k22 = m + c.ia * rn2a * rn2a + c.ib * rn2b * rn2b;
    const F k12 = m + c.ia * rn1a * rn2a + c.ib * rn1b * rn2b;
    const F det = k11 * k22 - k12 * k12;
    const M conditioned = L::both(both_points, L::lt(k11 * k11, L::splat(max_condition) * det));
    const F kept1 = (one - t[0].impulse_scale) * x[0].normal;
    const F kept2 = (one - t[1].impulse_scale) * x[1].normal;
    const F vn1 = relative_speed(v, p[0], c.nx, c.ny);
    const F vn2 = relative_speed(v, p[1], c.nx, c.ny);
    const F q1 = t[0].mass_scale * vn1 + t[0].bias - (k11 * kept1 + k12 * kept2);
    const F q2 = t[1].mass_scale * vn2 + t[1].bias - (k12 * kept1 + k22 * kept2);

    const F inv_det = one / det;
    const F both1 = (-inv_det) * (k22 * q1 - k12 * q2), both2 = (-inv_det) * (k11 * q2 - k12 * q1);
    // One point alone: its normal mass is 1 / k11 (or 1 / k22), made the same way.
    const F first = (-q1) * mass[0], second = (-q2) * mass[1];
    const M both_push = L::both(L::ge(both1, zero), L::ge(both2, zero));
    const M first_pushes = L::both(L::ge(first, zero), L::ge(k12 * first + q2, zero));
    const M second_pushes = L::both(L::ge(second, zero), L::ge(k12 * second + q1, zero));
    const M neither = L::both(L::ge(q1, zero), L::ge(q2, zero));
    const M fits =
        L::both(conditioned, L::either(L::either(both_push, first_pushes), L::either(second_pushes, neither)));
    const F x1 = L::blend(both_push, L::blend(first_pushes, zero, first), both1);
    const F x2 = L::blend(both_push, L::blend(first_pushes, L::blend(second_pushes, zero, second), zero), both2);

    Velocities<L> solved = v;
    PointImpulse<L> solved_x[2] = {x[0], x[1]};
    set_normal_impulse(solved, c, p[0], solved_x[0], x1);
    set_normal_impulse(solved, c, p[1], solved_x[1], x2);
    v = Velocities<L>::select(fits, v, solved);
    x[0] = PointImpulse<L>::select(fits, x[0], solved_x[0]);
    x[1] = PointImpulse<L>::select(fits, x[1], solved_x[1]);
    return fits;
}

/// The normal impulses of a block: the 2x2 block where both points are active and it
/// fits, else point by point over the active points. `any_second` is false when no lane
/// has an active second point: then point 2 is skipped, with the same result.
template <class L>
I2D_FORCE_INLINE void solve_normal(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L> p[2],
                                   const typename L::F mass[2], const PointTerms<L> t[2], PointImpulse<L> x[2],
                                   const typename L::M active[2], bool any_second) {
    if (!any_second) {
        const Velocities<L> before = v;
        const PointImpulse<L> before_x = x[0];
        solve_normal_point(v, c, p[0], mass[0], t[0], x[0]);
        v = Velocities<L>::select(active[0], before, v);
        x[0] = PointImpulse<L>::select(active[0], before_x, x[0]);
        return;
    }
    const Velocities<L> before = v;
    const PointImpulse<L> before_x[2] = {x[0], x[1]};
    const typename L::M fits = solve_normal_block(v, c, p, mass, t, x, L::both(active[0], active[1]));
    if (L::all(fits)) {
        return;
    }
    Velocities<L> single = before;
    PointImpulse<L> single_x[2] = {before_x[0], before_x[1]};
    for (int i = 0; i < 2; ++i) {
        const Velocities<L> prior = single;
        const PointImpulse<L> prior_x = single_x[i];
        solve_normal_point(single, c, p[i], mass[i], t[i], single_x[i]);
        single = Velocities<L>::select(active[i], prior, single);
        single_x[i] = PointImpulse<L>::select(active[i], prior_x, single_x[i]);
    }
    v = Velocities<L>::select(fits, single, v);
    x[0] = PointImpulse<L>::select(fits, single_x[0], x[0]);
    x[1] = PointImpulse<L>::select(fits, single_x[1], x[1]);
}

/// Per block: which lanes have a second point, and whether any does.
template <class L>
struct SecondPoint {
    typename L::M lanes;
    bool any;

    template <int W>
    I2D_FORCE_INLINE static SecondPoint of(const ContactBlock<W>& c) {
        const typename L::M lanes = L::gt(L::load(c.points[1].normal_mass), L::splat(0.0f));
        return {lanes, L::any(lanes)};
    }
};

template <class L, int W>
I2D_FORCE_INLINE void warm_start_block(ContactBlock<W>& c, uint8_t uses, BodyState* states) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    const SecondPoint<L> second = SecondPoint<L>::of(c);
    Velocities<L> v = Velocities<L>::of(a, b);
    for (int i = 0; i < (second.any ? 2 : 1); ++i) {
        const Velocities<L> before = v;
        const PointLanes<L> p = PointLanes<L>::load(c.points[i]);
        const F n = L::load(c.points[i].normal_impulse), t = L::load(c.points[i].tangent_impulse);
        apply_impulse(v, pair, p, n * pair.nx + t * pair.tx(), n * pair.ny + t * pair.ty());
        if (i == 1) {
            v = Velocities<L>::select(second.lanes, before, v);
        }
    }
    if (uses & block_rolls) {
        const F rolling = L::load(c.rolling_impulse);
        const typename L::M rolls = nonzero<L>(L::load(c.rolling_resistance));
        v.wa = L::blend(rolls, v.wa, v.wa - pair.ia * rolling);
        v.wb = L::blend(rolls, v.wb, v.wb + pair.ib * rolling);
    }
    v.write_to(a, b);
    a.scatter(states, c.state_a);
    b.scatter(states, c.state_b);
}

/// Where a point's two anchors are relative to each other now: anchors ride their
/// bodies' motion and turn since the step began.
template <class L>
struct AnchorOffset {
    typename L::F x, y;

    I2D_FORCE_INLINE static AnchorOffset of(const BodyLanes<L>& a, const BodyLanes<L>& b, const PointLanes<L>& p) {
        using F = typename L::F;
        const F ra_x = a.dqc * p.rax - a.dqs * p.ray, ra_y = a.dqs * p.rax + a.dqc * p.ray;
        const F rb_x = b.dqc * p.rbx - b.dqs * p.rby, rb_y = b.dqs * p.rbx + b.dqc * p.rby;
        return {(b.dpx - a.dpx) + (rb_x - ra_x), (b.dpy - a.dpy) + (rb_y - ra_y)};
    }
    /// Separation: as prepared, plus how far the anchors moved apart along the normal.
    I2D_FORCE_INLINE typename L::F separation(const PairLanes<L>& c, typename L::F base_separation) const {
        return (x * c.nx + y * c.ny) + base_separation;
    }
    /// Drift: how far the anchors slid apart along the tangent since the step began.
    I2D_FORCE_INLINE typename L::F drift(const PairLanes<L>& c, const PointLanes<L>& p) const {
        return (x - (p.rbx - p.rax)) * c.tx() + (y - (p.rby - p.ray)) * c.ty();
    }
};

// A gap allows approach up to closing it within the substep (speculative); overlap is
// pushed out softly, at most push_max_speed, and only when the pass uses the bias. A
// contact with a body it cannot move (inverse mass 0) is twice as stiff (Box2D v3's
// choice): the fixed side cannot give, so the pair settles as fast with half the mass.
template <class L>
I2D_FORCE_INLINE PointTerms<L> point_terms(const PairLanes<L>& c, typename L::F separation, const SolvePass& pass) {
    using F = typename L::F;
    const F zero = L::splat(0.0f);
    const typename L::M gap = L::gt(separation, zero);
    const F speculative = separation * L::splat(pass.inv_h);
    if (!pass.use_bias) {
        return {L::blend(gap, zero, speculative), L::splat(1.0f), zero};
    }
    const typename L::M fixed = L::either(L::eq(c.ma, zero), L::eq(c.mb, zero));
    const F mass_scale = L::blend(fixed, L::splat(pass.soft.mass_scale), L::splat(pass.fixed_soft.mass_scale));
    const F bias_rate = L::blend(fixed, L::splat(pass.soft.bias_rate), L::splat(pass.fixed_soft.bias_rate));
    const F impulse_scale = L::blend(fixed, L::splat(pass.soft.impulse_scale), L::splat(pass.fixed_soft.impulse_scale));
    const F push = L::max(mass_scale * bias_rate * separation, L::splat(-pass.push_max_speed));
    return {L::blend(gap, push, speculative), L::blend(gap, mass_scale, L::splat(1.0f)),
            L::blend(gap, impulse_scale, zero)};
}

// Until a point first pushes, the impact speed of a pair that was approaching when the
// step began follows its free motion: sqrt(v^2 + 2 a gap), from energy.
template <class L, int W>
I2D_FORCE_INLINE void track_impact(ContactBlock<W>& c, int i, typename L::F separation, typename L::F max_normal,
                                   float elapsed) {
    using F = typename L::F;
    const F zero = L::splat(0.0f);
    const F start = L::load(c.points[i].start_speed);
    const typename L::M tracking = L::but_not(L::lt(start, zero), nonzero<L>(max_normal));
    if (!L::any(tracking)) {
        return;
    }
    const F accel = L::load(c.approach_acceleration);
    const F free_speed = start - accel * L::splat(elapsed);
    const F impact = -L::sqrt(free_speed * free_speed + L::splat(2.0f) * accel * L::max(separation, zero));
    L::store(c.points[i].relative_velocity, L::blend(tracking, L::load(c.points[i].relative_velocity), impact));
}

// Coulomb friction towards the surfaces' relative speed (zero but for conveyor belts).
// In the solve pass a sticking point also pulls back how far its two anchors slid apart
// since the step began (its drift), capped at the Coulomb limit like the rest of the
// friction: a velocity-only friction leaves each substep's slip in place, a loaded pile
// shears a little every step, and a tall pile creeps sideways. The relax pass that
// follows removes the velocity this adds, as it does the push-out's. Surfaces that move
// (tangent speed) are meant to slide, and have no anchors.
template <class L, int W>
I2D_FORCE_INLINE void solve_friction(Velocities<L>& v, ContactBlock<W>& c, const PairLanes<L>& pair,
                                     const PointLanes<L> p[2], const PointImpulse<L> x[2],
                                     const SecondPoint<L>& second, const typename L::F drift[2], bool conveys,
                                     const SolvePass& pass) {
    using F = typename L::F;
    // Without moving surfaces every lane's tangent speed is +0, which subtracts exactly.
    const F friction = L::load(c.friction);
    const F tangent_speed = conveys ? L::load(c.tangent_speed) : L::splat(0.0f);
    const typename L::M anchored = L::eq(tangent_speed, L::splat(0.0f));
    for (int i = 0; i < (second.any ? 2 : 1); ++i) {
        const Velocities<L> before = v;
        F vt = relative_speed(v, p[i], pair.tx(), pair.ty()) - tangent_speed;
        if (pass.use_bias) {
            vt = L::blend(anchored, vt, vt + L::splat(pass.anchor_rate) * drift[i]);
        }
        const F max_friction = friction * x[i].normal;
        const F old = L::load(c.points[i].tangent_impulse);
        const F impulse = clamp_lanes<L>(old - L::load(c.points[i].tangent_mass) * vt, -max_friction, max_friction);
        const F change = impulse - old;
        apply_impulse(v, pair, p[i], change * pair.tx(), change * pair.ty());
        if (i == 1) {
            v = Velocities<L>::select(second.lanes, before, v);
            L::store(c.points[i].tangent_impulse, L::blend(second.lanes, old, impulse));
        } else {
            L::store(c.points[i].tangent_impulse, impulse);
        }
    }
}

// A torque opposing the relative spin, bounded by arm x normal impulse.
template <class L, int W>
I2D_FORCE_INLINE void solve_rolling(Velocities<L>& v, ContactBlock<W>& c, const PairLanes<L>& pair,
                                    typename L::F normal_total) {
    using F = typename L::F;
    const F arm = L::load(c.rolling_resistance);
    const typename L::M rolls = nonzero<L>(arm);
    const F rolling_mass = positive_inverse<L>(pair.ia + pair.ib);
    const F max_torque = arm * normal_total;
    const F old = L::load(c.rolling_impulse);
    const F impulse = clamp_lanes<L>(old - rolling_mass * (v.wb - v.wa), -max_torque, max_torque);
    const F change = impulse - old;
    v.wa = L::blend(rolls, v.wa, v.wa - pair.ia * change);
    v.wb = L::blend(rolls, v.wb, v.wb + pair.ib * change);
    L::store(c.rolling_impulse, L::blend(rolls, old, impulse));
}

template <class L, int W>
I2D_FORCE_INLINE void solve_block(ContactBlock<W>& c, uint8_t uses, BodyState* states, const SolvePass& pass) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    const SecondPoint<L> second = SecondPoint<L>::of(c);
    const int points = second.any ? 2 : 1;
    PointLanes<L> p[2];
    PointTerms<L> terms[2];
    PointImpulse<L> x[2];
    F mass[2], drift[2] = {L::splat(0.0f), L::splat(0.0f)};
    // Without it, the largest push is neither read nor kept: nothing will ask for it.
    const bool keeps_max_push = (uses & block_keeps_max_push) != 0;
    for (int i = 0; i < points; ++i) {
        p[i] = PointLanes<L>::load(c.points[i]);
        const AnchorOffset<L> offset = AnchorOffset<L>::of(a, b, p[i]);
        const F separation = offset.separation(pair, L::load(c.points[i].base_separation));
        if (pass.use_bias) {
            drift[i] = offset.drift(pair, p[i]);
        }
        terms[i] = point_terms(pair, separation, pass);
        x[i] = {L::load(c.points[i].normal_impulse),
                keeps_max_push ? L::load(c.points[i].max_normal_impulse) : L::splat(0.0f)};
        mass[i] = L::load(c.points[i].normal_mass);
        if (pass.use_bias && (uses & block_tracks_impact)) {
            track_impact<L, W>(c, i, separation, x[i].max_normal, pass.elapsed);
        }
    }
    if (!second.any) {
        x[1] = {L::splat(0.0f), L::splat(0.0f)};  // as stored for a missing point
    }
    Velocities<L> v = Velocities<L>::of(a, b);
    const typename L::M active[2] = {all_lanes<L>(), second.lanes};
    solve_normal(v, pair, p, mass, terms, x, active, second.any);
    for (int i = 0; i < points; ++i) {
        L::store(c.points[i].normal_impulse, x[i].normal);
        if (keeps_max_push) {
            L::store(c.points[i].max_normal_impulse, x[i].max_normal);
        }
    }
    solve_friction<L, W>(v, c, pair, p, x, second, drift, (uses & block_conveys) != 0, pass);
    if (uses & block_rolls) {
        solve_rolling<L, W>(v, c, pair, (L::splat(0.0f) + x[0].normal) + x[1].normal);
    }
    v.write_to(a, b);
    a.scatter(states, c.state_a);
    b.scatter(states, c.state_b);
}

// Bouncing points aim at vn = -e v_impact (bias e v_impact on a rigid point); the other
// points that pushed during the step keep their bodies from moving into each other.
// Slow impacts do not bounce, nor do points that never pushed.
template <class L, int W>
I2D_FORCE_INLINE void restitution_block(ContactBlock<W>& c, BodyState* states, float threshold) {
    using F = typename L::F;
    using M = typename L::M;
    const F zero = L::splat(0.0f);
    BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    const F restitution = L::load(c.restitution);
    const M elastic = nonzero<L>(restitution);
    PointLanes<L> p[2];
    PointTerms<L> terms[2];
    PointImpulse<L> x[2];
    F mass[2];
    M active[2];
    for (int i = 0; i < 2; ++i) {
        p[i] = PointLanes<L>::load(c.points[i]);
        x[i] = {L::load(c.points[i].normal_impulse), L::load(c.points[i].max_normal_impulse)};
        mass[i] = L::load(c.points[i].normal_mass);
        active[i] = nonzero<L>(x[i].max_normal);
        const F impact = L::load(c.points[i].relative_velocity);
        const M bounces = L::both(L::both(elastic, L::lt(impact, L::splat(-threshold))), active[i]);
        terms[i] = {L::blend(bounces, zero, restitution * impact), L::splat(1.0f), zero};
    }
    Velocities<L> v = Velocities<L>::of(a, b);
    solve_normal(v, pair, p, mass, terms, x, active, L::any(active[1]));
    for (int i = 0; i < 2; ++i) {
        L::store(c.points[i].normal_impulse, x[i].normal);
        L::store(c.points[i].max_normal_impulse, x[i].max_normal);
    }
    v.write_to(a, b);
    a.scatter(states, c.state_a);
    b.scatter(states, c.state_b);
}

// The separation the store's touching test reads, for both points of every lane (a lane
// without a second point gives a value no one reads), with the solve pass's arithmetic.
template <class L, int W>
I2D_FORCE_INLINE void final_separations_block(const ContactBlock<W>& c, const BodyState* states, float* out) {
    const BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    const BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    for (int i = 0; i < 2; ++i) {
        const AnchorOffset<L> offset = AnchorOffset<L>::of(a, b, PointLanes<L>::load(c.points[i]));
        L::store(out + i * W, offset.separation(pair, L::load(c.points[i].base_separation)));
    }
}

// 1 / (mA + mB + (rA x d)^2 iA + (rB x d)^2 iB), or 0 where that is not positive:
// effective_mass.hpp's arithmetic in lanes.
template <class L>
I2D_FORCE_INLINE typename L::F effective_mass_lanes(const PairLanes<L>& c, const PointLanes<L>& p, typename L::F dx,
                                                    typename L::F dy) {
    const typename L::F ra = p.rax * dy - p.ray * dx, rb = p.rbx * dy - p.rby * dx;
    return positive_inverse<L>(c.ma + c.mb + c.ia * ra * ra + c.ib * rb * rb);
}

// A point's row from its anchors and separation, where the lane has the point; a lane
// without it keeps the zeros packing left.
template <class L, int W>
I2D_FORCE_INLINE void finish_point(ContactPointLanes<W>& p, const PairLanes<L>& c, const Velocities<L>& start,
                                   typename L::M has) {
    using F = typename L::F;
    const F zero = L::splat(0.0f);
    const PointLanes<L> anchors = PointLanes<L>::load(p);
    const F offset = (anchors.rbx - anchors.rax) * c.nx + (anchors.rby - anchors.ray) * c.ny;
    L::store(p.base_separation, L::blend(has, zero, L::load(p.base_separation) - offset));
    const F speed = L::blend(has, zero, relative_speed<L>(start, anchors, c.nx, c.ny));
    L::store(p.relative_velocity, speed);
    L::store(p.start_speed, speed);
    L::store(p.normal_mass, L::blend(has, zero, effective_mass_lanes<L>(c, anchors, c.nx, c.ny)));
    L::store(p.tangent_mass, L::blend(has, zero, effective_mass_lanes<L>(c, anchors, c.tx(), c.ty())));
}

template <class L, int W>
I2D_FORCE_INLINE void finish_pack_block(ContactBlock<W>& c, const PackLanes<W>& in) {
    const PairLanes<L> pair = PairLanes<L>::load(c);
    const Velocities<L> start{L::load(in.vax), L::load(in.vay), L::load(in.wa),
                              L::load(in.vbx), L::load(in.vby), L::load(in.wb)};
    for (int i = 0; i < 2; ++i) {
        const typename L::M has = L::gt(L::load(in.has_point[i]), L::splat(0.0f));
        if (L::any(has)) {
            finish_point<L, W>(c.points[i], pair, start, has);
        }
    }
}

/// The table entries of one lane type.
template <class L>
struct KernelsOf {
    static constexpr int W = L::width;
    static void warm_start(void* blocks, const uint8_t* uses, int32_t count, BodyState* states) {
        ContactBlock<W>* c = static_cast<ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            warm_start_block<L, W>(c[k], uses[k], states);
        }
    }
    static void solve(void* blocks, const uint8_t* uses, int32_t count, BodyState* states, const SolvePass& pass) {
        ContactBlock<W>* c = static_cast<ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            solve_block<L, W>(c[k], uses[k], states, pass);
        }
    }
    static void restitution(void* blocks, int32_t count, BodyState* states, float threshold) {
        ContactBlock<W>* c = static_cast<ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            restitution_block<L, W>(c[k], states, threshold);
        }
    }
    static void final_separations(const void* blocks, int32_t count, const BodyState* states, float* separations) {
        const ContactBlock<W>* c = static_cast<const ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            final_separations_block<L, W>(c[k], states, separations + 2 * W * k);
        }
    }
    static void finish_pack(void* block, const void* inputs) {
        finish_pack_block<L, W>(*static_cast<ContactBlock<W>*>(block), *static_cast<const PackLanes<W>*>(inputs));
    }
};

}  // namespace i2d
