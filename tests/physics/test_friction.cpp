// SPDX-License-Identifier: MIT
// Coulomb friction against closed form: a sliding box decelerates at mu g, the mixing
// rule is the geometric mean, and static friction holds until the push exceeds mu m g.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// A unit box resting on the ground slides off at v0 along x. Returns the distance it
// slides before stopping, and checks its speed half-way through against v0 - mu g t.
double slide(float mu_box, float mu_ground, double v0, double mu_expected) {
    Scene scene;
    i2d_body_id ground = scene.ground(0.0f, 50.0f, with_friction(mu_ground));
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f, with_friction(mu_box), i2d_vec2{float(v0), 0});
    if (I2D_IS_NULL(ground) || I2D_IS_NULL(box)) {
        ++i2d_check_failures;
        return NAN;
    }
    const double stop_time = v0 / (mu_expected * g);
    const int half = steps_for(stop_time / 2);
    if (!scene.step(half)) {
        ++i2d_check_failures;
        return NAN;
    }
    const double t = half * double(time_step);
    I2D_CHECK_NEAR(velocity(box).x, v0 - mu_expected * g * t, 0.01 * v0);
    // Well past the stop: friction must not push it backwards.
    if (!scene.step(steps_for(stop_time))) {
        ++i2d_check_failures;
        return NAN;
    }
    I2D_CHECK_NEAR(velocity(box).x, 0.0, 1e-3);
    return position(box).x;
}

}  // namespace

I2D_TEST(phys_friction_sliding_box_stops) {
    // Deceleration mu g: from v0 = 5 m/s with mu = 0.5 the box stops after 1 s, having
    // slid v0^2 / (2 mu g) = 2.5 m.
    const double d = slide(0.5f, 0.5f, 5.0, 0.5);
    printf("    sliding box, mu = 0.5: stopped after %.4f m, expected 2.5 m\n", d);
    I2D_CHECK_NEAR(d, 2.5, 0.02 * 2.5);
}

I2D_TEST(phys_friction_geometric_mean) {
    // Friction 0.8 on the box and 0.2 on the ground mix to sqrt(0.8 x 0.2) = 0.4:
    // deceleration 4 m/s^2, distance 25 / 8 = 3.125 m. (The minimum would give 6.25 m,
    // the mean 2.5 m.)
    const double d = slide(0.8f, 0.2f, 5.0, 0.4);
    printf("    sliding box, mu 0.8 on 0.2: stopped after %.4f m, expected 3.125 m\n", d);
    I2D_CHECK_NEAR(d, 3.125, 0.02 * 3.125);
}

I2D_TEST(phys_friction_static_threshold) {
    // A horizontal push below mu m g does not move a resting box; twice mu m g
    // accelerates it at (F - mu m g) / m = mu g.
    const double mu = 0.5;
    const double m = box_mass(0.5, 0.5, 1.0);
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, with_friction(float(mu)))));
    i2d_body_id held = scene.dynamic_box(i2d_vec2{-5, 0.5f}, 0.5f, 0.5f, with_friction(float(mu)));
    i2d_body_id pushed = scene.dynamic_box(i2d_vec2{5, 0.5f}, 0.5f, 0.5f, with_friction(float(mu)));
    I2D_REQUIRE(!I2D_IS_NULL(held) && !I2D_IS_NULL(pushed));
    I2D_REQUIRE(scene.step(steps_for(0.5)));  // let the contacts settle first
    const double held_x0 = position(held).x, pushed_v0 = velocity(pushed).x;
    for (int s = 0; s < steps_for(1.0); ++s) {
        const i2d_vec2 small{float(0.5 * mu * m * g), 0}, large{float(2.0 * mu * m * g), 0};
        I2D_CHECK_STATUS(i2d_body_apply_force(held, small, position(held), true), I2D_OK);
        I2D_CHECK_STATUS(i2d_body_apply_force(pushed, large, position(pushed), true), I2D_OK);
        I2D_REQUIRE(scene.step());
    }
    I2D_CHECK_NEAR(position(held).x, held_x0, 1e-5);
    I2D_CHECK_NEAR(velocity(held).x, 0.0, 1e-5);
    I2D_CHECK_NEAR(velocity(pushed).x - pushed_v0, mu * g * 1.0, 0.01 * mu * g);
}

I2D_TEST(phys_friction_changed_on_a_sliding_box_takes_effect_at_once) {
    // A unit box slides at 4 m/s on frictionless ground (it keeps its speed). Setting the
    // box's friction to 0.5 (ground 0.5, geometric mean 0.5) on the existing contact
    // makes it decelerate at mu g = 5 m/s^2 from the next step: after 0.4 s it moves at
    // 4 - 5 x 0.4 = 2 m/s.
    Scene scene;
    const i2d_body_id ground = scene.ground(0.0f, 50.0f, with_friction(0.5f));
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f, with_friction(0.0f), i2d_vec2{4.0f, 0});
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(box));
    I2D_REQUIRE(scene.step(steps_for(0.5)));
    const double free_speed = velocity(box).x;
    const i2d_shape_id shape = only_shape(box);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    I2D_CHECK_STATUS(i2d_shape_set_friction(shape, 0.5f), I2D_OK);
    I2D_REQUIRE(scene.step(steps_for(0.4)));
    const double slowed = velocity(box).x;
    fprintf(stderr, "    frictionless slide %.4f m/s; 0.4 s after friction 0.5: %.4f m/s (expected 2)\n", free_speed,
            slowed);
    I2D_CHECK_NEAR(free_speed, 4.0, 1e-3);
    I2D_CHECK_NEAR(slowed, 2.0, 0.02);
}
