// SPDX-License-Identifier: MIT
// Mouse joints against closed form: one drags a box onto its target, holds a box against
// gravity where its spring balances the weight, and drags a box over a floor to where static
// friction holds it, wherever the box is held.
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

namespace {

// Issue 43's drag: a 1 kg unit box on a floor, friction 0.6 on both (0.6 mixed), gravity
// 10, pulled by a 5 Hz mouse joint with the default damping ratio and max force.
constexpr float drag_hertz = 5.0f;
constexpr float drag_distance = 1.0f;  // m
constexpr float drag_speed = 0.1f;     // m/s: slow, so that the box creeps to a stop
constexpr double hold_seconds = 3.0;   // after the target stops
/** Share of the closed form the stopping offset may miss it by (issue 43's target). */
constexpr double stop_tolerance = 0.10;

struct Drag {
    double behind;  // m: how far the anchor rests behind the target, along the drag
    double below;   // m: how far below it
    double angle;   // rad: the box's turn
};

// Grabs the box at `grab` (box frame) and drags the target drag_distance along +x at
// drag_speed, then holds it for hold_seconds. `on_ground`: the joint's body A is the
// floor itself, not a body without shapes.
Drag drag_box(i2d_vec2 grab, bool on_ground) {
    Scene s(Scene::no_sleep_def());
    const i2d_body_id floor = s.ground();
    const i2d_body_id holder = s.anchor();
    const i2d_body_id box = s.dynamic_box(i2d_vec2{0.0f, 0.5f}, 0.5f, 0.5f);
    Drag d{};
    if (I2D_IS_NULL(floor) || I2D_IS_NULL(holder) || I2D_IS_NULL(box)) {
        ++i2d_check_failures;
        return d;
    }
    i2d_mouse_joint_def def = i2d_default_mouse_joint_def();
    def.base.body_a = on_ground ? floor : holder;
    def.base.body_b = box;
    def.base.local_anchor_b = grab;
    def.hertz = drag_hertz;
    const i2d_vec2 start = i2d_body_get_world_point(box, grab);
    def.target = start;
    const i2d_joint_id joint = i2d_joint_create_mouse(s.world, &def);
    if (I2D_IS_NULL(joint)) {
        ++i2d_check_failures;
        return d;
    }
    const int drag_steps = steps_for(drag_distance / drag_speed);
    const i2d_vec2 end{start.x + drag_distance, start.y};
    for (int k = 1; k <= drag_steps + steps_for(hold_seconds); ++k) {
        const float moved = std::fmin(drag_distance, drag_speed * float(k) * time_step);
        i2d_mouse_joint_set_target(joint, i2d_vec2{start.x + moved, start.y});
        if (!s.step()) {
            ++i2d_check_failures;
            return d;
        }
    }
    const i2d_vec2 anchor = i2d_body_get_world_point(box, grab);
    d.behind = double(end.x) - anchor.x;
    d.below = double(end.y) - anchor.y;
    d.angle = angle_of(box);
    return d;
}

}  // namespace

// Static friction holds the box where the spring's pull, k x with k = m (2 pi f)^2, falls
// to mu m g: it stops within mu g / (2 pi f)^2 = 6.08 mm of the target, wherever it is
// held, and creeping to a stop it stops about there. Grabs low enough not to tip it (a
// pull at height h tips a unit box once mu h > 1/2): the centre, the bottom corners and
// the bottom's middle, a side's middle, a point off both axes. Before issue 43 the spring
// took the anchor's effective mass for m: held at the bottom's middle or its front corner
// the box stopped 14.3 mm away, at its back corner 7.1 mm. The
// control holds the box from the floor body itself: a joint stops its two bodies
// colliding, so the box sinks into the floor and hangs g / (2 pi f)^2 = 10.1 mm below the
// target (the figure issue 43 measured), never where friction would hold it.
I2D_TEST(phys_joint_mouse_drags_a_box_to_where_friction_holds_it_wherever_it_is_held) {
    const double omega = 2.0 * pi * double(drag_hertz);
    const double friction = 0.6;
    const double expected = friction * g / (omega * omega);
    const i2d_vec2 grabs[] = {{0.0f, 0.0f}, {0.5f, -0.5f}, {-0.5f, -0.5f}, {0.0f, -0.5f}, {0.5f, 0.0f},
                              {-0.5f, 0.0f}, {0.3f, 0.2f}};
    for (const i2d_vec2 grab : grabs) {
        const int before = i2d_check_failures;
        const Drag d = drag_box(grab, false);
        fprintf(stderr, "    held at (%+.1f, %+.1f): stops %.3f mm behind the target (%.3f mm below), closed form %.3f "
                "mm (%+.2f %%), turned %.2g rad\n", double(grab.x), double(grab.y), 1000.0 * d.behind,
                1000.0 * d.below, 1000.0 * expected, 100.0 * (d.behind / expected - 1.0), d.angle);
        I2D_CHECK_NEAR(d.behind, expected, stop_tolerance * expected);
        char what[64];
        snprintf(what, sizeof what, "held at (%.1f, %.1f)", double(grab.x), double(grab.y));
        report_case(before, what);
    }
    const Drag control = drag_box(i2d_vec2{0.0f, 0.0f}, true);
    const double sag = g / (omega * omega);
    fprintf(stderr, "    held from the floor body: %.3f mm behind, %.3f mm below the target (g / w^2 = %.3f mm)\n",
            1000.0 * control.behind, 1000.0 * control.below, 1000.0 * sag);
    I2D_CHECK(std::fabs(control.behind - expected) > stop_tolerance * expected);
    I2D_CHECK_NEAR(control.below, sag, stop_tolerance * sag);
}
