// SPDX-License-Identifier: MIT
// Sine, cosine and atan2 of the engine's own, so that results never depend on the C
// library: libm differs between platforms, versions and even compile flags, and a
// rotation built from a different cos bit gives a different simulation. These use only
// +, -, *, / and sqrt, which IEEE 754 rounds the same everywhere (contraction to fused
// multiply-add is off in the build), so every build gives the same bits.
//
// Accuracy: within 1 ulp of the float result for |angle| <= 1e5 (tests compare with
// long double) and, by construction, to 1e6; beyond 1e6 whole turns are removed with
// a double 2 pi, off by |angle| x 2e-17 rad, so far angles lose accuracy (any finite
// angle still gives a finite unit rotation), and the result is the same on every
// platform.
#pragma once

namespace i2d {

/// sin and cos of one angle (rad), computed together.
struct SinCos {
    float s, c;
};
SinCos sin_cos(float angle);

inline float sin(float angle) { return sin_cos(angle).s; }
inline float cos(float angle) { return sin_cos(angle).c; }

/// The angle of (x, y) in [-pi, pi], with IEEE's signed-zero and infinity cases.
float atan2(float y, float x);

/// The same angle wound into (-pi, pi], pi being the float nearest it (3.14159274, as the
/// joint solver's unwind_angle takes it): any finite angle, however many turns out. An
/// angle already there comes back unchanged, bit for bit; any other loses whole turns by
/// an exact remainder in double (std::remainder is exact under IEEE 754, so the bits are
/// the same everywhere), rounded to float once, -pi taken as pi. NaN for NaN or infinity.
float wind_angle(float angle);

}  // namespace i2d
