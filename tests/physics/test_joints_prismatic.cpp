// SPDX-License-Identifier: MIT
// A prismatic joint as a frictionless 30 degree incline: a box on a rail down the slope
// accelerates at g sin(theta); a limit stops it where it says; a motor drives it up the
// slope at the motor's speed, never pushing harder than its maximum force (F = m a).
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

constexpr double incline = pi / 6.0;  // rad, 30 degrees
const i2d_vec2 rail_top{0.0f, 10.0f};

// The rail's axis, pointing down the slope: translation grows as the box slides down.
i2d_vec2 down_slope() { return i2d_vec2{float(std::cos(incline)), float(-std::sin(incline))}; }

struct Incline {
    i2d_body_id box;
    i2d_joint_id joint;
};

// A 1 m box (1 kg) on a rail from a static body at the top of the slope; `edit` sets the
// limit or motor on the def before creation.
template <class Edit>
Incline make_incline(Scene& s, Edit edit) {
    const i2d_body_id ground = s.anchor(rail_top);
    const i2d_body_id box = s.dynamic_box(rail_top, 0.5f, 0.5f);
    i2d_prismatic_joint_def def = i2d_default_prismatic_joint_def();
    def.local_axis_a = down_slope();
    edit(def);
    return {box, i2d_joint_create_prismatic(s.world, &join_at(def, ground, box, rail_top))};
}

}  // namespace

// Released at rest, the box slides down at a = g sin(theta): its speed and distance after
// 1 s are a t and a t^2 / 2 within 1 %.
I2D_TEST(phys_joint_prismatic_slides_down_a_frictionless_incline_at_g_sin_theta) {
    Scene s;
    const Incline in = make_incline(s, [](i2d_prismatic_joint_def&) {});
    I2D_REQUIRE(!I2D_IS_NULL(in.box) && !I2D_IS_NULL(in.joint));
    const int steps = steps_for(1.0);
    I2D_REQUIRE(s.step(steps));
    const double t = steps * double(time_step), a = s.gravity() * std::sin(incline);
    const double v = i2d_prismatic_joint_get_speed(in.joint), d = i2d_prismatic_joint_get_translation(in.joint);
    // The body's own velocity, projected on the slope, must say the same as the joint.
    const i2d_vec2 vb = velocity(in.box), axis = down_slope();
    fprintf(stderr, "    after %.2f s: speed %.5f m/s (a t = %.5f, %+.3f %%), distance %.5f m (a t^2/2 = %.5f, "
            "%+.3f %%); acceleration %.4f m/s^2 vs g sin 30 = %.4f\n",
            t, v, a * t, 100.0 * (v / (a * t) - 1.0), d, 0.5 * a * t * t, 100.0 * (d / (0.5 * a * t * t) - 1.0),
            v / t, a);
    I2D_CHECK_NEAR(v, a * t, 0.01 * a * t);
    I2D_CHECK_NEAR(d, 0.5 * a * t * t, 0.01 * 0.5 * a * t * t);
    I2D_CHECK_NEAR(double(vb.x) * axis.x + double(vb.y) * axis.y, v, 0.01 * a * t);
    // It stays on the rail: no speed across it.
    I2D_CHECK_NEAR(double(vb.x) * -axis.y + double(vb.y) * axis.x, 0.0, 0.01 * a * t);
}

// A limit 1 m down the rail stops the box, arriving at about 3 m/s, within 1 mm of it, and
// holds it there.
I2D_TEST(phys_joint_prismatic_limit_stops_the_box_within_1mm) {
    constexpr float upper = 1.0f;       // m down the slope
    constexpr double tolerance = 0.001;  // m
    Scene s;
    const Incline in = make_incline(s, [](i2d_prismatic_joint_def& def) {
        def.enable_limit = true;
        def.lower_translation = -1.0f;
        def.upper_translation = upper;
    });
    I2D_REQUIRE(!I2D_IS_NULL(in.box) && !I2D_IS_NULL(in.joint));
    double furthest = 0.0, arrival_speed = 0.0;
    for (int k = 0; k < steps_for(2.0); ++k) {
        I2D_REQUIRE(s.step());
        const double d = i2d_prismatic_joint_get_translation(in.joint);
        arrival_speed = std::max(arrival_speed, double(i2d_prismatic_joint_get_speed(in.joint)));
        furthest = std::max(furthest, d);
    }
    const double rest = i2d_prismatic_joint_get_translation(in.joint);
    // Speed is sampled after each step: the fastest sample is the last before the box reaches
    // the limit, a t at the last whole step before t = sqrt(2 d / a).
    const double a = s.gravity() * std::sin(incline);
    const double expected_speed = a * double(time_step) * std::floor(std::sqrt(2.0 * upper / a) / double(time_step));
    fprintf(stderr, "    limit %.3f m: furthest %.5f m (%+.3f mm), at rest %.5f m (%+.3f mm); fastest %.3f m/s "
            "(a t at the last step before the limit: %.3f)\n",
            double(upper), furthest, 1000.0 * (furthest - upper), rest, 1000.0 * (rest - upper), arrival_speed,
            expected_speed);
    I2D_CHECK(furthest <= upper + tolerance);
    I2D_CHECK_NEAR(rest, upper, tolerance);
    I2D_CHECK_NEAR(i2d_prismatic_joint_get_speed(in.joint), 0.0, 0.01);
    // It got there the way the incline says, not held back.
    I2D_CHECK_NEAR(arrival_speed, expected_speed, 0.01 * expected_speed);
}

// A motor of max force F = 1.5 m g sin(theta) drives the box up the slope toward 2 m/s:
// with gravity's m g sin(theta) against it, it accelerates at (F - m g sin(theta)) / m
// within 1 %, reaches its speed, then holds it with m g sin(theta), never more than F.
I2D_TEST(phys_joint_prismatic_motor_reaches_its_speed_within_its_max_force) {
    constexpr double force_factor = 1.5;   // max force over the slope's pull
    constexpr float speed_up_slope = 2.0f;  // m/s
    Scene s;
    const double g = s.gravity();
    const double mass = box_mass(0.5, 0.5, 1.0);
    const float max_force = float(force_factor * mass * g * std::sin(incline));
    const Incline in = make_incline(s, [&](i2d_prismatic_joint_def& def) {
        def.enable_motor = true;
        def.motor_speed = -speed_up_slope;  // the axis points down the slope
        def.max_motor_force = max_force;
    });
    I2D_REQUIRE(!I2D_IS_NULL(in.box) && !I2D_IS_NULL(in.joint));
    I2D_CHECK_NEAR(i2d_body_get_mass(in.box), mass, 1e-5);
    const double pull = mass * g * std::sin(incline);
    const double a = (max_force - pull) / mass;  // up the slope
    const double reach = speed_up_slope / a;
    double worst_a = 0.0, worst_force = 0.0, worst_net = 0.0, last_v = 0.0;
    int k = 1;
    for (; k <= steps_for(reach + 1.0); ++k) {
        I2D_REQUIRE(s.step());
        const double v = -double(i2d_prismatic_joint_get_speed(in.joint));  // up the slope
        const double t = k * double(time_step);
        if (t < 0.9 * reach) {
            worst_a = std::max(worst_a, std::fabs(v / t - a) / a);
        }
        worst_force = std::max(worst_force, std::fabs(double(i2d_prismatic_joint_get_motor_force(in.joint))));
        // F = m a: the net force the step's change of speed implies, motor minus the slope's pull.
        worst_net = std::max(worst_net, mass * (v - last_v) / double(time_step) + pull);
        last_v = v;
    }
    const double hold = std::fabs(double(i2d_prismatic_joint_get_motor_force(in.joint)));
    fprintf(stderr, "    a = (F - m g sin)/m = %.4f m/s^2, worst step %.3f %% off; speed %.5f m/s (motor %.1f); "
            "largest motor force %.4f N, largest m dv/dt + m g sin %.4f N, of max %.4f N; holding %.4f N "
            "(m g sin = %.4f)\n",
            a, 100.0 * worst_a, last_v, double(speed_up_slope), worst_force, worst_net, double(max_force), hold, pull);
    I2D_CHECK(worst_a <= 0.01);
    I2D_CHECK_NEAR(last_v, speed_up_slope, 1e-3 * speed_up_slope);
    I2D_CHECK(worst_force <= max_force * (1.0 + 1e-4));
    I2D_CHECK(worst_net <= max_force * (1.0 + 1e-3));
    I2D_CHECK_NEAR(hold, pull, 0.01 * pull);
}
