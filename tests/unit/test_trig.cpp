// SPDX-License-Identifier: MIT
// The engine's sin, cos and atan2 (math/trig.hpp) against long double references: within
// 1 ulp of the float result over |angle| <= 1e5, and IEEE's special cases for atan2.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <cstdio>
#include <limits>

#include "check.h"
#include "math/trig.hpp"

namespace {

// Distance in units in the last place between two floats of the same sign region.
long ulps(float a, float b) {
    if (a == b) {
        return 0;
    }
    const double ref = std::fabs(double(b)) < 1e-30 ? 1e-30 : std::fabs(double(b));
    const double ulp = std::ldexp(1.0, std::ilogb(ref) - 23);
    return std::lround(std::fabs(double(a) - double(b)) / ulp);
}

long worst_ulps = 0;

void check_close(float got, long double reference, int max_ulps, const char* what, float x) {
    const long error = ulps(got, float(reference));
    worst_ulps = error > worst_ulps ? error : worst_ulps;
    // Near zero crossings a float ulp is tiny: compare absolutely there.
    const bool near_zero = std::fabs(double(reference)) < 1e-6 && std::fabs(double(got - float(reference))) < 1e-12;
    if (error > max_ulps && !near_zero) {
        ++i2d_check_failures;
        std::fprintf(stderr, "%s(%.9g) = %.9g, reference %.9Lg (%ld ulps)\n", what, double(x), double(got), reference,
                     error);
    }
}

}  // namespace

I2D_TEST(unit_trig_sin_cos_within_one_ulp) {
    worst_ulps = 0;
    for (int i = -200000; i <= 200000; ++i) {
        const float x = float(i) * 0.5f;  // every half radian to 1e5
        const float y = float(i) * 1.0e-4f;  // dense near zero
        for (float a : {x, y}) {
            const i2d::SinCos sc = i2d::sin_cos(a);
            check_close(sc.s, std::sin((long double)a), 1, "sin", a);
            check_close(sc.c, std::cos((long double)a), 1, "cos", a);
        }
    }
    std::printf("    sin/cos worst error %ld ulp\n", worst_ulps);
}

I2D_TEST(unit_trig_atan2_within_one_ulp) {
    worst_ulps = 0;
    for (int i = 0; i < 100000; ++i) {
        const float angle = -3.14159f + float(i) * 6.28318f / 100000.0f;
        const float r = 0.001f + float(i % 97) * 0.37f;
        const float x = r * float(std::cos((long double)angle)), y = r * float(std::sin((long double)angle));
        check_close(i2d::atan2(y, x), std::atan2((long double)y, (long double)x), 1, "atan2", angle);
    }
    std::printf("    atan2 worst error %ld ulp\n", worst_ulps);
}

I2D_TEST(unit_trig_special_cases) {
    const float inf = std::numeric_limits<float>::infinity();
    const float pi = 3.14159265f;
    I2D_CHECK(i2d::atan2(0.0f, 1.0f) == 0.0f && !std::signbit(i2d::atan2(0.0f, 1.0f)));
    I2D_CHECK(i2d::atan2(-0.0f, 1.0f) == 0.0f && std::signbit(i2d::atan2(-0.0f, 1.0f)));
    I2D_CHECK(i2d::atan2(0.0f, -1.0f) == pi);
    I2D_CHECK(i2d::atan2(-0.0f, -1.0f) == -pi);
    I2D_CHECK(i2d::atan2(0.0f, -0.0f) == pi);
    I2D_CHECK(i2d::atan2(1.0f, 0.0f) == pi / 2);
    I2D_CHECK(i2d::atan2(-1.0f, 0.0f) == -pi / 2);
    I2D_CHECK(i2d::atan2(inf, inf) == pi / 4);
    I2D_CHECK(i2d::atan2(-inf, -inf) == -3 * pi / 4);
    I2D_CHECK(i2d::atan2(1.0f, -inf) == pi);
    I2D_CHECK(std::isnan(i2d::atan2(std::nanf(""), 1.0f)));
    const i2d::SinCos zero = i2d::sin_cos(0.0f);
    I2D_CHECK(zero.s == 0.0f && zero.c == 1.0f);
    const i2d::SinCos half_pi = i2d::sin_cos(1.57079637f);
    I2D_CHECK(half_pi.s == 1.0f);
    I2D_CHECK(std::isnan(i2d::sin_cos(inf).s));
    // Exact quadrant symmetry: sin(-x) = -sin(x), cos(-x) = cos(x) bit for bit.
    for (float x = 0.001f; x < 1000.0f; x *= 1.37f) {
        I2D_CHECK(i2d::sin_cos(-x).s == -i2d::sin_cos(x).s && i2d::sin_cos(-x).c == i2d::sin_cos(x).c);
    }
}

// Found by the fuzzer: i2d_make_rot(3.4e38) gave (inf, -inf), the reduction of so far an
// angle leaving a remainder the series overflowed on. Every finite angle must give a
// finite, unit rotation, close to the true one while the angle's float spacing allows.
I2D_TEST(unit_trig_far_angles_stay_unit) {
    const float far[] = {3.4028235e38f, -3.4028235e38f, 1e30f, -1e20f, 1e9f, 123456792.0f, 1.0000001e6f, 2e6f};
    for (float x : far) {
        const i2d::SinCos sc = i2d::sin_cos(x);
        const double length = double(sc.s) * sc.s + double(sc.c) * sc.c;
        if (!std::isfinite(sc.s) || !std::isfinite(sc.c) || std::fabs(length - 1.0) > 1e-6) {
            ++i2d_check_failures;
            std::fprintf(stderr, "sin_cos(%g) = (%g, %g)\n", double(x), double(sc.s), double(sc.c));
        }
    }
    // Up to 1e7 the double 2 pi is off by less than 2e-10 rad: still within 2 ulp.
    for (float x = 1.0e6f; x < 1.0e7f; x = x * 1.1f + 0.37f) {
        const i2d::SinCos sc = i2d::sin_cos(x);
        I2D_CHECK(std::fabs(double(sc.s) - double(std::sin((long double)x))) < 2.5e-7);
        I2D_CHECK(std::fabs(double(sc.c) - double(std::cos((long double)x))) < 2.5e-7);
    }
}

// wind_angle keeps an angle already in (-pi, pi] bit for bit (so no existing joint
// changes), and brings any other finite one there: the same pose, to within the float
// rounding of the result while the double 2 pi's error (|angle| x 4e-17 rad) stays below it.
I2D_TEST(unit_trig_wind_angle_keeps_range_and_reduces_the_rest) {
    constexpr float pi_f = 3.14159265f;
    for (float x : {0.0f, -0.0f, 1e-30f, 0.5f, -3.0f, pi_f, std::nextafter(-pi_f, 0.0f)}) {
        const float wound = i2d::wind_angle(x);
        I2D_CHECK(wound == x && std::signbit(wound) == std::signbit(x));
    }
    // 3 pi: the remainder, just past -pi in double, rounds to -pi in float, taken as pi.
    I2D_CHECK(i2d::wind_angle(9.42477796f) == pi_f);
    const long double two_pi = 2.0L * 3.141592653589793238462643383279502884L;
    const float far[] = {7.0f, -7.0f, 100.0f, -100.0f, 1.0e4f, -1.0e4f, 123456.7f, 3.5f, -3.5f, -pi_f, 9.42477796f};
    for (float x : far) {
        const float wound = i2d::wind_angle(x);
        const long double reference = std::remainder((long double)x, two_pi);
        // The same pose: equal but for whole turns (near -pi the float may round to -pi,
        // taken as pi), to one float ulp at pi, rad.
        constexpr double wound_tolerance = 2.4e-7;
        const long double off = std::remainder((long double)wound - reference, two_pi);
        if (!(wound > -pi_f && wound <= pi_f) || std::fabs(double(off)) > wound_tolerance) {
            ++i2d_check_failures;
            std::fprintf(stderr, "wind_angle(%.9g) = %.9g, reference %.9Lg\n", double(x), double(wound), reference);
        }
    }
    // Any finite angle lands in range, however far; NaN and infinities give NaN.
    for (float x : {3.4028235e38f, -3.4028235e38f, 1e30f, -1e20f}) {
        const float wound = i2d::wind_angle(x);
        I2D_CHECK(wound > -pi_f && wound <= pi_f);
    }
    I2D_CHECK(std::isnan(i2d::wind_angle(std::numeric_limits<float>::infinity())));
    I2D_CHECK(std::isnan(i2d::wind_angle(std::numeric_limits<float>::quiet_NaN())));
}
