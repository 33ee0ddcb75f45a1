// SPDX-License-Identifier: MIT
// A body's settings changed after creation (issue 40), against closed form: a mass set in
// place of the shapes', a kinematic target, gravity scale, damping, fixed rotation, sleep
// settings and the bullet flag.
#include <cmath>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

/** i2d_mass_data by value. */
i2d_mass_data mass_data(float mass, i2d_vec2 center, float inertia) {
    i2d_mass_data m;
    m.mass = mass;
    m.center = center;
    m.rotational_inertia = inertia;
    return m;
}

/** Pushes `body` with `force` at its centre for `steps` steps (a force lasts one step). */
bool push(Scene& scene, i2d_body_id body, i2d_vec2 force, int steps) {
    for (int s = 0; s < steps; ++s) {
        if (i2d_body_apply_force_to_center(body, force, true) != I2D_OK || !scene.step()) {
            return false;
        }
    }
    return true;
}

/** A unit box that has fallen asleep on the ground; null if the scene failed. */
i2d_body_id box_asleep_on_the_ground(Scene& scene) {
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    if (I2D_IS_NULL(scene.ground()) || I2D_IS_NULL(box) || !scene.step(steps_for(2.0)) || i2d_body_is_awake(box)) {
        return I2D_NULL_BODY_ID;
    }
    return box;
}

/** Tolerance of F = m a over a second of forces: float rounding of 240 substeps. */
constexpr double newton_tolerance = 1e-3;

}  // namespace

I2D_TEST(phys_runtime_mass_override_obeys_f_equals_ma) {
    // A 1 kg box set to 2 kg: 10 N for 1 s gives 5 m/s, not 10; a torque of 3 N m on the
    // inertia it was set gives w = 3 t / I. Back to the shapes': 10 m/s more in the next
    // second.
    Scene scene(Scene::zero_gravity_def());
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_CHECK_NEAR(i2d_body_get_mass(box), 1.0, 1e-6);
    const float inertia = 0.75f;
    I2D_REQUIRE(i2d_body_set_mass_data(box, mass_data(2.0f, i2d_vec2{0, 0}, inertia)) == I2D_OK);
    const i2d_mass_data set = i2d_body_get_mass_data(box);
    I2D_CHECK(set.mass == 2.0f && set.rotational_inertia == inertia && set.center.x == 0.0f);
    I2D_REQUIRE(push(scene, box, i2d_vec2{10, 0}, steps_for(1.0)));
    I2D_CHECK_NEAR(velocity(box).x, 5.0, 5.0 * newton_tolerance);
    for (int s = 0; s < steps_for(1.0); ++s) {
        I2D_REQUIRE(i2d_body_apply_torque(box, 3.0f, true) == I2D_OK && scene.step());
    }
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(box), 3.0 / inertia, 3.0 / inertia * newton_tolerance);

    I2D_REQUIRE(i2d_body_apply_mass_from_shapes(box) == I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_mass(box), 1.0, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(box), 1.0 / 6.0, 1e-6);  // m (w^2 + h^2) / 12
    I2D_REQUIRE(push(scene, box, i2d_vec2{10, 0}, steps_for(1.0)));
    I2D_CHECK_NEAR(velocity(box).x, 15.0, 15.0 * newton_tolerance);
}

I2D_TEST(phys_runtime_mass_override_outlives_shape_changes) {
    // A mass the caller set stays when a shape is added, and moves the centre of mass to
    // where it was set (the body turns about it).
    Scene scene(Scene::zero_gravity_def());
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(i2d_body_set_mass_data(box, mass_data(4.0f, i2d_vec2{0.25f, 0}, 0.5f)) == I2D_OK);
    const i2d_shape_def sd = shape_def(Material{});
    const i2d_circle c{i2d_vec2{2, 0}, 0.5f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(box, &sd, &c)));
    I2D_CHECK(i2d_body_get_mass(box) == 4.0f);
    I2D_CHECK(i2d_body_get_local_center_of_mass(box).x == 0.25f);
    I2D_CHECK_NEAR(i2d_body_get_world_center_of_mass(box).x, 0.25, 1e-6);
    I2D_REQUIRE(i2d_body_apply_mass_from_shapes(box) == I2D_OK);
    const double m_box = box_mass(0.5, 0.5, 1.0), m_circle = circle_mass(0.5, 1.0);
    I2D_CHECK_NEAR(i2d_body_get_mass(box), m_box + m_circle, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_local_center_of_mass(box).x, 2.0 * m_circle / (m_box + m_circle), 1e-5);
}

I2D_TEST(phys_runtime_target_transform_reached_in_one_step) {
    // The velocities set carry a kinematic body to its target in the time step given: its
    // centre exactly, its angle as the integrator turns it (each of the n substeps turns
    // by atan(theta / n), the angle of q + (theta / n) q_perp), a lag of theta^3 / (3 n^2).
    Scene scene;
    const i2d_body_id platform = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{1, 2}), 2.0f, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(platform));
    const double angle = 0.5;
    const i2d_transform target{i2d_vec2{3.0f, 1.5f}, rot(angle)};
    I2D_REQUIRE(i2d_body_set_target_transform(platform, target, time_step) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(platform));
    I2D_REQUIRE(scene.step());
    const i2d_vec2 p = position(platform);
    I2D_CHECK_NEAR(p.x, 3.0, 1e-4);
    I2D_CHECK_NEAR(p.y, 1.5, 1e-4);
    I2D_CHECK_NEAR(angle_of(platform), substeps * std::atan(angle / substeps), 1e-5);
    // The short way round: a target a little clockwise of a body turned 3 rad.
    const i2d_transform around{i2d_vec2{3.0f, 1.5f}, rot(-3.0)};
    I2D_REQUIRE(i2d_body_set_transform(platform, target.p, rot(3.0)) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_target_transform(platform, around, 0.5f) == I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(platform), wrap_angle(-3.0 - 3.0) / 0.5, 1e-3);
}

I2D_TEST(phys_runtime_gravity_scale_wakes_and_lifts) {
    // A box asleep on the ground, its gravity scale turned to -1: it wakes and rises at g.
    Scene scene;
    const i2d_body_id box = box_asleep_on_the_ground(scene);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(i2d_body_set_gravity_scale(box, -1.0f) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(box));
    I2D_CHECK(i2d_body_get_gravity_scale(box) == -1.0f);
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    I2D_CHECK_NEAR(velocity(box).y, g * 1.0, g * newton_tolerance);
}

I2D_TEST(phys_runtime_damping_slows_as_its_closed_form) {
    // Each substep h scales v by 1 / (1 + h c): after n substeps v0 / (1 + h c)^n.
    Scene scene(Scene::zero_gravity_def());
    const i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, 0}, 0.5f, Material{}, i2d_vec2{10, 0});
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    I2D_REQUIRE(i2d_body_set_angular_velocity(ball, 4.0f) == I2D_OK);
    const double c = 2.0, c_angular = 0.5;
    I2D_REQUIRE(i2d_body_set_linear_damping(ball, float(c)) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_angular_damping(ball, float(c_angular)) == I2D_OK);
    I2D_CHECK(i2d_body_get_linear_damping(ball) == 2.0f && i2d_body_get_angular_damping(ball) == 0.5f);
    const int steps = steps_for(1.0);
    I2D_REQUIRE(scene.step(steps));
    const int n = steps * substeps;
    I2D_CHECK_NEAR(velocity(ball).x, 10.0 / std::pow(1.0 + substep * c, n), 1e-4);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(ball), 4.0 / std::pow(1.0 + substep * c_angular, n), 1e-4);
}

I2D_TEST(phys_runtime_fixed_rotation_stops_and_frees_spin) {
    // Fixed: the spin stops and a torque cannot start it. Freed: the torque turns it at
    // tau t / I with the shapes' inertia again.
    Scene scene(Scene::zero_gravity_def());
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(i2d_body_set_angular_velocity(box, 3.0f) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_fixed_rotation(box, true) == I2D_OK);
    I2D_CHECK(i2d_body_is_fixed_rotation(box));
    I2D_CHECK(i2d_body_get_angular_velocity(box) == 0.0f);
    const double start = angle_of(box);
    for (int s = 0; s < 30; ++s) {
        I2D_REQUIRE(i2d_body_apply_torque(box, 5.0f, true) == I2D_OK && scene.step());
    }
    I2D_CHECK(angle_of(box) == start);
    I2D_REQUIRE(i2d_body_set_fixed_rotation(box, false) == I2D_OK);
    const double inertia = 1.0 / 6.0;
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(box), inertia, 1e-6);
    for (int s = 0; s < steps_for(1.0); ++s) {
        I2D_REQUIRE(i2d_body_apply_torque(box, 0.5f, true) == I2D_OK && scene.step());
    }
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(box), 0.5 / inertia, 0.5 / inertia * newton_tolerance);
}

I2D_TEST(phys_runtime_sleep_threshold_decides_rest) {
    // A body drifting at 0.3 m/s never rests under the default 0.05 m/s; under a 0.5 m/s
    // threshold it falls asleep once the world's time_to_sleep (0.5 s) has passed.
    Scene scene(Scene::zero_gravity_def());
    const i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, 0}, 0.5f, Material{}, i2d_vec2{0.3f, 0});
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    I2D_CHECK_NEAR(i2d_body_get_sleep_threshold(ball), 0.05, 1e-7);
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    I2D_CHECK(i2d_body_is_awake(ball));
    I2D_REQUIRE(i2d_body_set_sleep_threshold(ball, 0.5f) == I2D_OK);
    I2D_REQUIRE(scene.step(steps_for(0.5) - 1));
    I2D_CHECK(i2d_body_is_awake(ball));
    I2D_REQUIRE(scene.step(2));
    I2D_CHECK(!i2d_body_is_awake(ball));
}

I2D_TEST(phys_runtime_sleep_disabled_wakes_and_stays_awake) {
    Scene scene;
    const i2d_body_id box = box_asleep_on_the_ground(scene);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(i2d_body_enable_sleep(box, false) == I2D_OK);
    I2D_CHECK(!i2d_body_is_sleep_enabled(box));
    I2D_CHECK(i2d_body_is_awake(box));
    I2D_REQUIRE(scene.step(steps_for(2.0)));
    I2D_CHECK(i2d_body_is_awake(box));
    I2D_REQUIRE(i2d_body_enable_sleep(box, true) == I2D_OK);
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    I2D_CHECK(!i2d_body_is_awake(box));
}

I2D_TEST(phys_runtime_bullet_flag_stops_a_projectile_at_a_moving_plate) {
    // A 5 cm ball at 300 m/s (5 m per step) passes a free 4 cm plate as a plain body and
    // stops at it once made a bullet: bullets are swept against dynamic bodies too.
    for (const bool bullet : {false, true}) {
        Scene scene(Scene::zero_gravity_def());
        const i2d_body_id plate = scene.dynamic_box(i2d_vec2{10, 0}, 0.02f, 2.0f, with_density(50.0f));
        const i2d_body_id shot = scene.dynamic_circle(i2d_vec2{0, 0}, 0.05f, Material{}, i2d_vec2{300, 0});
        I2D_REQUIRE(!I2D_IS_NULL(plate) && !I2D_IS_NULL(shot));
        I2D_REQUIRE(i2d_body_set_bullet(shot, bullet) == I2D_OK);
        I2D_CHECK(i2d_body_is_bullet(shot) == bullet);
        I2D_REQUIRE(scene.step(4));
        const bool passed = position(shot).x > position(plate).x;
        I2D_CHECK(passed != bullet);
    }
}
