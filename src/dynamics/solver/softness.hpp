// SPDX-License-Identifier: MIT
// Softness: a constraint made to act like a damped spring of a given frequency, solved
// implicitly so that it is stable at any stiffness the substep can resolve.
//
// A rigid constraint fed with a position error (Baumgarte) overshoots and jitters; a
// soft one of frequency f and damping ratio zeta is the implicit Euler solution of a
// spring k = m w^2 with damper c = 2 m zeta w (w = 2 pi f) over the substep h. Solved
// for the impulse, that spring becomes three numbers (Catto, "Solver2D", 2024):
//   impulse = -mass * mass_scale * (v + bias_rate * C) - impulse_scale * accumulated
// with a1 = 2 zeta + h w, a2 = h w a1, a3 = 1 / (1 + a2):
//   bias_rate = w / a1, mass_scale = a2 a3, impulse_scale = a3.
#pragma once

namespace i2d {

struct Softness {
    float bias_rate = 0.0f;    // 1/s: how much of the position error to remove per second
    float mass_scale = 1.0f;   // share of the rigid impulse
    float impulse_scale = 0.0f;  // share of the accumulated impulse given back
};

inline Softness make_softness(float hertz, float damping_ratio, float h) {
    if (hertz == 0.0f) {
        return {0.0f, 1.0f, 0.0f};
    }
    const float omega = 2.0f * 3.14159265f * hertz;
    const float a1 = 2.0f * damping_ratio + h * omega;
    const float a2 = h * omega * a1;
    const float a3 = 1.0f / (1.0f + a2);
    return {omega / a1, a2 * a3, a3};
}

/// A spring row (a joint's spring, as opposed to a rigid row made soft): its impulse
/// from the row's error C, its speed Cdot and the impulse it accumulated this substep:
///   impulse = -mass * (position_rate * C + speed_scale * Cdot) - impulse_scale * accumulated
/// Softness above is the implicit (backward) Euler spring: unconditionally stable, but it
/// takes energy out, exp(-pi h w) of the amplitude per cycle (15 % per cycle for a 2 Hz
/// spring at 240 substeps/s), so that a spring rings down even with no damping at all.
/// A spring slow for the substep (h w at most symplectic_limit) is instead stepped with
/// its force taken where the substep starts and its damping implicit (symplectic Euler
/// for the spring): no energy lost but what damping_ratio asks for; such a row acts once
/// per substep, in the pass that pushes errors out, not again in the relax pass.
struct SpringRow {
    float position_rate = 0.0f;  // 1/s: share of the error removed as speed per substep
    float speed_scale = 1.0f;
    float impulse_scale = 0.0f;
    bool relaxes = true;  // also acts in the relax pass (the implicit form)
};

/// h w past which an explicit spring would not be stable enough (it diverges at 2).
constexpr float symplectic_limit = 1.0f;

inline SpringRow as_spring_row(const Softness& soft) {
    return {soft.bias_rate * soft.mass_scale, soft.mass_scale, soft.impulse_scale, true};
}

inline SpringRow make_spring(float hertz, float damping_ratio, float h) {
    const float omega = 2.0f * 3.14159265f * hertz;
    if (h * omega > symplectic_limit) {
        return as_spring_row(make_softness(hertz, damping_ratio, h));
    }
    const float damping = 2.0f * h * damping_ratio * omega;
    const float scale = 1.0f / (1.0f + damping);
    return {h * omega * omega * scale, damping * scale, scale, false};
}

}  // namespace i2d
