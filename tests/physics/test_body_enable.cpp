// SPDX-License-Identifier: MIT
// i2d_body_disable and i2d_body_enable: a disabled body is out of the world (what rests on
// it falls through it in free fall, its joints hold nothing, it keeps its pose and
// velocity and whatever it is given), and enabling it brings it back as it was, awake,
// with its contacts and its joints.
#include <impulse2d/impulse2d.h>

#include <cmath>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// Drop after n steps of semi-implicit Euler from rest: g h^2 n (n + 1) / 2 over the substeps.
double euler_drop(double g, int steps) {
    const int n = steps * substeps;
    return g * substep * substep * double(n) * double(n + 1) / 2.0;
}

int touching_pairs(i2d_world_id world) { return i2d_world_get_counters(world).contact_count; }

bool same_pair(i2d_shape_id a, i2d_shape_id b, i2d_shape_id x, i2d_shape_id y) {
    return (I2D_ID_EQUALS(a, x) && I2D_ID_EQUALS(b, y)) || (I2D_ID_EQUALS(a, y) && I2D_ID_EQUALS(b, x));
}

// A revolute joint between a and b at a world point.
i2d_joint_id hinge(i2d_world_id world, i2d_body_id a, i2d_body_id b, i2d_vec2 at) {
    i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
    join_at(def, a, b, at);
    return i2d_joint_create_revolute(world, &def);
}

// How far apart the joint's anchors are, m: 0 while it holds.
double anchor_gap(i2d_body_id a, i2d_body_id b, i2d_vec2 local_a, i2d_vec2 local_b) {
    return distance(i2d_body_get_world_point(a, local_a), i2d_body_get_world_point(b, local_b));
}

}  // namespace

I2D_TEST(phys_enable_box_on_a_disabled_box_falls_through_it_to_the_ground) {
    Scene s;
    I2D_REQUIRE(!I2D_IS_NULL(s.ground()));
    const i2d_body_id lower = s.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    const i2d_body_id upper = s.dynamic_box(i2d_vec2{0, 1.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(lower) && !I2D_IS_NULL(upper));
    I2D_REQUIRE(s.step(steps_for(2.0)));
    I2D_CHECK(!i2d_body_is_awake(upper));  // the pile rests
    const double rest_y = position(upper).y;
    I2D_CHECK_NEAR(rest_y, 1.5, 0.02);

    I2D_REQUIRE(i2d_body_disable(lower) == I2D_OK);
    I2D_CHECK(!i2d_body_is_enabled(lower) && i2d_body_is_enabled(upper));
    I2D_CHECK(i2d_body_is_awake(upper));  // it lost its support
    I2D_CHECK(!i2d_body_is_awake(lower));
    const BodyState lower_before = BodyState::of(lower);
    // Nothing holds it up: free fall from rest, through the space the lower box fills.
    const int steps = steps_for(0.25);
    I2D_REQUIRE(s.step(steps));
    I2D_CHECK_NEAR(rest_y - position(upper).y, euler_drop(g, steps), 1e-4);
    I2D_CHECK_NEAR(position(upper).x, 0.0, 1e-6);
    // Then it lands on the ground below, where the lower box stands.
    I2D_REQUIRE(s.step(steps_for(2.0)));
    I2D_CHECK_NEAR(position(upper).y, 0.5, 0.02);
    I2D_CHECK(speed(velocity(upper)) < 0.01);
    I2D_CHECK(BodyState::of(lower).same_bits(lower_before));
}

I2D_TEST(phys_enable_brings_a_resting_box_back_awake_with_its_contact) {
    Scene s;
    const i2d_body_id ground = s.ground();
    const i2d_body_id box = s.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(box));
    I2D_REQUIRE(s.step(steps_for(1.0)));
    I2D_CHECK(touching_pairs(s.world) == 1);

    // Its contact ends (reported with the next step's events) and does not come back.
    I2D_REQUIRE(i2d_body_disable(box) == I2D_OK);
    I2D_CHECK(i2d_world_get_counters(s.world).pair_count == 0);
    const BodyState before = BodyState::of(box);
    I2D_REQUIRE(s.step());
    const i2d_contact_events ended = i2d_world_get_contact_events(s.world);
    I2D_CHECK(ended.end_count == 1 && ended.begin_count == 0);
    if (ended.end_count == 1) {
        I2D_CHECK(same_pair(ended.end_events[0].shape_a, ended.end_events[0].shape_b, only_shape(ground),
                            only_shape(box)));
    }
    I2D_REQUIRE(s.step(steps_for(1.0)));
    I2D_CHECK(touching_pairs(s.world) == 0);
    I2D_CHECK(BodyState::of(box).same_bits(before));
    I2D_CHECK(!i2d_body_is_awake(box));  // it neither sleeps nor wakes

    I2D_REQUIRE(i2d_body_enable(box) == I2D_OK);
    I2D_CHECK(i2d_body_is_enabled(box) && i2d_body_is_awake(box));
    I2D_REQUIRE(s.step());
    I2D_CHECK(touching_pairs(s.world) == 1);
    I2D_CHECK(i2d_world_get_contact_events(s.world).begin_count == 1);
    // The ground holds it again: it rests where it was and falls asleep.
    I2D_REQUIRE(s.step(steps_for(1.0)));
    I2D_CHECK_NEAR(position(box).y, before.transform.p.y, 1e-3);
    I2D_CHECK(!i2d_body_is_awake(box));
}

// Static bodies leave the static tree: a disabled shelf drops what it carried to the
// floor below, and enabled again it catches a box put above it.
I2D_TEST(phys_enable_disabled_shelf_drops_its_box_and_catches_it_again) {
    Scene s;
    const i2d_body_id floor = s.ground(-5.0f);
    const i2d_body_id shelf = s.ground(0.0f, 2.0f);
    const i2d_body_id box = s.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(floor) && !I2D_IS_NULL(shelf) && !I2D_IS_NULL(box));
    I2D_REQUIRE(s.step(steps_for(1.0)));
    I2D_CHECK(!i2d_body_is_awake(box));

    I2D_REQUIRE(i2d_body_disable(shelf) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(box));
    I2D_REQUIRE(s.step(steps_for(2.0)));
    I2D_CHECK_NEAR(position(box).y, -4.5, 0.02);

    I2D_REQUIRE(i2d_body_enable(shelf) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_transform(box, i2d_vec2{0, 2.0f}, rot(0.0)) == I2D_OK);
    I2D_REQUIRE(s.step(steps_for(2.0)));
    I2D_CHECK_NEAR(position(box).y, 0.5, 0.02);
    I2D_CHECK(speed(velocity(box)) < 0.01);
}

// A bob hanging from a pivot: with the pivot disabled the hinge holds nothing and the bob
// falls freely; enabled, the hinge pulls it back under the pivot.
I2D_TEST(phys_enable_hinge_to_a_disabled_pivot_is_not_solved_until_enabled) {
    Scene s;
    const i2d_vec2 pivot_at{0, 10};
    const i2d_body_id pivot = s.anchor(pivot_at);
    const i2d_body_id bob = s.dynamic_box(i2d_vec2{0, 9}, 0.25f, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(pivot) && !I2D_IS_NULL(bob));
    I2D_REQUIRE(!I2D_IS_NULL(hinge(s.world, pivot, bob, pivot_at)));
    const i2d_vec2 local_bob{0, 1}, local_pivot{0, 0};
    I2D_REQUIRE(s.step(steps_for(1.0)));
    I2D_CHECK(anchor_gap(pivot, bob, local_pivot, local_bob) < 1e-3);

    I2D_REQUIRE(i2d_body_disable(pivot) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(bob));
    const double start_y = position(bob).y;
    const int steps = steps_for(0.3);
    I2D_REQUIRE(s.step(steps));
    I2D_CHECK_NEAR(start_y - position(bob).y, euler_drop(g, steps), 2e-3);
    I2D_CHECK_NEAR(position(bob).x, 0.0, 1e-5);

    I2D_REQUIRE(i2d_body_enable(pivot) == I2D_OK);
    I2D_REQUIRE(s.step(steps_for(3.0)));
    I2D_CHECK(anchor_gap(pivot, bob, local_pivot, local_bob) < 0.01);
}

// A two-link chain: the upper link disabled, neither of its hinges holds, so the lower
// link falls freely and the upper one stays put; enabled, both hinges hold again.
I2D_TEST(phys_enable_hinges_of_a_disabled_link_come_back_when_enabled) {
    Scene s;
    const i2d_vec2 pivot_at{0, 10}, elbow_at{0, 8};
    const i2d_body_id pivot = s.anchor(pivot_at);
    const i2d_body_id upper = s.dynamic_box(i2d_vec2{0, 9}, 0.1f, 1.0f);
    const i2d_body_id lower = s.dynamic_box(i2d_vec2{0, 7}, 0.1f, 1.0f);
    I2D_REQUIRE(!I2D_IS_NULL(pivot) && !I2D_IS_NULL(upper) && !I2D_IS_NULL(lower));
    I2D_REQUIRE(!I2D_IS_NULL(hinge(s.world, pivot, upper, pivot_at)));
    I2D_REQUIRE(!I2D_IS_NULL(hinge(s.world, upper, lower, elbow_at)));
    const i2d_vec2 upper_top{0, 1}, upper_bottom{0, -1}, lower_top{0, 1};
    I2D_REQUIRE(s.step(steps_for(1.0)));

    I2D_REQUIRE(i2d_body_disable(upper) == I2D_OK);
    const BodyState upper_before = BodyState::of(upper);
    const double start_y = position(lower).y;
    const int steps = steps_for(0.3);
    I2D_REQUIRE(s.step(steps));
    I2D_CHECK_NEAR(start_y - position(lower).y, euler_drop(g, steps), 2e-3);
    I2D_CHECK(BodyState::of(upper).same_bits(upper_before));

    I2D_REQUIRE(i2d_body_enable(upper) == I2D_OK);
    I2D_REQUIRE(s.step(steps_for(3.0)));
    I2D_CHECK(anchor_gap(pivot, upper, i2d_vec2{0, 0}, upper_top) < 0.01);
    I2D_CHECK(anchor_gap(upper, lower, upper_bottom, lower_top) < 0.01);
}

// The decision for what a disabled body is given: a velocity set or an impulse changes
// the velocity it keeps, a force acts in its first step back and only then.
I2D_TEST(phys_enable_disabled_body_keeps_its_velocity_and_what_it_is_given) {
    Scene s(Scene::zero_gravity_def());
    const i2d_body_id box = s.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f, Material{}, i2d_vec2{2.0f, 1.0f});
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(i2d_body_set_angular_velocity(box, 0.5f) == I2D_OK);
    I2D_REQUIRE(s.step(10));

    I2D_REQUIRE(i2d_body_disable(box) == I2D_OK);
    const BodyState before = BodyState::of(box);
    I2D_REQUIRE(s.step(60));
    I2D_CHECK(BodyState::of(box).same_bits(before));  // it keeps its velocity and does not move
    I2D_CHECK(!i2d_body_is_awake(box));

    const double mass = i2d_body_get_mass(box);
    const i2d_vec2 center = i2d_body_get_world_center_of_mass(box);
    I2D_REQUIRE(i2d_body_set_linear_velocity(box, i2d_vec2{1.0f, 0.0f}) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_angular_velocity(box, 0.0f) == I2D_OK);
    I2D_REQUIRE(i2d_body_apply_linear_impulse(box, i2d_vec2{0.0f, float(mass)}, center, false) == I2D_OK);
    I2D_CHECK_NEAR(velocity(box).x, 1.0, 1e-6);
    I2D_CHECK_NEAR(velocity(box).y, 1.0, 1e-6);
    I2D_REQUIRE(i2d_body_apply_force_to_center(box, i2d_vec2{float(6.0 * mass), 0.0f}, false) == I2D_OK);
    I2D_CHECK_NEAR(velocity(box).x, 1.0, 1e-6);  // a force waits for the step
    I2D_REQUIRE(s.step(30));
    I2D_CHECK(BodyState::of(box).same_pose(before));
    I2D_CHECK(!i2d_body_is_awake(box));

    I2D_REQUIRE(i2d_body_enable(box) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(box));
    I2D_REQUIRE(s.step());
    I2D_CHECK_NEAR(velocity(box).x, 1.0 + 6.0 * double(time_step), 1e-5);
    I2D_CHECK_NEAR(velocity(box).y, 1.0, 1e-6);
    I2D_REQUIRE(s.step());
    I2D_CHECK_NEAR(velocity(box).x, 1.0 + 6.0 * double(time_step), 1e-5);  // the force acted once
    I2D_CHECK(!BodyState::of(box).same_pose(before));
}
