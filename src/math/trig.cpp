// SPDX-License-Identifier: MIT
// Engine-owned sine, cosine and atan2 (trig.hpp): reduction and series in double, each
// operation rounded by IEEE 754 rules alone.
#include "math/trig.hpp"

#include <cmath>
#include <limits>

namespace i2d {

namespace {

// pi / 2 in three parts: the first two have their low bits zero, so that k times them
// is exact for |k| < 2^20 and the reduction keeps double precision there.
constexpr double half_pi_1 = 1.57079632673412561417e+00;
constexpr double half_pi_2 = 6.07710050630396597660e-11;
constexpr double half_pi_3 = 2.02226624879595063154e-21;
constexpr double two_over_pi = 6.36619772367581382433e-01;
constexpr double two_pi = 6.28318530717958623200e+00;
// Below this |k| < 2^20 and k times the first two parts of pi / 2 is exact.
constexpr double exact_reduction_limit = 1.0e6;
constexpr double pi = 3.14159265358979311600e+00;
constexpr double pi_lo = 1.22464679914735317723e-16;  // pi - (double)pi
constexpr double quarter_pi = 7.85398163397448278999e-01;
constexpr double tan_eighth_pi = 4.14213562373095034237e-01;
// The float nearest pi, the bound of the joint angles' range (wind_angle).
constexpr float pi_f = 3.14159265f;

// Taylor series on |r| <= pi/4: the first omitted terms are below 1e-16 relative.
double sin_series(double r) {
    const double r2 = r * r;
    double p = -1.0 / 1307674368000.0;          // -1/15!
    p = p * r2 + 1.0 / 6227020800.0;             // 1/13!
    p = p * r2 - 1.0 / 39916800.0;               // -1/11!
    p = p * r2 + 1.0 / 362880.0;                 // 1/9!
    p = p * r2 - 1.0 / 5040.0;                   // -1/7!
    p = p * r2 + 1.0 / 120.0;                    // 1/5!
    p = p * r2 - 1.0 / 6.0;                      // -1/3!
    return r + r * (r2 * p);
}

double cos_series(double r) {
    const double r2 = r * r;
    double p = 1.0 / 20922789888000.0;           // 1/16!
    p = p * r2 - 1.0 / 87178291200.0;            // -1/14!
    p = p * r2 + 1.0 / 479001600.0;              // 1/12!
    p = p * r2 - 1.0 / 3628800.0;                // -1/10!
    p = p * r2 + 1.0 / 40320.0;                  // 1/8!
    p = p * r2 - 1.0 / 720.0;                    // -1/6!
    p = p * r2 + 1.0 / 24.0;                     // 1/4!
    p = p * r2 - 0.5;                            // -1/2!
    return 1.0 + r2 * p;
}

// atan on |u| <= tan(pi/8) after one halving, u -> u / (1 + sqrt(1 + u^2)), so that
// the series (terms u^(2n+1) / (2n+1)) is below 1e-17 after 12 terms.
double atan_small(double u) {
    const double h = u / (1.0 + std::sqrt(1.0 + u * u));
    const double h2 = h * h;
    double p = 0.0;
    for (int n = 12; n >= 1; --n) {
        const double term = 1.0 / double(2 * n + 1);
        p = (n % 2 == 1 ? -term : term) + h2 * p;
    }
    return 2.0 * (h + h * (h2 * p));
}

}  // namespace

SinCos sin_cos(float angle) {
    if (!std::isfinite(angle)) {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        return {nan, nan};
    }
    double x = angle;
    if (std::fabs(x) > exact_reduction_limit) {
        // Far angles first lose whole turns of the double 2 pi (fmod is exact): the
        // turns are then off by x times 2e-17 rad, but the remainder stays small
        // enough for the reduction below. Without this, 3e38 reduced to about 1e22
        // and the series overflowed (found by the fuzzer).
        x = std::fmod(x, two_pi);
    }
    const double k = std::floor(x * two_over_pi + 0.5);  // nearest quarter turn
    const double r = ((x - k * half_pi_1) - k * half_pi_2) - k * half_pi_3;
    const double s = sin_series(r), c = cos_series(r);
    // The quadrant: k mod 4, exact for any k (fmod is exact by IEEE 754).
    double q = std::fmod(k, 4.0);
    if (q < 0.0) {
        q += 4.0;
    }
    switch (int(q)) {
        case 0: return {float(s), float(c)};
        case 1: return {float(c), float(-s)};
        case 2: return {float(-s), float(-c)};
        default: return {float(-c), float(s)};
    }
}

float atan2(float y, float x) {
    if (std::isnan(x) || std::isnan(y)) {
        return std::numeric_limits<float>::quiet_NaN();
    }
    const bool x_negative = std::signbit(x), y_negative = std::signbit(y);
    double angle;
    if (y == 0.0f) {
        angle = x_negative ? pi : 0.0;  // atan2(+-0, -0 or x < 0) = +-pi, else +-0
    } else if (x == 0.0f) {
        angle = pi / 2.0;
    } else if (std::isinf(x) || std::isinf(y)) {
        if (std::isinf(x) && std::isinf(y)) {
            angle = x_negative ? 3.0 * quarter_pi : quarter_pi;
        } else {
            angle = std::isinf(y) ? pi / 2.0 : (x_negative ? pi : 0.0);
        }
    } else {
        const double ax = std::fabs(double(x)), ay = std::fabs(double(y));
        const bool steep = ay > ax;
        const double t = steep ? ax / ay : ay / ax;  // in (0, 1]
        double a = t > tan_eighth_pi ? quarter_pi + atan_small((t - 1.0) / (t + 1.0)) : atan_small(t);
        if (steep) {
            a = (pi / 2.0 - a) + pi_lo / 2.0;
        }
        angle = x_negative ? (pi - a) + pi_lo : a;
    }
    return float(y_negative ? -angle : angle);
}

float wind_angle(float angle) {
    if (angle > -pi_f && angle <= pi_f) {
        return angle;  // in range: untouched, so that no existing setting changes a bit
    }
    // In [-pi, pi] of double; rounding to float lands in [-pi_f, pi_f].
    const float wound = float(std::remainder(double(angle), two_pi));
    return wound == -pi_f ? pi_f : wound;
}

}  // namespace i2d
