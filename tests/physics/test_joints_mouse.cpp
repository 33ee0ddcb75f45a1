// SPDX-License-Identifier: MIT
// Mouse joints against closed form: one drags a box onto its target, and holds a box against
// gravity where its spring balances the weight.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstdio>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

}  // namespace

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
    const double miss = distance(position(box), def.target);
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
    const double expected = s.gravity() / (omega * omega);
    const double below = double(target.y) - double(position(box).y);
    fprintf(stderr, "    box %.3f mm below the target, g / w^2 = %.3f mm (%+.2f %%)\n", 1000.0 * below,
            1000.0 * expected, 100.0 * (below / expected - 1.0));
    I2D_CHECK_NEAR(below, expected, 0.05 * expected);
    I2D_CHECK_NEAR(position(box).x, target.x, 1e-4);
}
