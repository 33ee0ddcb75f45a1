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

}  // namespace i2d
