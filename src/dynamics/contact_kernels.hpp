// SPDX-License-Identifier: MIT
// The contact kernels of the soft step, written once over a lane type (lanes_*.hpp) and
// compiled for each instruction set: warm start, solve (with push-out) or relax, and the
// restitution pass, W contacts at a time.
//
// The physics is the contact solver's (contact_solver.hpp says what and why); this file
// is its arithmetic. Every lane performs the same operations in the same order whatever
// the lane type, with no fused multiply-add and no approximate reciprocal, so that a
// world gives the same bits on the scalar, SSE2 and AVX2 paths. Choices that differ per
// contact (speculative or overlapping, the 2x2 block case, whether rolling resistance
// applies) are made by blending both outcomes per lane, never by a branch on one lane.
// The lane types live in anonymous namespaces, so each translation unit's kernels are
// its own.
#pragma once

#include <cstdint>

#include "dynamics/body_state.hpp"
#include "dynamics/contact_block.hpp"

namespace i2d {

template <class L>
struct BodyLanes {
    typename L::F vx, vy, w, moves, dpx, dpy, dqc, dqs;

    static BodyLanes gather(const BodyState* states, const int32_t* index) {
        typename L::F f[8];
        L::gather(states, index, f);
        return {f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7]};
    }
    void scatter(BodyState* states, const int32_t* index) const { L::scatter(states, index, vx, vy, w, moves); }
};

/// One contact point's fixed data in lanes: anchors, masses.
template <class L>
struct PointLanes {
    using F = typename L::F;
    F rax, ray, rbx, rby;

    template <int W>
    static PointLanes load(const ContactPointLanes<W>& p) {
        return {L::load(p.anchor_ax), L::load(p.anchor_ay), L::load(p.anchor_bx), L::load(p.anchor_by)};
    }
};

/// The constraint's fixed data in lanes.
template <class L>
struct PairLanes {
    using F = typename L::F;
    F ma, mb, ia, ib, nx, ny;

    template <int W>
    static PairLanes load(const ContactBlock<W>& c) {
        return {L::load(c.inv_mass_a), L::load(c.inv_mass_b), L::load(c.inv_inertia_a),
                L::load(c.inv_inertia_b), L::load(c.normal_x), L::load(c.normal_y)};
    }
    // The tangent is left_perp(normal).
    F tx() const { return -ny; }
    F ty() const { return nx; }
};

/// The bodies' velocities while a block is solved.
template <class L>
struct Velocities {
    using F = typename L::F;
    F vax, vay, wa, vbx, vby, wb;

    static Velocities select(typename L::M m, const Velocities& if_false, const Velocities& if_true) {
        return {L::blend(m, if_false.vax, if_true.vax), L::blend(m, if_false.vay, if_true.vay),
                L::blend(m, if_false.wa, if_true.wa),   L::blend(m, if_false.vbx, if_true.vbx),
                L::blend(m, if_false.vby, if_true.vby), L::blend(m, if_false.wb, if_true.wb)};
    }
};

// (vB + wB x rB) - (vA + wA x rA), along (dx, dy); w x r = (-w r.y, w r.x).
template <class L>
typename L::F relative_speed(const Velocities<L>& v, const PointLanes<L>& p, typename L::F dx, typename L::F dy) {
    const typename L::F rvx = (v.vbx + (-v.wb) * p.rby) - (v.vax + (-v.wa) * p.ray);
    const typename L::F rvy = (v.vby + v.wb * p.rbx) - (v.vay + v.wa * p.rax);
    return rvx * dx + rvy * dy;
}

// A takes -P at its anchor, B takes +P at its anchor.
template <class L>
void apply_impulse(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L>& p, typename L::F px,
                   typename L::F py) {
    v.vax = v.vax - c.ma * px;
    v.vay = v.vay - c.ma * py;
    v.wa = v.wa - c.ia * (p.rax * py - p.ray * px);
    v.vbx = v.vbx + c.mb * px;
    v.vby = v.vby + c.mb * py;
    v.wb = v.wb + c.ib * (p.rbx * py - p.rby * px);
}

template <class L>
typename L::M nonzero(typename L::F a) {
    return L::either(L::lt(a, L::splat(0.0f)), L::gt(a, L::splat(0.0f)));
}

// a < lo ? lo : (a > hi ? hi : a)
template <class L>
typename L::F clamp_lanes(typename L::F a, typename L::F lo, typename L::F hi) {
    return L::blend(L::lt(a, lo), L::blend(L::gt(a, hi), a, hi), lo);
}

/// How one point is solved this pass: impulse = -mass (mass_scale vn + bias) - impulse_scale x.
template <class L>
struct PointTerms {
    typename L::F bias, mass_scale, impulse_scale;
};

/// A point's accumulated impulses as they change during a pass.
template <class L>
struct PointImpulse {
    typename L::F normal, max_normal;
};

// The new accumulated normal impulse: the change is applied and the largest change kept.
template <class L>
void set_normal_impulse(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L>& p, PointImpulse<L>& x,
                        typename L::F impulse) {
    const typename L::F change = impulse - x.normal;
    x.max_normal = L::max(x.max_normal, change);
    apply_impulse(v, c, p, change * c.nx, change * c.ny);
    x.normal = impulse;
}

template <class L>
void solve_normal_point(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L>& p, typename L::F normal_mass,
                        const PointTerms<L>& t, PointImpulse<L>& x) {
    using F = typename L::F;
    const F vn = relative_speed(v, p, c.nx, c.ny);
    const F impulse = (-normal_mass) * (t.mass_scale * vn + t.bias) - t.impulse_scale * x.normal;
    set_normal_impulse(v, c, p, x, L::max(x.normal + impulse, L::splat(0.0f)));
}

/// Both points of a two-point manifold as one 2x2 linear complementarity problem: find
/// x >= 0 with w = K (x - (1 - impulse_scale) x_old) + mass_scale vn + bias >= 0 and
/// x_i w_i = 0, trying both, first only, second only, neither. `fits` says per lane
/// whether K was well conditioned and a case fitted; lanes where it did not keep their
/// inputs, for the caller to solve point by point.
template <class L>
typename L::M solve_normal_block(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L> p[2],
                                 const PointTerms<L> t[2], PointImpulse<L> x[2], typename L::M two_points) {
    using F = typename L::F;
    using M = typename L::M;
    constexpr float max_condition = 1000.0f;
    const F zero = L::splat(0.0f);
    const F rn1a = p[0].rax * c.ny - p[0].ray * c.nx, rn1b = p[0].rbx * c.ny - p[0].rby * c.nx;
    const F rn2a = p[1].rax * c.ny - p[1].ray * c.nx, rn2b = p[1].rbx * c.ny - p[1].rby * c.nx;
    const F m = c.ma + c.mb;
    const F k11 = m + c.ia * rn1a * rn1a + c.ib * rn1b * rn1b;
    const F k22 = m + c.ia * rn2a * rn2a + c.ib * rn2b * rn2b;
    const F k12 = m + c.ia * rn1a * rn2a + c.ib * rn1b * rn2b;
    const F det = k11 * k22 - k12 * k12;
    const M conditioned = L::both(two_points, L::lt(k11 * k11, L::splat(max_condition) * det));
    const F one = L::splat(1.0f);
    const F kept1 = (one - t[0].impulse_scale) * x[0].normal;
    const F kept2 = (one - t[1].impulse_scale) * x[1].normal;
    const F vn1 = relative_speed(v, p[0], c.nx, c.ny);
    const F vn2 = relative_speed(v, p[1], c.nx, c.ny);
    const F q1 = t[0].mass_scale * vn1 + t[0].bias - (k11 * kept1 + k12 * kept2);
    const F q2 = t[1].mass_scale * vn2 + t[1].bias - (k12 * kept1 + k22 * kept2);

    const F inv_det = one / det;
    const F both1 = (-inv_det) * (k22 * q1 - k12 * q2), both2 = (-inv_det) * (k11 * q2 - k12 * q1);
    const F first = (-q1) / k11, second = (-q2) / k22;
    const M both_push = L::both(L::ge(both1, zero), L::ge(both2, zero));
    const M first_pushes = L::both(L::ge(first, zero), L::ge(k12 * first + q2, zero));
    const M second_pushes = L::both(L::ge(second, zero), L::ge(k12 * second + q1, zero));
    const M neither = L::both(L::ge(q1, zero), L::ge(q2, zero));
    const M fits = L::both(conditioned, L::either(L::either(both_push, first_pushes), L::either(second_pushes, neither)));
    const F x1 = L::blend(both_push, L::blend(first_pushes, zero, first), both1);
    const F x2 = L::blend(both_push, L::blend(first_pushes, L::blend(second_pushes, zero, second), zero), both2);

    Velocities<L> solved = v;
    PointImpulse<L> solved_x[2] = {x[0], x[1]};
    set_normal_impulse(solved, c, p[0], solved_x[0], x1);
    set_normal_impulse(solved, c, p[1], solved_x[1], x2);
    v = Velocities<L>::select(fits, v, solved);
    for (int i = 0; i < 2; ++i) {
        x[i].normal = L::blend(fits, x[i].normal, solved_x[i].normal);
        x[i].max_normal = L::blend(fits, x[i].max_normal, solved_x[i].max_normal);
    }
    return fits;
}

/// The normal impulses of a block: the 2x2 block where it fits, else point by point
/// (only the `active` points; both in the solve passes).
template <class L>
void solve_normal(Velocities<L>& v, const PairLanes<L>& c, const PointLanes<L> p[2], const typename L::F mass[2],
                  const PointTerms<L> t[2], PointImpulse<L> x[2], typename L::M two_points,
                  const typename L::M active[2]) {
    const Velocities<L> before = v;
    const PointImpulse<L> x_before[2] = {x[0], x[1]};
    const typename L::M fits = solve_normal_block(v, c, p, t, x, L::both(two_points, L::both(active[0], active[1])));
    if (L::all(fits)) {
        return;
    }
    Velocities<L> single = before;
    PointImpulse<L> single_x[2] = {x_before[0], x_before[1]};
    for (int i = 0; i < 2; ++i) {
        const Velocities<L> prior = single;
        const PointImpulse<L> prior_x = single_x[i];
        solve_normal_point(single, c, p[i], mass[i], t[i], single_x[i]);
        single = Velocities<L>::select(active[i], prior, single);
        single_x[i].normal = L::blend(active[i], prior_x.normal, single_x[i].normal);
        single_x[i].max_normal = L::blend(active[i], prior_x.max_normal, single_x[i].max_normal);
    }
    v = Velocities<L>::select(fits, single, v);
    for (int i = 0; i < 2; ++i) {
        x[i].normal = L::blend(fits, single_x[i].normal, x[i].normal);
        x[i].max_normal = L::blend(fits, single_x[i].max_normal, x[i].max_normal);
    }
}

template <class L, int W>
void warm_start_block(ContactBlock<W>& c, BodyState* states) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    Velocities<L> v{a.vx, a.vy, a.w, b.vx, b.vy, b.w};
    for (int i = 0; i < 2; ++i) {
        const PointLanes<L> p = PointLanes<L>::template load<W>(c.points[i]);
        const F n = L::load(c.points[i].normal_impulse), t = L::load(c.points[i].tangent_impulse);
        apply_impulse(v, pair, p, n * pair.nx + t * pair.tx(), n * pair.ny + t * pair.ty());
    }
    const F rolling = L::load(c.rolling_impulse);
    v.wa = v.wa - pair.ia * rolling;
    v.wb = v.wb + pair.ib * rolling;
    a.vx = v.vax, a.vy = v.vay, a.w = v.wa;
    b.vx = v.vbx, b.vy = v.vby, b.w = v.wb;
    a.scatter(states, c.state_a);
    b.scatter(states, c.state_b);
}

// Separation of a point now: as prepared, plus how far its two anchors moved apart along
// the normal since (anchors ride their bodies' motion and turn).
template <class L>
typename L::F current_separation(const BodyLanes<L>& a, const BodyLanes<L>& b, const PairLanes<L>& c,
                                 const PointLanes<L>& p, typename L::F base_separation) {
    using F = typename L::F;
    const F ra_x = a.dqc * p.rax - a.dqs * p.ray, ra_y = a.dqs * p.rax + a.dqc * p.ray;
    const F rb_x = b.dqc * p.rbx - b.dqs * p.rby, rb_y = b.dqs * p.rbx + b.dqc * p.rby;
    const F moved_x = (b.dpx - a.dpx) + (rb_x - ra_x);
    const F moved_y = (b.dpy - a.dpy) + (rb_y - ra_y);
    return (moved_x * c.nx + moved_y * c.ny) + base_separation;
}

// A gap allows approach up to closing it within the substep (speculative); overlap is
// pushed out softly, at most push_max_speed, and only when the pass uses the bias.
template <class L, int W>
PointTerms<L> point_terms(const ContactBlock<W>& c, typename L::F separation, const SolvePass& pass) {
    using F = typename L::F;
    const typename L::M gap = L::gt(separation, L::splat(0.0f));
    const F speculative = separation * L::splat(pass.inv_h);
    if (!pass.use_bias) {
        return {L::blend(gap, L::splat(0.0f), speculative), L::splat(1.0f), L::splat(0.0f)};
    }
    const F mass_scale = L::load(c.mass_scale);
    const F push = L::max(mass_scale * L::load(c.bias_rate) * separation, L::splat(-pass.push_max_speed));
    return {L::blend(gap, push, speculative), L::blend(gap, mass_scale, L::splat(1.0f)),
            L::blend(gap, L::load(c.impulse_scale), L::splat(0.0f))};
}

// Until a point first pushes, the impact speed of a pair that was approaching when the
// step began follows its free motion: sqrt(v^2 + 2 a gap), from energy.
template <class L, int W>
void track_impact(ContactBlock<W>& c, int i, typename L::F separation, typename L::F max_normal, float elapsed) {
    using F = typename L::F;
    const F zero = L::splat(0.0f);
    const F start = L::load(c.points[i].start_speed);
    const F accel = L::load(c.approach_acceleration);
    const typename L::M tracking = L::but_not(L::lt(start, zero), nonzero<L>(max_normal));
    const F free_speed = start - accel * L::splat(elapsed);
    const F impact = -L::sqrt(free_speed * free_speed + L::splat(2.0f) * accel * L::max(separation, zero));
    L::store(c.points[i].relative_velocity, L::blend(tracking, L::load(c.points[i].relative_velocity), impact));
}

// Coulomb friction towards the surfaces' relative speed (zero but for conveyor belts).
template <class L, int W>
void solve_friction(Velocities<L>& v, ContactBlock<W>& c, const PairLanes<L>& pair, const PointLanes<L> p[2],
                    const PointImpulse<L> x[2]) {
    using F = typename L::F;
    const F friction = L::load(c.friction), tangent_speed = L::load(c.tangent_speed);
    for (int i = 0; i < 2; ++i) {
        const F vt = relative_speed(v, p[i], pair.tx(), pair.ty()) - tangent_speed;
        const F max_friction = friction * x[i].normal;
        const F old = L::load(c.points[i].tangent_impulse);
        const F impulse = clamp_lanes<L>(old - L::load(c.points[i].tangent_mass) * vt, -max_friction, max_friction);
        const F change = impulse - old;
        apply_impulse(v, pair, p[i], change * pair.tx(), change * pair.ty());
        L::store(c.points[i].tangent_impulse, impulse);
    }
}

// A torque opposing the relative spin, bounded by arm x normal impulse.
template <class L, int W>
void solve_rolling(Velocities<L>& v, ContactBlock<W>& c, const PairLanes<L>& pair, typename L::F normal_total) {
    using F = typename L::F;
    const F arm = L::load(c.rolling_resistance);
    const typename L::M rolls = nonzero<L>(arm);
    if (!L::any(rolls)) {
        return;
    }
    const F max_torque = arm * normal_total;
    const F old = L::load(c.rolling_impulse);
    const F impulse = clamp_lanes<L>(old - L::load(c.rolling_mass) * (v.wb - v.wa), -max_torque, max_torque);
    const F change = impulse - old;
    v.wa = L::blend(rolls, v.wa, v.wa - pair.ia * change);
    v.wb = L::blend(rolls, v.wb, v.wb + pair.ib * change);
    L::store(c.rolling_impulse, L::blend(rolls, old, impulse));
}

template <class L, int W>
void solve_block(ContactBlock<W>& c, BodyState* states, const SolvePass& pass) {
    using F = typename L::F;
    BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    const PointLanes<L> p[2] = {PointLanes<L>::template load<W>(c.points[0]),
                                PointLanes<L>::template load<W>(c.points[1])};
    PointTerms<L> terms[2];
    PointImpulse<L> x[2];
    F mass[2];
    for (int i = 0; i < 2; ++i) {
        const F separation = current_separation(a, b, pair, p[i], L::load(c.points[i].base_separation));
        terms[i] = point_terms<L, W>(c, separation, pass);
        x[i] = {L::load(c.points[i].normal_impulse), L::load(c.points[i].max_normal_impulse)};
        mass[i] = L::load(c.points[i].normal_mass);
        if (pass.use_bias) {
            track_impact<L, W>(c, i, separation, x[i].max_normal, pass.elapsed);
        }
    }
    Velocities<L> v{a.vx, a.vy, a.w, b.vx, b.vy, b.w};
    const typename L::M two_points = L::eq(L::load(c.point_count), L::splat(2.0f));
    const typename L::M all_points = L::eq(L::splat(0.0f), L::splat(0.0f));
    const typename L::M active[2] = {all_points, all_points};
    solve_normal(v, pair, p, mass, terms, x, two_points, active);
    for (int i = 0; i < 2; ++i) {
        L::store(c.points[i].normal_impulse, x[i].normal);
        L::store(c.points[i].max_normal_impulse, x[i].max_normal);
    }
    solve_friction<L, W>(v, c, pair, p, x);
    solve_rolling<L, W>(v, c, pair, (L::splat(0.0f) + x[0].normal) + x[1].normal);
    a.vx = v.vax, a.vy = v.vay, a.w = v.wa;
    b.vx = v.vbx, b.vy = v.vby, b.w = v.wb;
    a.scatter(states, c.state_a);
    b.scatter(states, c.state_b);
}

// Bouncing points aim at vn = -e v_impact (bias e v_impact on a rigid point); the other
// points that pushed during the step keep their bodies from moving into each other.
// Slow impacts do not bounce, nor do points that never pushed.
template <class L, int W>
void restitution_block(ContactBlock<W>& c, BodyState* states, float threshold) {
    using F = typename L::F;
    using M = typename L::M;
    const F zero = L::splat(0.0f);
    BodyLanes<L> a = BodyLanes<L>::gather(states, c.state_a);
    BodyLanes<L> b = BodyLanes<L>::gather(states, c.state_b);
    const PairLanes<L> pair = PairLanes<L>::load(c);
    const PointLanes<L> p[2] = {PointLanes<L>::template load<W>(c.points[0]),
                                PointLanes<L>::template load<W>(c.points[1])};
    const F restitution = L::load(c.restitution);
    const M elastic = nonzero<L>(restitution);
    PointTerms<L> terms[2];
    PointImpulse<L> x[2];
    F mass[2];
    M active[2];
    for (int i = 0; i < 2; ++i) {
        x[i] = {L::load(c.points[i].normal_impulse), L::load(c.points[i].max_normal_impulse)};
        mass[i] = L::load(c.points[i].normal_mass);
        active[i] = nonzero<L>(x[i].max_normal);
        const F impact = L::load(c.points[i].relative_velocity);
        const M bounces = L::both(L::both(elastic, L::lt(impact, L::splat(-threshold))), active[i]);
        terms[i] = {L::blend(bounces, zero, restitution * impact), L::splat(1.0f), zero};
    }
    Velocities<L> v{a.vx, a.vy, a.w, b.vx, b.vy, b.w};
    const M two_points = L::eq(L::load(c.point_count), L::splat(2.0f));
    solve_normal(v, pair, p, mass, terms, x, two_points, active);
    for (int i = 0; i < 2; ++i) {
        L::store(c.points[i].normal_impulse, x[i].normal);
        L::store(c.points[i].max_normal_impulse, x[i].max_normal);
    }
    a.vx = v.vax, a.vy = v.vay, a.w = v.wa;
    b.vx = v.vbx, b.vy = v.vby, b.w = v.wb;
    a.scatter(states, c.state_a);
    b.scatter(states, c.state_b);
}

/// The table entries of one lane type.
template <class L>
struct KernelsOf {
    static constexpr int W = L::width;
    static void warm_start(void* blocks, int32_t count, BodyState* states) {
        ContactBlock<W>* c = static_cast<ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            warm_start_block<L, W>(c[k], states);
        }
    }
    static void solve(void* blocks, int32_t count, BodyState* states, const SolvePass& pass) {
        ContactBlock<W>* c = static_cast<ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            solve_block<L, W>(c[k], states, pass);
        }
    }
    static void restitution(void* blocks, int32_t count, BodyState* states, float threshold) {
        ContactBlock<W>* c = static_cast<ContactBlock<W>*>(blocks);
        for (int32_t k = 0; k < count; ++k) {
            restitution_block<L, W>(c[k], states, threshold);
        }
    }
};

}  // namespace i2d
