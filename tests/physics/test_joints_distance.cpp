// SPDX-License-Identifier: MIT
// A distance joint's spring against the damped harmonic oscillator: a mass on a spring to
// a static body, no gravity, oscillates at the spring's hertz and, damped, loses amplitude
// per cycle as exp(-2 pi zeta / sqrt(1 - zeta^2)).
//
// The spring's stiffness is k = m_eff (2 pi f)^2 (the soft-constraint model: a spring of
// frequency f on the constraint's effective mass). With the anchor at the body's centre
// and the other body static, m_eff is the body's mass, so the natural frequency is f.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstdio>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

constexpr float rest_length = 2.0f;   // m
constexpr float amplitude = 0.1f;     // m, the start's stretch
constexpr float spring_hertz = 1.0f;  // Hz: a game's soft spring
const i2d_vec2 fixed_end{0.0f, 0.0f};

struct Spring {
    i2d_body_id mass;
    i2d_joint_id joint;
};

// A mass on a spring is measured for seconds as its amplitude decays, so sleep is off (the
// world would rightly put a body this slow to sleep, freezing the oscillation).
i2d_world_def spring_world_def() { return Scene::no_sleep_def(Scene::zero_gravity_def()); }

// A 0.25 m disc on a spring of rest_length from a static point, released at rest
// stretched by `amplitude` along x.
Spring make_spring(Scene& s, float damping_ratio) {
    const i2d_body_id ground = s.anchor(fixed_end);
    const i2d_body_id mass = s.dynamic_circle(i2d_vec2{fixed_end.x + rest_length + amplitude, fixed_end.y}, 0.25f);
    i2d_distance_joint_def def = i2d_default_distance_joint_def();
    def.base.body_a = ground;
    def.base.body_b = mass;
    def.length = rest_length;
    def.enable_spring = true;
    def.hertz = spring_hertz;
    def.damping_ratio = damping_ratio;
    return {mass, i2d_joint_create_distance(s.world, &def)};
}

// Steps `seconds`, recording the stretch (length minus rest length).
Oscillation run(Scene& s, const Spring& spring, double seconds) {
    Oscillation o;
    for (int k = 1; k <= steps_for(seconds); ++k) {
        if (!s.step()) {
            ++i2d_check_failures;
            break;
        }
        o.add(k * double(time_step), double(i2d_distance_joint_get_current_length(spring.joint)) - rest_length);
    }
    return o;
}

}  // namespace

// Undamped, it oscillates at the spring's hertz within 2 %, and keeps its amplitude.
I2D_TEST(phys_joint_distance_spring_oscillates_at_its_hertz) {
    Scene s(spring_world_def());
    const Spring spring = make_spring(s, 0.0f);
    I2D_REQUIRE(!I2D_IS_NULL(spring.mass) && !I2D_IS_NULL(spring.joint));
    const Oscillation o = run(s, spring, 10.0);
    const double frequency = o.period() > 0.0 ? 1.0 / o.period() : 0.0;
    fprintf(stderr, "    measured %.4f Hz over %zu cycles, spring %.4f Hz (%+.2f %%); amplitude after 10 s %.4f m "
            "of %.4f\n",
            frequency, o.up_crossings.size() - 1, double(spring_hertz), 100.0 * (frequency / spring_hertz - 1.0),
            o.extremes.empty() ? 0.0 : std::fabs(o.extremes.back()), double(amplitude));
    I2D_CHECK(o.up_crossings.size() >= 8);
    I2D_CHECK_NEAR(frequency, spring_hertz, 0.02 * spring_hertz);
    // Undamped, nothing takes energy out: the last swing is as wide as the first, within 2 %.
    I2D_REQUIRE(!o.extremes.empty());
    I2D_CHECK_NEAR(std::fabs(o.extremes.back()), amplitude, 0.02 * amplitude);
}

// With damping ratio 0.1 each cycle keeps exp(-2 pi zeta / sqrt(1 - zeta^2)) = 0.532 of
// the amplitude, within 5 % (measured over the first four cycles, peak to same-sign peak).
I2D_TEST(phys_joint_distance_damped_spring_decays_per_cycle_as_exp_minus_2pi_zeta) {
    constexpr double zeta = 0.1;
    constexpr int cycles = 4;
    Scene s(spring_world_def());
    const Spring spring = make_spring(s, float(zeta));
    I2D_REQUIRE(!I2D_IS_NULL(spring.mass) && !I2D_IS_NULL(spring.joint));
    const Oscillation o = run(s, spring, 6.0);
    I2D_REQUIRE(o.extremes.size() > size_t(2 * cycles));
    const double expected = std::exp(-2.0 * pi * zeta / std::sqrt(1.0 - zeta * zeta));
    // Geometric mean of the per-cycle ratios: peak 2 cycles on over peak 0, and so on.
    const double measured = std::pow(o.extremes[2 * cycles] / o.extremes[0], 1.0 / cycles);
    fprintf(stderr, "    amplitude kept per cycle %.4f, closed form %.4f (%+.2f %%); peaks", measured, expected,
            100.0 * (measured / expected - 1.0));
    for (size_t k = 0; k <= size_t(2 * cycles); ++k) {
        fprintf(stderr, " %.4f", o.extremes[k]);
    }
    fprintf(stderr, "\n");
    I2D_CHECK_NEAR(measured, expected, 0.05 * expected);
}
