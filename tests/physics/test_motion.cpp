// SPDX-License-Identifier: MIT
// Motion without contacts against closed form: mass from shapes, free fall, gravity
// scale, damping, the speed limit, forces and impulses.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics_fixture.hpp"

using namespace phys;

I2D_TEST(phys_motion_mass_from_shapes) {
    // Mass = density x area: box 4 hw hh, circle pi r^2; a dynamic body without shapes
    // weighs 1 kg; static and kinematic bodies report 0.
    Scene scene;
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 1.5f, 0.25f, with_density(2.0f));
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{5, 0}, 0.75f, with_density(3.0f));
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(ball));
    I2D_CHECK_NEAR(i2d_body_get_mass(box), box_mass(1.5, 0.25, 2.0), 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_mass(ball), circle_mass(0.75, 3.0), 1e-5);

    // A second shape adds its mass.
    i2d_shape_def sd = shape_def(with_density(0.5f));
    i2d_circle c{i2d_vec2{0, 0}, 0.5f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(box, &sd, &c)));
    I2D_CHECK_NEAR(i2d_body_get_mass(box), box_mass(1.5, 0.25, 2.0) + circle_mass(0.5, 0.5), 1e-5);

    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{10, 0});
    i2d_body_id empty = i2d_body_create(scene.world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(empty));
    I2D_CHECK_NEAR(i2d_body_get_mass(empty), 1.0, 1e-6);

    i2d_body_id still = scene.box(body_def(I2D_BODY_STATIC, i2d_vec2{0, -5}), 1.0f, 1.0f);
    i2d_body_id kin = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, -10}), 1.0f, 1.0f);
    I2D_REQUIRE(!I2D_IS_NULL(still) && !I2D_IS_NULL(kin));
    I2D_CHECK(i2d_body_get_mass(still) == 0.0f);
    I2D_CHECK(i2d_body_get_mass(kin) == 0.0f);
}

I2D_TEST(phys_motion_free_fall) {
    // Semi-implicit Euler with substep h: v_n = -g n h exactly, and
    // y_n = y0 - g h^2 n (n + 1) / 2 = y0 - g t^2 / 2 - g h t / 2: the position error
    // against the exact parabola is at most g h t / 2. x never changes.
    Scene scene;
    const double y0 = 10.0;
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{3, float(y0)}, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    double worst_v = 0.0, worst_y_excess = 0.0;
    bool x_fixed = true;
    for (int s = 1; s <= steps_for(2.0); ++s) {
        I2D_REQUIRE(scene.step());
        const double t = s * double(time_step);
        const i2d_vec2 p = position(ball), v = velocity(ball);
        worst_v = std::max(worst_v, std::fabs(v.y + g * t) - (1e-4 * g * t + 1e-5));
        const double bound = g * substep * t / 2 + 2e-4;
        worst_y_excess = std::max(worst_y_excess, std::fabs(p.y - (y0 - g * t * t / 2)) - bound);
        x_fixed = x_fixed && p.x == 3.0f && v.x == 0.0f;
    }
    I2D_CHECK(worst_v <= 0.0);         // velocity = -g t
    I2D_CHECK(worst_y_excess <= 0.0);  // position within the integrator's error bound
    I2D_CHECK(x_fixed);
    // World gravity read back.
    i2d_vec2 gravity = i2d_world_get_gravity(scene.world);
    I2D_CHECK(gravity.x == 0.0f && gravity.y == float(-g));
}

I2D_TEST(phys_motion_gravity_scale) {
    // Each body falls with g x gravity_scale: after 1 s, v = -10 s. Scale 0 floats
    // exactly in place; a negative scale rises.
    const float scales[] = {0.0f, 0.5f, -1.0f, 2.0f};
    Scene scene;
    i2d_body_id bodies[4];
    for (int i = 0; i < 4; ++i) {
        i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{float(3 * i), 0});
        def.gravity_scale = scales[i];
        bodies[i] = scene.circle(def, 0.5f);
        I2D_REQUIRE(!I2D_IS_NULL(bodies[i]));
    }
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    for (int i = 0; i < 4; ++i) {
        int before = i2d_check_failures;
        const double v_expected = -g * scales[i] * 1.0;
        I2D_CHECK_NEAR(velocity(bodies[i]).y, v_expected, 1e-4 * 20 + 1e-6);
        // y = -g s t^2 / 2 within the semi-implicit bound g |s| h t / 2.
        I2D_CHECK_NEAR(position(bodies[i]).y, -g * scales[i] / 2, g * std::fabs(scales[i]) * substep / 2 + 1e-4);
        char what[48];
        snprintf(what, sizeof what, "gravity_scale %g", scales[i]);
        report_case(before, what);
    }
    I2D_CHECK(position(bodies[0]).y == 0.0f && velocity(bodies[0]).y == 0.0f);
}

I2D_TEST(phys_motion_set_gravity) {
    // Gravity can point anywhere: with (3, -4) a body reaches v = (3, -4) m/s after 1 s.
    Scene scene;
    I2D_CHECK_STATUS(i2d_world_set_gravity(scene.world, i2d_vec2{3, -4}), I2D_OK);
    const i2d_vec2 gravity = i2d_world_get_gravity(scene.world);
    I2D_CHECK(gravity.x == 3.0f && gravity.y == -4.0f);
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    I2D_CHECK_NEAR(velocity(box).x, 3.0, 1e-4);
    I2D_CHECK_NEAR(velocity(box).y, -4.0, 1e-4);
    I2D_CHECK_NEAR(position(box).x, 1.5, 3.0 * substep / 2 + 1e-4);
    I2D_CHECK_NEAR(position(box).y, -2.0, 4.0 * substep / 2 + 1e-4);
}

I2D_TEST(phys_motion_linear_damping) {
    // Without gravity, damping c scales the velocity by 1 / (1 + h c) every substep:
    // after n substeps v = v0 (1 + h c)^-n (close to v0 exp(-c t), but not equal: the
    // tolerance is tight enough to tell the two apart). The direction never changes and
    // the speed falls monotonically; c = 0 keeps the velocity exactly.
    Scene scene(Scene::zero_gravity_def());
    const double c = 0.5;
    const i2d_vec2 v0{6.0f, -8.0f};
    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, v0);
    def.linear_damping = float(c);
    i2d_body_id damped = scene.circle(def, 0.5f);
    i2d_body_id undamped = scene.dynamic_circle(i2d_vec2{0, 5}, 0.5f, Material{}, v0);
    I2D_REQUIRE(!I2D_IS_NULL(damped) && !I2D_IS_NULL(undamped));

    bool monotonic = true, straight = true, undamped_exact = true;
    double previous = speed(v0);
    const int steps = steps_for(2.0);
    for (int s = 1; s <= steps; ++s) {
        I2D_REQUIRE(scene.step());
        const i2d_vec2 v = velocity(damped);
        monotonic = monotonic && speed(v) < previous;
        previous = speed(v);
        straight = straight && std::fabs(v.x * v0.y - v.y * v0.x) <= 1e-5 * speed(v) * speed(v0);
        undamped_exact = undamped_exact && velocity(undamped).x == v0.x && velocity(undamped).y == v0.y;
    }
    const double factor = std::pow(1.0 + substep * c, -double(steps * substeps));
    const double v_expected = speed(v0) * factor;
    printf("    damping c = %g, t = 2 s: speed %.6f, expected %.6f (exp model %.6f)\n", c, speed(velocity(damped)),
           v_expected, speed(v0) * std::exp(-c * 2.0));
    I2D_CHECK(monotonic);
    I2D_CHECK(straight);
    I2D_CHECK(undamped_exact);
    I2D_CHECK_NEAR(speed(velocity(damped)), v_expected, 2e-4 * v_expected);
}

I2D_TEST(phys_motion_max_linear_speed) {
    // Speeds above maximum_linear_speed are clamped to it at the next step, keeping the
    // direction: (30, 40) with a limit of 20 becomes (12, 16).
    i2d_world_def def = Scene::zero_gravity_def();
    def.maximum_linear_speed = 20.0f;
    {
        Scene scene(def);
        i2d_body_id body = scene.dynamic_circle(i2d_vec2{0, 0}, 0.5f, Material{}, i2d_vec2{30, 40});
        I2D_REQUIRE(!I2D_IS_NULL(body));
        I2D_REQUIRE(scene.step());
        I2D_CHECK_NEAR(velocity(body).x, 12.0, 1e-4);
        I2D_CHECK_NEAR(velocity(body).y, 16.0, 1e-4);
        // An impulse that would reach 1000 m/s is clamped too.
        I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(body, i2d_vec2{1000.0f * float(circle_mass(0.5, 1)), 0},
                                                       position(body), true),
                         I2D_OK);
        I2D_REQUIRE(scene.step());
        I2D_CHECK_NEAR(speed(velocity(body)), 20.0, 1e-4);
    }
    {
        // Falling under gravity with a limit of 5 m/s: terminal speed 5, never more.
        def.gravity = i2d_vec2{0, -10};
        def.maximum_linear_speed = 5.0f;
        Scene scene(def);
        i2d_body_id body = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f);
        I2D_REQUIRE(!I2D_IS_NULL(body));
        double fastest = 0.0;
        for (int s = 0; s < steps_for(2.0); ++s) {
            I2D_REQUIRE(scene.step());
            fastest = std::max(fastest, speed(velocity(body)));
        }
        I2D_CHECK(fastest <= 5.0 + 1e-5);
        I2D_CHECK_NEAR(velocity(body).y, -5.0, 1e-5);
    }
}

I2D_TEST(phys_motion_force) {
    // A force applied before every step accelerates at a = F / m. Box 2 x 1 m of density
    // 2: m = 4 kg; F = (8, -4) N gives a = (2, -1) m/s^2, so after 1 s v = (2, -1) and
    // x = a t^2 / 2 within a h t / 2. Forces are cleared after each step: once we stop
    // applying it the velocity stays constant.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 1.0f, 0.5f, with_density(2.0f));
    I2D_REQUIRE(!I2D_IS_NULL(box));
    const double m = box_mass(1.0, 0.5, 2.0);
    I2D_CHECK_NEAR(i2d_body_get_mass(box), m, 1e-6);
    const double fx = 8.0, fy = -4.0;
    for (int s = 0; s < steps_for(1.0); ++s) {
        I2D_CHECK_STATUS(i2d_body_apply_force(box, i2d_vec2{float(fx), float(fy)}, i2d_body_get_world_center_of_mass(box),
                                              true),
                         I2D_OK);
        I2D_REQUIRE(scene.step());
    }
    const double ax = fx / m, ay = fy / m;
    I2D_CHECK_NEAR(velocity(box).x, ax * 1.0, 1e-4);
    I2D_CHECK_NEAR(velocity(box).y, ay * 1.0, 1e-4);
    I2D_CHECK_NEAR(position(box).x, ax / 2, std::fabs(ax) * substep / 2 + 1e-4);
    I2D_CHECK_NEAR(position(box).y, ay / 2, std::fabs(ay) * substep / 2 + 1e-4);

    I2D_REQUIRE(scene.step(steps_for(0.5)));
    I2D_CHECK_NEAR(velocity(box).x, ax, 1e-4);
    I2D_CHECK_NEAR(velocity(box).y, ay, 1e-4);
}

I2D_TEST(phys_motion_linear_impulse) {
    // An impulse J changes the velocity at once by J / m (no step needed): box of 4 kg,
    // J = (2, -6) N s gives dv = (0.5, -1.5) m/s. Impulses add up. Kinematic and static
    // bodies do not respond.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 1.0f, 0.5f, with_density(2.0f),
                                        i2d_vec2{1, 1});
    i2d_body_id kin = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{5, 0}, i2d_vec2{1, 0}), 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(kin));
    const double m = box_mass(1.0, 0.5, 2.0);

    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(box, i2d_vec2{2, -6}, position(box), true), I2D_OK);
    I2D_CHECK_NEAR(velocity(box).x, 1.0 + 2.0 / m, 1e-6);
    I2D_CHECK_NEAR(velocity(box).y, 1.0 - 6.0 / m, 1e-6);
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(box, i2d_vec2{-2, 6}, position(box), true), I2D_OK);
    I2D_CHECK_NEAR(velocity(box).x, 1.0, 1e-6);
    I2D_CHECK_NEAR(velocity(box).y, 1.0, 1e-6);

    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(kin, i2d_vec2{100, 100}, position(kin), true), I2D_OK);
    I2D_CHECK(velocity(kin).x == 1.0f && velocity(kin).y == 0.0f);
    I2D_REQUIRE(scene.step());
    I2D_CHECK(velocity(kin).x == 1.0f && velocity(kin).y == 0.0f);
}
