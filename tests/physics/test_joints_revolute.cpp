// SPDX-License-Identifier: MIT
// Revolute joints against closed form: a pendulum's period and energy, a hanging
// pendulum's reaction force, and a motor's spin-up at its maximum torque.
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

constexpr float pendulum_length = 1.0f;  // m, pivot to the bob's centre
constexpr float bob_radius = 0.05f;      // m: nearly a point mass
const i2d_vec2 pivot{0.0f, 10.0f};

struct Pendulum {
    i2d_body_id bob;
    i2d_joint_id joint;
};

// A disc of bob_radius hanging from a static pivot by a revolute joint, released at rest
// `start_angle` (rad) from straight down, counter-clockwise.
Pendulum make_pendulum(Scene& s, double start_angle) {
    const i2d_body_id ground = s.anchor(pivot);
    const i2d_vec2 at{pivot.x + pendulum_length * float(std::sin(start_angle)),
                      pivot.y - pendulum_length * float(std::cos(start_angle))};
    const i2d_body_id bob = s.dynamic_circle(at, bob_radius);
    i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
    return {bob, i2d_joint_create_revolute(s.world, &join_at(def, ground, bob, pivot))};
}

// Period of a physical pendulum (a body turning about a pivot at distance L from its
// centre of mass): 2 pi sqrt(I_pivot / (m g L)), I_pivot = I_cm + m L^2; the finite swing
// amplitude lengthens it by (1 + theta0^2 / 16) to second order.
double physical_pendulum_period(i2d_body_id bob, double g, double amplitude) {
    const double m = i2d_body_get_mass(bob), i_cm = i2d_body_get_rotational_inertia(bob);
    const double l = pendulum_length;
    return 2.0 * pi * std::sqrt((i_cm + m * l * l) / (m * g * l)) * (1.0 + amplitude * amplitude / 16.0);
}

}  // namespace

// Swung 0.05 rad and left for 60 s, the pendulum keeps the period of the closed form
// (2 pi sqrt(L / g) for a point bob) within 1 %.
I2D_TEST(phys_joint_pendulum_small_angle_period_is_2pi_sqrt_l_over_g) {
    constexpr double amplitude = 0.05;  // rad: the small-angle regime (period +0.016 %)
    constexpr double duration = 60.0;   // s
    Scene s;
    const Pendulum p = make_pendulum(s, amplitude);
    I2D_REQUIRE(!I2D_IS_NULL(p.bob) && !I2D_IS_NULL(p.joint));
    const double g = s.gravity();
    Oscillation swing;
    double worst_length_error = 0.0;
    for (int k = 1; k <= steps_for(duration); ++k) {
        I2D_REQUIRE(s.step());
        const i2d_vec2 x = position(p.bob);
        swing.add(k * double(time_step), double(x.x - pivot.x));
        worst_length_error = std::max(worst_length_error, std::fabs(distance(x, pivot) - pendulum_length));
    }
    const double expected = physical_pendulum_period(p.bob, g, amplitude);
    const double point_mass = 2.0 * pi * std::sqrt(pendulum_length / g);
    fprintf(stderr, "    measured period %.5f s over %zu cycles; physical pendulum %.5f s, 2 pi sqrt(L/g) %.5f s; "
            "error %.3f %%; worst bob distance error %.2f mm\n",
            swing.period(), swing.up_crossings.size() - 1, expected, point_mass,
            100.0 * (swing.period() / expected - 1.0), 1000.0 * worst_length_error);
    I2D_CHECK(swing.up_crossings.size() >= 25);  // it swung the whole time (T ~ 2 s)
    I2D_CHECK_NEAR(swing.period(), expected, 0.01 * expected);
    // The bob stays on its circle: the joint holds the length.
    I2D_CHECK(worst_length_error < 0.001);
}

// Undamped, a pendulum released at 60 degrees keeps its energy within 2 % for 60 s.
I2D_TEST(phys_joint_pendulum_keeps_its_energy_within_2_percent_over_60s) {
    constexpr double amplitude = pi / 3.0;  // rad
    constexpr double duration = 60.0;       // s
    Scene s;
    const Pendulum p = make_pendulum(s, amplitude);
    I2D_REQUIRE(!I2D_IS_NULL(p.bob) && !I2D_IS_NULL(p.joint));
    const double g = s.gravity(), m = i2d_body_get_mass(p.bob);
    // Energy measured from the lowest point the bob can reach.
    auto energy = [&] {
        return kinetic_energy(p.bob) + m * g * (double(position(p.bob).y) - (double(pivot.y) - pendulum_length));
    };
    const double e0 = energy();
    const double expected = m * g * pendulum_length * (1.0 - std::cos(amplitude));
    I2D_CHECK_NEAR(e0, expected, 1e-4 * expected);  // the start is what the test means it to be
    double worst = 0.0, last = e0;
    for (int k = 1; k <= steps_for(duration); ++k) {
        I2D_REQUIRE(s.step());
        last = energy();
        worst = std::max(worst, std::fabs(last - e0));
    }
    fprintf(stderr, "    energy %.5f J at the start, %.5f J after 60 s (%+.2f %%); worst deviation %.2f %%\n", e0,
            last, 100.0 * (last / e0 - 1.0), 100.0 * worst / e0);
    I2D_CHECK(worst <= 0.02 * e0);
}

// A pendulum hanging at rest: the joint holds up exactly its weight, so the reaction on
// the bob is (0, m g) within 1 %, with no torque.
I2D_TEST(phys_joint_hanging_pendulum_reaction_force_is_its_weight) {
    Scene s;
    const Pendulum p = make_pendulum(s, 0.0);
    I2D_REQUIRE(!I2D_IS_NULL(p.bob) && !I2D_IS_NULL(p.joint));
    I2D_REQUIRE(s.step(steps_for(1.0)));
    const double weight = double(i2d_body_get_mass(p.bob)) * s.gravity();
    const i2d_vec2 f = i2d_joint_get_reaction_force(p.joint);
    fprintf(stderr, "    reaction (%.5f, %.5f) N, weight %.5f N (%+.3f %%), torque %.2e N m\n", f.x, f.y, weight,
            100.0 * (double(f.y) / weight - 1.0), double(i2d_joint_get_reaction_torque(p.joint)));
    I2D_CHECK_NEAR(f.x, 0.0, 0.01 * weight);
    I2D_CHECK_NEAR(f.y, weight, 0.01 * weight);
    // The pivot is at the bob's centre line: any torque is only rounding.
    I2D_CHECK_NEAR(i2d_joint_get_reaction_torque(p.joint), 0.0, 0.01 * weight * bob_radius);
}

// A disc pinned at its centre, driven by a motor of max torque tau toward a speed it takes
// seconds to reach: it spins up at alpha = tau / I within 2 %, then holds the speed with
// no more than tau.
I2D_TEST(phys_joint_revolute_motor_spins_up_at_max_torque_over_inertia) {
    constexpr float radius = 0.5f;        // m
    constexpr float max_torque = 0.5f;    // N m
    constexpr float motor_speed = 10.0f;  // rad/s
    Scene s;
    const i2d_vec2 centre{0.0f, 5.0f};
    const i2d_body_id ground = s.anchor(centre);
    const i2d_body_id disc = s.dynamic_circle(centre, radius);
    i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
    def.enable_motor = true;
    def.motor_speed = motor_speed;
    def.max_motor_torque = max_torque;
    const i2d_joint_id joint = i2d_joint_create_revolute(s.world, &join_at(def, ground, disc, centre));
    I2D_REQUIRE(!I2D_IS_NULL(disc) && !I2D_IS_NULL(joint));
    const double inertia = i2d_body_get_rotational_inertia(disc);
    const double alpha = max_torque / inertia;
    const double reach = motor_speed / alpha;  // s until the motor is at speed
    I2D_REQUIRE(reach > 1.0);                  // the spin-up is long enough to measure
    double worst = 0.0, worst_torque = 0.0;
    int k = 1;
    for (; k * double(time_step) <= 0.9 * reach; ++k) {
        I2D_REQUIRE(s.step());
        const double expected = alpha * k * double(time_step);
        worst = std::max(worst, std::fabs(double(i2d_body_get_angular_velocity(disc)) - expected) / expected);
    }
    const double w_mid = i2d_body_get_angular_velocity(disc), t_mid = (k - 1) * double(time_step);
    for (; k <= steps_for(reach + 2.0); ++k) {
        I2D_REQUIRE(s.step());
        worst_torque = std::max(worst_torque, std::fabs(double(i2d_revolute_joint_get_motor_torque(joint))));
    }
    fprintf(stderr, "    I = %.5f kg m^2: alpha = tau / I = %.4f rad/s^2; measured %.4f rad/s^2 at %.2f s, worst "
            "step %.3f %%; final speed %.5f rad/s; largest torque holding speed %.4f N m\n",
            inertia, alpha, w_mid / t_mid, t_mid, 100.0 * worst, double(i2d_body_get_angular_velocity(disc)),
            worst_torque);
    I2D_CHECK(worst <= 0.02);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(disc), motor_speed, 1e-3 * motor_speed);
    I2D_CHECK(worst_torque <= max_torque * (1.0 + 1e-4));
}
