// SPDX-License-Identifier: MIT
// Weld, wheel and mouse joints against closed form: a rigid weld holds a body still under
// gravity, a welded cantilever keeps its shape, a car on wheel joints sags by its weight
// over the springs' stiffness, and a mouse joint drags a box onto its target.
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

double gravity(const Scene& s) { return -double(i2d_world_get_gravity(s.world).y); }

double cross(i2d_vec2 a, i2d_vec2 b) { return double(a.x) * b.y - double(a.y) * b.x; }

}  // namespace

// A 1 m bar welded by one end to a static body, sticking out sideways: gravity pulls and
// twists it, and the (rigid) weld keeps both its ends within 1 mm of where they started.
I2D_TEST(phys_joint_weld_to_static_holds_within_1mm_under_gravity) {
    constexpr double tolerance = 0.001;  // m
    Scene s;
    const i2d_vec2 wall{0.0f, 5.0f};
    const i2d_body_id ground = s.anchor(wall);
    const i2d_body_id bar = s.dynamic_box(i2d_vec2{wall.x + 0.5f, wall.y}, 0.5f, 0.1f);
    i2d_weld_joint_def def = i2d_default_weld_joint_def();
    const i2d_joint_id joint = i2d_joint_create_weld(s.world, &join_at(def, ground, bar, wall));
    I2D_REQUIRE(!I2D_IS_NULL(bar) && !I2D_IS_NULL(joint));
    const i2d_vec2 far_end_local{0.5f, 0.0f};
    const i2d_vec2 far_start = i2d_body_get_world_point(bar, far_end_local);
    const i2d_vec2 centre_start = position(bar);
    double worst = 0.0;
    for (int k = 0; k < steps_for(3.0); ++k) {
        I2D_REQUIRE(s.step());
        const i2d_vec2 far = i2d_body_get_world_point(bar, far_end_local), c = position(bar);
        worst = std::max({worst, std::hypot(double(far.x - far_start.x), double(far.y - far_start.y)),
                          std::hypot(double(c.x - centre_start.x), double(c.y - centre_start.y))});
    }
    fprintf(stderr, "    worst displacement of the bar's centre or far end: %.4f mm (allowed 1 mm); angle %.2e rad; "
            "reaction (%.4f, %.4f) N, %.4f N m (weight %.4f N, its torque %.4f N m)\n",
            1000.0 * worst, angle(bar), double(i2d_joint_get_reaction_force(joint).x),
            double(i2d_joint_get_reaction_force(joint).y), double(i2d_joint_get_reaction_torque(joint)),
            double(i2d_body_get_mass(bar)) * gravity(s), double(i2d_body_get_mass(bar)) * gravity(s) * 0.5);
    I2D_CHECK(worst < tolerance);
}

// Ten 0.5 m boxes welded end to end out of a wall: the cantilever holds its shape. Its
// tip drops less than 2 % of its 5 m (10 cm: a bend of about a degree), no box turns more
// than 2 degrees, and it is still: the tip moves less than 1 mm between 2 s and 5 s.
I2D_TEST(phys_joint_weld_cantilever_of_10_boxes_holds_its_shape) {
    constexpr int box_count = 10;
    constexpr float box_half_length = 0.25f, box_half_height = 0.1f;
    constexpr double length = 2.0 * box_half_length * box_count;
    constexpr double max_drop = 0.02 * length;         // m
    constexpr double max_turn = 2.0 * pi / 180.0;      // rad
    constexpr double max_creep = 0.001;                // m
    Scene s;
    const i2d_vec2 wall{0.0f, 10.0f};
    i2d_body_id previous = s.anchor(wall);
    std::vector<i2d_body_id> boxes;
    for (int i = 0; i < box_count; ++i) {
        const float left = wall.x + 2.0f * box_half_length * float(i);
        const i2d_body_id box = s.dynamic_box(i2d_vec2{left + box_half_length, wall.y}, box_half_length,
                                              box_half_height);
        i2d_weld_joint_def def = i2d_default_weld_joint_def();
        I2D_REQUIRE(!I2D_IS_NULL(box) &&
                    !I2D_IS_NULL(i2d_joint_create_weld(s.world, &join_at(def, previous, box, i2d_vec2{left, wall.y}))));
        boxes.push_back(box);
        previous = box;
    }
    const i2d_vec2 tip_local{box_half_length, 0.0f};
    I2D_REQUIRE(s.step(steps_for(2.0)));
    const i2d_vec2 tip_at_2s = i2d_body_get_world_point(boxes.back(), tip_local);
    I2D_REQUIRE(s.step(steps_for(3.0)));
    const i2d_vec2 tip = i2d_body_get_world_point(boxes.back(), tip_local);
    double turn = 0.0;
    bool finite = true;
    for (const i2d_body_id b : boxes) {
        turn = std::max(turn, std::fabs(angle(b)));
        finite = finite && is_finite(b);
    }
    const double drop = double(wall.y) - double(tip.y);
    const double creep = std::hypot(double(tip.x - tip_at_2s.x), double(tip.y - tip_at_2s.y));
    fprintf(stderr, "    tip dropped %.2f cm (allowed %.0f cm), largest box angle %.3f deg, tip moved %.4f mm "
            "between 2 s and 5 s\n",
            100.0 * drop, 100.0 * max_drop, turn * 180.0 / pi, 1000.0 * creep);
    I2D_CHECK(finite);
    I2D_CHECK(drop < max_drop);
    I2D_CHECK(turn < max_turn);
    I2D_CHECK(creep < max_creep);
}

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
    Material steel_ish;
    steel_ish.density = 2.0f;
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
    const double expected = big_m * gravity(s) / 2.0 / k;
    I2D_REQUIRE(s.step(steps_for(4.0)));
    const double sag[2] = {i2d_wheel_joint_get_translation(joints[0]), i2d_wheel_joint_get_translation(joints[1])};
    fprintf(stderr, "    M %.3f kg, wheel %.3f kg, m_eff %.4f kg, k %.2f N/m: M g / 2k = %.2f mm; measured %.2f and "
            "%.2f mm (%+.2f %%)\n",
            big_m, m_wheel, m_eff, k, 1000.0 * expected, 1000.0 * sag[0], 1000.0 * sag[1],
            100.0 * (sag[0] / expected - 1.0));
    // The wheel rides up the axis as the chassis settles onto the springs.
    I2D_CHECK_NEAR(sag[0], expected, 0.05 * expected);
    I2D_CHECK_NEAR(sag[1], expected, 0.05 * expected);
    I2D_CHECK_NEAR(angle(chassis), 0.0, 1e-3);
}

// No gravity: a mouse joint (the default 4 Hz, damping ratio 1, 1000 N) pulls a 1 kg box
// onto a target 5 m away; 2 s later the box is within 1 cm of it.
I2D_TEST(phys_joint_mouse_drags_a_1kg_box_5m_onto_its_target_within_1cm_in_2s) {
    Scene s(Scene::zero_gravity_def());
    const i2d_body_id ground = s.anchor();
    const i2d_body_id box = s.dynamic_box(i2d_vec2{0.0f, 0.0f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_CHECK_NEAR(i2d_body_get_mass(box), 1.0, 1e-6);
    i2d_mouse_joint_def def = i2d_default_mouse_joint_def();
    def.base.body_a = ground;
    def.base.body_b = box;
    def.target = i2d_vec2{5.0f, 0.0f};
    const i2d_joint_id joint = i2d_joint_create_mouse(s.world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(joint));
    I2D_REQUIRE(s.step(steps_for(2.0)));
    const i2d_vec2 p = position(box);
    const double miss = std::hypot(double(p.x) - 5.0, double(p.y));
    fprintf(stderr, "    after 2 s the box is %.3f mm from the target (allowed 10 mm), moving %.4f m/s\n",
            1000.0 * miss, speed(velocity(box)));
    I2D_CHECK(miss < 0.01);
}

// With gravity the mouse spring (k = m w^2 for an anchor at the centre of mass) holds the
// box g / w^2 below the target: 15.8 mm at 4 Hz, within 5 %.
I2D_TEST(phys_joint_mouse_holds_a_box_g_over_omega_squared_below_its_target) {
    Scene s;
    const i2d_body_id ground = s.anchor();
    const i2d_vec2 target{0.0f, 5.0f};
    const i2d_body_id box = s.dynamic_box(target, 0.5f, 0.5f);
    i2d_mouse_joint_def def = i2d_default_mouse_joint_def();
    def.base.body_a = ground;
    def.base.body_b = box;
    def.target = target;
    const i2d_joint_id joint = i2d_joint_create_mouse(s.world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(joint));
    I2D_REQUIRE(s.step(steps_for(3.0)));
    const double omega = 2.0 * pi * double(def.hertz);
    const double expected = gravity(s) / (omega * omega);
    const double below = double(target.y) - double(position(box).y);
    fprintf(stderr, "    box %.3f mm below the target, g / w^2 = %.3f mm (%+.2f %%)\n", 1000.0 * below,
            1000.0 * expected, 100.0 * (below / expected - 1.0));
    I2D_CHECK_NEAR(below, expected, 0.05 * expected);
    I2D_CHECK_NEAR(position(box).x, target.x, 1e-4);
}
