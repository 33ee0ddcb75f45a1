// SPDX-License-Identifier: MIT
// Wheel joints against closed form: a car on its suspension springs sags by its weight over
// their stiffness.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstdio>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

double cross(i2d_vec2 a, i2d_vec2 b) { return double(a.x) * b.y - double(a.y) * b.x; }

}  // namespace

// A car resting on flat ground: a 2.5 x 0.5 m chassis on two wheels with vertical wheel
// joints (springs of 4 Hz, damping ratio 0.7). Each spring carries half the chassis'
// weight, M g / 2, so it shortens by that over its stiffness k.
//
// k is the joint's hertz in the soft-constraint model: k = m_eff (2 pi f)^2, m_eff the
// suspension's effective mass along its axis,
//   1 / m_eff = 1/M + 1/m_wheel + (r_a x axis)^2 / I_chassis + (r_b x axis)^2 / I_wheel,
// r_a from the chassis' centre of mass to the wheel's anchor, r_b from the wheel's (0 here).
I2D_TEST(phys_joint_wheel_car_sags_by_its_weight_over_the_spring_stiffness) {
    constexpr float wheel_radius = 0.4f, axle_x = 1.0f;
    constexpr float chassis_half_width = 1.25f, chassis_half_height = 0.25f, axle_below_chassis = 0.5f;
    constexpr float spring_hertz = 4.0f, damping_ratio = 0.7f;
    Scene s;
    I2D_REQUIRE(!I2D_IS_NULL(s.ground(0.0f)));
    const Material steel_ish = with_density(2.0f);
    const i2d_vec2 chassis_at{0.0f, wheel_radius + axle_below_chassis};
    const i2d_body_id chassis = s.dynamic_box(chassis_at, chassis_half_width, chassis_half_height, steel_ish);
    I2D_REQUIRE(!I2D_IS_NULL(chassis));
    i2d_joint_id joints[2];
    i2d_body_id wheels[2];
    const i2d_vec2 axis{0.0f, 1.0f};
    for (int side = 0; side < 2; ++side) {
        const i2d_vec2 axle{side == 0 ? -axle_x : axle_x, wheel_radius};
        wheels[side] = s.dynamic_circle(axle, wheel_radius);
        i2d_wheel_joint_def def = i2d_default_wheel_joint_def();
        def.local_axis_a = axis;
        def.enable_spring = true;
        def.hertz = spring_hertz;
        def.damping_ratio = damping_ratio;
        joints[side] = i2d_joint_create_wheel(s.world, &join_at(def, chassis, wheels[side], axle));
        I2D_REQUIRE(!I2D_IS_NULL(wheels[side]) && !I2D_IS_NULL(joints[side]));
    }
    const double big_m = i2d_body_get_mass(chassis), m_wheel = i2d_body_get_mass(wheels[0]);
    const double i_chassis = i2d_body_get_rotational_inertia(chassis), i_wheel = i2d_body_get_rotational_inertia(wheels[0]);
    const i2d_vec2 com = i2d_body_get_world_center_of_mass(chassis);
    const i2d_vec2 r_a{-axle_x - com.x, wheel_radius - com.y};
    const double ra = cross(r_a, axis);
    const double m_eff = 1.0 / (1.0 / big_m + 1.0 / m_wheel + ra * ra / i_chassis + 0.0 / i_wheel);
    const double omega = 2.0 * pi * spring_hertz;
    const double k = m_eff * omega * omega;
    const double expected = big_m * s.gravity() / 2.0 / k;
    I2D_REQUIRE(s.step(steps_for(4.0)));
    const double sag[2] = {i2d_wheel_joint_get_translation(joints[0]), i2d_wheel_joint_get_translation(joints[1])};
    fprintf(stderr, "    M %.3f kg, wheel %.3f kg, m_eff %.4f kg, k %.2f N/m: M g / 2k = %.2f mm; measured %.2f and "
            "%.2f mm (%+.2f %%)\n",
            big_m, m_wheel, m_eff, k, 1000.0 * expected, 1000.0 * sag[0], 1000.0 * sag[1],
            100.0 * (sag[0] / expected - 1.0));
    // The wheel rides up the axis as the chassis settles onto the springs.
    I2D_CHECK_NEAR(sag[0], expected, 0.05 * expected);
    I2D_CHECK_NEAR(sag[1], expected, 0.05 * expected);
    I2D_CHECK_NEAR(angle_of(chassis), 0.0, 1e-3);
}

