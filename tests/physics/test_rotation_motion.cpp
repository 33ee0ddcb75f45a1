// SPDX-License-Identifier: MIT
// Rotation without contacts against closed form: free spin, torque, forces and impulses
// at points, angular damping, fixed rotation, kinematic spin, transforms and the point
// helpers.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

double norm2(i2d_rot q) { return double(q.c) * q.c + double(q.s) * q.s; }

// A dynamic (or other) body turned by angle with one box of half sizes hw x hh centred at
// `center` in its frame. No gravity is assumed by the callers.
i2d_body_id box_body(Scene& scene, i2d_body_type type, i2d_vec2 position, double angle, float hw, float hh,
                     i2d_vec2 center = i2d_vec2{0, 0}, float density = 1.0f, bool fixed_rotation = false) {
    i2d_body_def def = turned_body_def(type, position, angle);
    def.fixed_rotation = fixed_rotation;
    i2d_body_id body = i2d_body_create(scene.world, &def);
    if (I2D_IS_NULL(body)) {
        fprintf(stderr, "    body creation failed: %s\n", i2d_last_error_message());
        return body;
    }
    i2d_shape_def sd = i2d_default_shape_def();
    sd.density = density;
    if (I2D_IS_NULL(i2d_shape_create_offset_box(body, &sd, hw, hh, center, i2d_rot{1, 0}))) {
        fprintf(stderr, "    offset box creation failed: %s\n", i2d_last_error_message());
        return I2D_NULL_BODY_ID;
    }
    return body;
}

// Closed-form box inertia about its centre, full sizes 2hw x 2hh.
double box_inertia(double hw, double hh, double density) {
    const double m = box_mass(hw, hh, density);
    return m * (4 * hw * hw + 4 * hh * hh) / 12;
}

}  // namespace

I2D_TEST(phys_rotmotion_make_rot_and_angle) {
    // i2d_make_rot(a) = (cos a, sin a); i2d_rot_get_angle gives the angle in (-pi, pi].
    const double angles[] = {0.0, 0.3, -1.2, 2.5, -3.0, 1.5707963, 7.0, -10.0};
    for (double a : angles) {
        const int before = i2d_check_failures;
        const i2d_rot q = i2d_make_rot(float(a));
        I2D_CHECK_NEAR(q.c, std::cos(a), 2e-6);
        I2D_CHECK_NEAR(q.s, std::sin(a), 2e-6);
        const double back = i2d_rot_get_angle(q);
        I2D_CHECK(back > -pi - 1e-6 && back <= pi + 1e-6);
        I2D_CHECK_NEAR(wrap_angle(back - a), 0.0, 2e-6);
        char what[48];
        snprintf(what, sizeof what, "angle %g", a);
        report_case(before, what);
    }
    // The half turn is +pi, not -pi.
    I2D_CHECK_NEAR(i2d_rot_get_angle(i2d_rot{-1.0f, 0.0f}), pi, 1e-6);
    I2D_CHECK_NEAR(i2d_rot_get_angle(i2d_rot{0.0f, -1.0f}), -pi / 2, 1e-6);
}

I2D_TEST(phys_rotmotion_free_spin) {
    // Without gravity, torque or damping a body spinning at w turns by w t about its centre
    // of mass, which stays put, and w never changes. A centred box keeps its origin; a box
    // offset by (1, 0) in its body frame swings its origin around the fixed centre of mass:
    // origin = c - R(theta) (1, 0). After 10 000 steps (166.7 s, 83 rad) the rotation is
    // still normalised (c^2 + s^2 within 1e-5 of 1) and the angle matches w t.
    Scene scene(Scene::zero_gravity_def());
    const double w = 0.5;
    i2d_body_id centred = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, 0.0, 0.5f, 0.25f);
    i2d_body_id offset = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{5, 0}, 0.0, 0.5f, 0.25f, i2d_vec2{1, 0});
    I2D_REQUIRE(!I2D_IS_NULL(centred) && !I2D_IS_NULL(offset));
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(centred, float(w)), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(offset, float(w)), I2D_OK);
    const i2d_vec2 c0 = i2d_body_get_world_center_of_mass(offset);
    I2D_CHECK_NEAR(c0.x, 6.0, 1e-6);

    I2D_REQUIRE(scene.step(60));
    const double a1 = angle_of(centred);
    I2D_CHECK_NEAR(a1, w * 1.0, 2e-4);
    I2D_CHECK_NEAR(angle_of(offset), w * 1.0, 2e-4);

    const int steps = 10000;
    I2D_REQUIRE(scene.step(steps - 60));
    const double t = steps * double(time_step);
    const double err_centred = wrap_angle(angle_of(centred) - w * t), err_offset = wrap_angle(angle_of(offset) - w * t);
    const double n_centred = norm2(i2d_body_get_rotation(centred)), n_offset = norm2(i2d_body_get_rotation(offset));
    const i2d_vec2 c = i2d_body_get_world_center_of_mass(offset), p = position(offset);
    const double theta = angle_of(offset);
    printf("    free spin w 0.5: angle after 1 s %.6f (expected 0.5); after %d steps error %.3g / %.3g rad, "
           "|q|^2 - 1 = %.3g / %.3g, centre drift %.3g m\n",
           a1, steps, err_centred, err_offset, n_centred - 1, n_offset - 1, distance(c, c0));
    I2D_CHECK_NEAR(err_centred, 0.0, 0.01);
    I2D_CHECK_NEAR(err_offset, 0.0, 0.01);
    I2D_CHECK_NEAR(n_centred, 1.0, 1e-5);
    I2D_CHECK_NEAR(n_offset, 1.0, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(centred), w, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(offset), w, 1e-6);
    I2D_CHECK_NEAR(position(centred).x, 0.0, 1e-5);
    I2D_CHECK_NEAR(position(centred).y, 0.0, 1e-5);
    I2D_CHECK_NEAR(c.x, c0.x, 1e-4);
    I2D_CHECK_NEAR(c.y, c0.y, 1e-4);
    I2D_CHECK_NEAR(p.x, c.x - std::cos(theta), 1e-4);
    I2D_CHECK_NEAR(p.y, c.y - std::sin(theta), 1e-4);
    I2D_CHECK(speed(velocity(offset)) < 1e-5);  // the centre of mass does not move
}

I2D_TEST(phys_rotmotion_torque) {
    // A torque T applied before every step gives alpha = T / I: box 2 x 1 at density 1,
    // m = 2, I = 2 (4 + 1) / 12 = 5/6; T = 5/3 N m gives alpha = 2 rad/s^2. After 1 s
    // w = 2 and the angle is alpha t^2 / 2 = 1 rad within alpha h t / 2 (the
    // semi-implicit integrator's offset). A pure torque does not move the centre. Once
    // the torque stops (it is cleared after each step) the spin stays constant.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id box = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{1, 1}, 0.0, 1.0f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    const double inertia = box_inertia(1.0, 0.5, 1.0);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(box), inertia, 1e-5);
    const double torque = 5.0 / 3.0, alpha = torque / inertia;
    for (int s = 0; s < steps_for(1.0); ++s) {
        I2D_CHECK_STATUS(i2d_body_apply_torque(box, float(torque), true), I2D_OK);
        I2D_REQUIRE(scene.step());
    }
    const double w1 = i2d_body_get_angular_velocity(box), a1 = angle_of(box);
    printf("    torque: alpha %.3f rad/s^2, after 1 s w %.6f (expected %.6f), angle %.6f (expected %.6f +- %.2g)\n",
           alpha, w1, alpha, a1, alpha / 2, alpha * substep / 2);
    I2D_CHECK_NEAR(w1, alpha * 1.0, 1e-4 * alpha);
    I2D_CHECK_NEAR(a1, alpha / 2, alpha * substep * 1.0 / 2 + 1e-4);
    I2D_CHECK_NEAR(position(box).x, 1.0, 1e-6);
    I2D_CHECK_NEAR(position(box).y, 1.0, 1e-6);
    I2D_CHECK(speed(velocity(box)) < 1e-6);

    I2D_REQUIRE(scene.step(steps_for(0.5)));
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(box), w1, 1e-6);
    I2D_CHECK_NEAR(wrap_angle(angle_of(box) - a1 - w1 * 0.5), 0.0, 1e-3);
}

I2D_TEST(phys_rotmotion_force_at_point) {
    // A force F at a world point r from the centre of mass gives, during the step it is
    // applied in, a = F / m and alpha = (r x F) / I. Box 2 x 1, density 1: m = 2, I = 5/6.
    // F = (4, 2) N at r = (0.3, 0.5): a = (2, 1) m/s^2, r x F = 0.3 * 2 - 0.5 * 4 = -1.4,
    // alpha = -1.68 rad/s^2. After one step dt: v = a dt, w = alpha dt; the position and
    // angle moved by a dt^2 / 2 and alpha dt^2 / 2 within a h dt / 2. The same force at the
    // centre (apply_force_to_center) gives the same v and no spin.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id box = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, 0.0, 1.0f, 0.5f);
    i2d_body_id centred = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{10, 0}, 0.0, 1.0f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(centred));
    const double m = box_mass(1.0, 0.5, 1.0), inertia = box_inertia(1.0, 0.5, 1.0);
    const double fx = 4, fy = 2, rx = 0.3, ry = 0.5;
    const double ax = fx / m, ay = fy / m, alpha = (rx * fy - ry * fx) / inertia;
    I2D_CHECK_STATUS(i2d_body_apply_force(box, i2d_vec2{float(fx), float(fy)}, i2d_vec2{float(rx), float(ry)}, true),
                     I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_force_to_center(centred, i2d_vec2{float(fx), float(fy)}, true), I2D_OK);
    I2D_REQUIRE(scene.step());
    const double dt = time_step;
    const i2d_vec2 v = velocity(box), p = position(box);
    const double w = i2d_body_get_angular_velocity(box), theta = angle_of(box);
    printf("    force at point: v (%.6f, %.6f) expected (%.6f, %.6f); w %.6f expected %.6f; angle %.3g expected %.3g\n",
           v.x, v.y, ax * dt, ay * dt, w, alpha * dt, theta, alpha * dt * dt / 2);
    I2D_CHECK_NEAR(v.x, ax * dt, 1e-5 * std::fabs(ax * dt));
    I2D_CHECK_NEAR(v.y, ay * dt, 1e-5 * std::fabs(ay * dt));
    I2D_CHECK_NEAR(w, alpha * dt, 1e-5 * std::fabs(alpha * dt));
    const double slack = substep * dt / 2 * 1.05 + 1e-8;
    I2D_CHECK_NEAR(p.x, ax * dt * dt / 2, std::fabs(ax) * slack);
    I2D_CHECK_NEAR(p.y, ay * dt * dt / 2, std::fabs(ay) * slack);
    I2D_CHECK_NEAR(theta, alpha * dt * dt / 2, std::fabs(alpha) * slack);
    I2D_CHECK(theta < 0.0);  // clockwise, as r x F says

    I2D_CHECK_NEAR(velocity(centred).x, ax * dt, 1e-5 * std::fabs(ax * dt));
    I2D_CHECK_NEAR(velocity(centred).y, ay * dt, 1e-5 * std::fabs(ay * dt));
    I2D_CHECK(i2d_body_get_angular_velocity(centred) == 0.0f);
    I2D_CHECK(i2d_body_get_rotation(centred).c == 1.0f && i2d_body_get_rotation(centred).s == 0.0f);

    // Cleared after the step: the next step adds nothing.
    I2D_REQUIRE(scene.step());
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(box), w, 1e-7);
    I2D_CHECK_NEAR(velocity(box).x, v.x, 1e-7);
}

I2D_TEST(phys_rotmotion_impulse_at_point) {
    // An impulse J at a world point r from the centre of mass changes the velocity at once
    // by J / m and the spin by (r x J) / I. A body turned by 0.5 rad whose 1 x 0.5 box
    // (density 2: m = 1, I = 1.25 / 12) sits at (0.5, 0) in its frame; J = (3, -1) at
    // r = (0.2, 0.7): dv = (3, -1), dw = (0.2 * -1 - 0.7 * 3) / I = -22.08 rad/s. An angular
    // impulse of +2.3 N m s cancels that spin; an impulse at the centre adds no spin.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id body = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{1, 2}, 0.5, 0.5f, 0.25f, i2d_vec2{0.5f, 0}, 2.0f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    const double m = 1.0, inertia = box_inertia(0.5, 0.25, 2.0);
    I2D_CHECK_NEAR(i2d_body_get_mass(body), m, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(body), inertia, 1e-5 * inertia);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(body, i2d_vec2{0.5f, 0}), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(body, 1.0f), I2D_OK);

    const i2d_vec2 c = i2d_body_get_world_center_of_mass(body);
    const Point expected_c = transform_point(1, 2, 0.5, 0.5, 0);
    I2D_CHECK_NEAR(c.x, expected_c.x, 1e-5);
    I2D_CHECK_NEAR(c.y, expected_c.y, 1e-5);
    const double rx = 0.2, ry = 0.7, jx = 3, jy = -1;
    const double dw = (rx * jy - ry * jx) / inertia;
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(body, i2d_vec2{float(jx), float(jy)},
                                                   i2d_vec2{float(c.x + rx), float(c.y + ry)}, true),
                     I2D_OK);
    const i2d_vec2 v = velocity(body);
    const double w = i2d_body_get_angular_velocity(body);
    printf("    impulse at point: v (%.6f, %.6f) expected (%.6f, %.6f); w %.5f expected %.5f\n", v.x, v.y, 0.5 + jx / m,
           jy / m, w, 1.0 + dw);
    I2D_CHECK_NEAR(v.x, 0.5 + jx / m, 1e-5);
    I2D_CHECK_NEAR(v.y, jy / m, 1e-5);
    I2D_CHECK_NEAR(w, 1.0 + dw, 1e-5 * std::fabs(dw));

    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(body, float(-(rx * jy - ry * jx)), true), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), 1.0, 1e-4);
    I2D_CHECK_NEAR(velocity(body).x, 0.5 + jx / m, 1e-5);  // an angular impulse leaves v alone

    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(body, i2d_vec2{-3, 1}, c, true), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), 1.0, 1e-4);
    I2D_CHECK_NEAR(velocity(body).x, 0.5, 1e-5);
    I2D_CHECK_NEAR(velocity(body).y, 0.0, 1e-5);
}

I2D_TEST(phys_rotmotion_def_angular_velocity) {
    // body def angular_velocity is the body's spin from the start ("rad/s, counter-clockwise
    // positive; default 0", types.h), like linear_velocity: a dynamic body made with
    // w = 4 and then given a box (as every body gets its shapes after creation) spins at
    // 4 rad/s and, without gravity or damping, has turned 4 dt after one step.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, i2d_vec2{1, 0});
    def.angular_velocity = 4.0f;
    i2d_body_id body = scene.box(def, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    const double w_created = i2d_body_get_angular_velocity(body);
    I2D_REQUIRE(scene.step());
    const double w_stepped = i2d_body_get_angular_velocity(body), a = angle_of(body);
    printf("    def angular_velocity 4: w after shape creation %.6f, after one step %.6f, angle %.6f (expected %.6f)\n",
           w_created, w_stepped, a, 4.0 * time_step);
    I2D_CHECK(w_created == 4.0);
    I2D_CHECK(w_stepped == 4.0);
    I2D_CHECK_NEAR(a, 4.0 * time_step, 1e-5);
    I2D_CHECK(velocity(body).x == 1.0f);  // the linear part of the def is kept
}

I2D_TEST(phys_rotmotion_angular_damping) {
    // Angular damping c scales the spin by 1 / (1 + h c) every substep: after n substeps
    // w = w0 (1 + h c)^-n (not exp(-c t): the tolerance tells them apart). The spin falls
    // monotonically; c = 0 keeps it exactly.
    Scene scene(Scene::zero_gravity_def());
    const double c = 0.5, w0 = 4.0;
    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 0});
    def.angular_damping = float(c);
    i2d_body_id damped = scene.box(def, 0.5f, 0.5f);
    def.position = i2d_vec2{5, 0};
    def.angular_damping = 0.0f;
    i2d_body_id undamped = scene.box(def, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(damped) && !I2D_IS_NULL(undamped));
    // The spin is set once the shapes give the bodies inertia (the def's angular_velocity
    // has its own test).
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(damped, float(w0)), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(undamped, float(w0)), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(damped) == float(w0));
    bool monotonic = true, undamped_exact = true;
    double previous = w0;
    const int steps = steps_for(2.0);
    for (int s = 0; s < steps; ++s) {
        I2D_REQUIRE(scene.step());
        const double w = i2d_body_get_angular_velocity(damped);
        monotonic = monotonic && w < previous && w > 0;
        previous = w;
        undamped_exact = undamped_exact && i2d_body_get_angular_velocity(undamped) == float(w0);
    }
    const double expected = w0 * std::pow(1.0 + substep * c, -double(steps * substeps));
    const double w = i2d_body_get_angular_velocity(damped);
    printf("    angular damping c = %g, t = 2 s: w %.6f, expected %.6f (exp model %.6f)\n", c, w, expected,
           w0 * std::exp(-c * 2.0));
    I2D_CHECK(monotonic);
    I2D_CHECK(undamped_exact);
    I2D_CHECK_NEAR(w, expected, 2e-4 * expected);
}

I2D_TEST(phys_rotmotion_fixed_rotation) {
    // A fixed-rotation body never turns: torque, an off-centre impulse, an angular impulse
    // and a set spin leave it at identity with w = 0, while the linear part of the impulse
    // still gives dv = J / m.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id body = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, 0.0, 1.0f, 0.5f, i2d_vec2{0, 0}, 1.0f, true);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    const double m = box_mass(1.0, 0.5, 1.0);
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(body, i2d_vec2{0, 2}, i2d_vec2{1, 0}, true), I2D_OK);
    I2D_CHECK_NEAR(velocity(body).y, 2.0 / m, 1e-6);
    I2D_CHECK_NEAR(velocity(body).x, 0.0, 1e-7);
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(body, 3.0f, true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(body, 5.0f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 0.0f);
    bool never_turned = true;
    for (int s = 0; s < steps_for(1.0); ++s) {
        I2D_CHECK_STATUS(i2d_body_apply_torque(body, 10.0f, true), I2D_OK);
        I2D_CHECK_STATUS(i2d_body_apply_force(body, i2d_vec2{0, 1}, i2d_vec2{1, 0}, true), I2D_OK);
        I2D_REQUIRE(scene.step());
        const i2d_rot q = i2d_body_get_rotation(body);
        never_turned = never_turned && q.c == 1.0f && q.s == 0.0f && i2d_body_get_angular_velocity(body) == 0.0f;
    }
    // The force at (1, 0) still accelerates it: after 1 s, v.y = 2/m + 1/m.
    printf("    fixed rotation: never turned %d, v.y %.6f (expected %.6f)\n", int(never_turned), velocity(body).y,
            3.0 / m);
    I2D_CHECK(never_turned);
    I2D_CHECK_NEAR(velocity(body).y, 3.0 / m, 1e-4);
}

I2D_TEST(phys_rotmotion_kinematic_spin) {
    // A kinematic body moves by its velocity only: with w = 1.5 rad/s and v = (1, 0) it
    // turns by w t and travels v t, and keeps both velocities exactly. A torque or an
    // impulse does nothing to it.
    Scene scene;  // gravity on: it must not matter
    i2d_body_def def = body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, 0}, i2d_vec2{1, 0});
    def.angular_velocity = 1.5f;
    i2d_body_id kin = scene.box(def, 1.0f, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(kin));
    bool kept = true;
    for (int s = 0; s < steps_for(2.0); ++s) {
        I2D_CHECK_STATUS(i2d_body_apply_torque(kin, 100.0f, true), I2D_OK);
        I2D_REQUIRE(scene.step());
        kept = kept && i2d_body_get_angular_velocity(kin) == 1.5f && velocity(kin).x == 1.0f && velocity(kin).y == 0.0f;
    }
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(kin, 100.0f, true), I2D_OK);
    const double err = wrap_angle(angle_of(kin) - 1.5 * 2.0);
    printf("    kinematic spin: angle error %.3g rad after 2 s, x %.6f (expected 2), velocities kept %d\n", err,
           position(kin).x, int(kept));
    I2D_CHECK(kept);
    I2D_CHECK(i2d_body_get_angular_velocity(kin) == 1.5f);
    I2D_CHECK_NEAR(err, 0.0, 1e-3);
    I2D_CHECK_NEAR(position(kin).x, 2.0, 1e-4);
    I2D_CHECK_NEAR(position(kin).y, 0.0, 1e-6);
    I2D_CHECK_NEAR(norm2(i2d_body_get_rotation(kin)), 1.0, 1e-5);
}

I2D_TEST(phys_rotmotion_set_transform) {
    // A rotation given to set_transform or a body def is read back normalised: make_rot
    // values as given (within float rounding), and a rotation within 1e-3 of unit length
    // comes back at unit length with the same angle. Rotations far from unit length or
    // with NaN are refused and change nothing. The world centre of mass follows.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 0});
    def.rotation = i2d_make_rot(-1.2f);
    i2d_body_id body = i2d_body_create(scene.world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = i2d_default_shape_def();
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_offset_box(body, &sd, 0.5f, 0.5f, i2d_vec2{1, 0.5f}, i2d_rot{1, 0})));
    I2D_CHECK_NEAR(angle_of(body), -1.2, 1e-6);

    const i2d_vec2 p{1.25f, -2.5f};
    I2D_CHECK_STATUS(i2d_body_set_transform(body, p, i2d_make_rot(0.7f)), I2D_OK);
    i2d_transform xf = i2d_body_get_transform(body);
    I2D_CHECK(xf.p.x == p.x && xf.p.y == p.y);
    I2D_CHECK_NEAR(xf.q.c, std::cos(0.7), 1e-6);
    I2D_CHECK_NEAR(xf.q.s, std::sin(0.7), 1e-6);
    I2D_CHECK(i2d_body_get_rotation(body).c == xf.q.c && i2d_body_get_rotation(body).s == xf.q.s);
    const Point c = transform_point(p.x, p.y, 0.7, 1, 0.5);
    I2D_CHECK_NEAR(i2d_body_get_world_center_of_mass(body).x, c.x, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_world_center_of_mass(body).y, c.y, 1e-5);

    // 0.04 % too long: accepted and normalised.
    const float k = 1.0004f;
    I2D_CHECK_STATUS(i2d_body_set_transform(body, p, i2d_rot{k * float(std::cos(2.0)), k * float(std::sin(2.0))}),
                     I2D_OK);
    const i2d_rot q = i2d_body_get_rotation(body);
    printf("    set_transform: |q|^2 after a 1.0004-long rotation %.9f, angle %.7f (expected 2)\n", norm2(q),
           std::atan2(q.s, q.c));
    I2D_CHECK_NEAR(norm2(q), 1.0, 1e-6);
    I2D_CHECK_NEAR(std::atan2(q.s, q.c), 2.0, 1e-6);

    // Refused: far from unit length, zero, NaN. Nothing changes.
    const i2d_transform before = i2d_body_get_transform(body);
    const i2d_rot bad[] = {{1.1f, 0.0f}, {0.0f, 0.0f}, {std::numeric_limits<float>::quiet_NaN(), 0.0f}, {0.7f, 0.7f}};
    for (const i2d_rot& r : bad) {
        I2D_CHECK_STATUS(i2d_body_set_transform(body, i2d_vec2{9, 9}, r), I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(i2d_last_error_message()[0] != '\0');
        const i2d_transform after = i2d_body_get_transform(body);
        I2D_CHECK(std::memcmp(&before, &after, sizeof before) == 0);
    }
    i2d_body_def bad_def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 0});
    bad_def.rotation = i2d_rot{2.0f, 0.0f};
    I2D_CHECK(I2D_IS_NULL(i2d_body_create(scene.world, &bad_def)));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
}

I2D_TEST(phys_rotmotion_point_helpers) {
    // world point = p + R l and local point = R^T (w - p), each the other's inverse; the
    // velocity of the material at a world point is v + w x (point - c) = v + w (-dy, dx).
    Scene scene(Scene::zero_gravity_def());
    const double px = 2, py = 3, angle = 0.4;
    i2d_body_id body = box_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{float(px), float(py)}, angle, 0.5f, 0.5f,
                                i2d_vec2{1, 0.5f});
    I2D_REQUIRE(!I2D_IS_NULL(body));
    const double locals[4][2] = {{0, 0}, {1, 0.5}, {-2.5, 4}, {0.3, -7}};
    double worst_world = 0, worst_round = 0;
    for (const auto& l : locals) {
        const Point world = transform_point(px, py, angle, l[0], l[1]);
        const i2d_vec2 w = i2d_body_get_world_point(body, i2d_vec2{float(l[0]), float(l[1])});
        worst_world = std::max(worst_world, std::hypot(w.x - world.x, w.y - world.y));
        const i2d_vec2 back = i2d_body_get_local_point(body, w);
        worst_round = std::max(worst_round, std::hypot(back.x - l[0], back.y - l[1]));
        // The local point of a world point, against R^T (w - p).
        const double dx = world.x - px, dy = world.y - py;
        const i2d_vec2 loc = i2d_body_get_local_point(body, i2d_vec2{float(world.x), float(world.y)});
        worst_round = std::max(worst_round, std::hypot(loc.x - (std::cos(angle) * dx + std::sin(angle) * dy),
                                                       loc.y - (-std::sin(angle) * dx + std::cos(angle) * dy)));
    }
    I2D_CHECK(worst_world < 1e-5);
    I2D_CHECK(worst_round < 1e-5);

    const double vx = 1, vy = -2, w = 3;
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(body, i2d_vec2{float(vx), float(vy)}), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(body, float(w)), I2D_OK);
    const Point c = transform_point(px, py, angle, 1, 0.5);  // the centre of mass
    const double points[3][2] = {{4, 1}, {c.x, c.y}, {-1, 6}};
    double worst_v = 0;
    for (const auto& pt : points) {
        const double ex = vx - w * (pt[1] - c.y), ey = vy + w * (pt[0] - c.x);
        const i2d_vec2 pv = i2d_body_get_world_point_velocity(body, i2d_vec2{float(pt[0]), float(pt[1])});
        worst_v = std::max(worst_v, std::hypot(pv.x - ex, pv.y - ey));
    }
    printf("    point helpers: world point error %.3g m, round trip %.3g m, point velocity error %.3g m/s\n",
           worst_world, worst_round, worst_v);
    I2D_CHECK(worst_v < 1e-4);
}

I2D_TEST(phys_rotmotion_spin_in_place_is_a_move_event) {
    // A kinematic wheel that only turns (no translation) moved as far as a binding's
    // renderer is concerned: it must be in the body move events with its new rotation.
    Scene scene;
    i2d_body_def def = body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, 0});
    def.angular_velocity = 2.0f;
    const i2d_body_id wheel = scene.box(def, 1.0f, 0.1f);
    I2D_REQUIRE(!I2D_IS_NULL(wheel));
    I2D_REQUIRE(scene.step());
    i2d_body_events events = i2d_world_get_body_events(scene.world);
    I2D_REQUIRE(events.move_count == 1);
    I2D_CHECK(events.move_events[0].body.bits == wheel.bits);
    I2D_CHECK_NEAR(i2d_rot_get_angle(events.move_events[0].transform.q), 2.0 * time_step, 1e-4);
    I2D_CHECK(events.move_events[0].transform.p.x == 0.0f && events.move_events[0].transform.p.y == 0.0f);
}
