// SPDX-License-Identifier: MIT
// Restitution against closed form: head-on collisions of unequal masses, the
// restitution threshold, the min mixing rule, and a ball bouncing on static ground.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// One head-on collision along x without gravity: A moves right at va, B at vb < va.
struct HeadOn {
    bool boxes;        // two unit boxes (half size 0.5) instead of two circles (radius 0.5)
    double density_a;  // mass ratio through density: the shapes have the same size
    double density_b;
    float restitution; // set on both shapes (a contact uses the minimum)
    double va, vb;     // m/s along x
    double gap;        // initial distance between the surfaces, m
};

struct HeadOnResult {
    double mass_a, mass_b, va, vb;
};

// Runs the collision for `seconds` and returns the masses and final velocities; NaN
// velocities when the scene could not be built.
HeadOnResult run_head_on(const HeadOn& c, double seconds, const i2d_world_def& def = Scene::zero_gravity_def()) {
    Scene scene(def);
    const float half = 0.5f;
    const double x = half + 0.5 * c.gap;
    Material ma = with_restitution(c.restitution, float(c.density_a));
    Material mb = with_restitution(c.restitution, float(c.density_b));
    i2d_body_id a, b;
    if (c.boxes) {
        a = scene.dynamic_box(i2d_vec2{float(-x), 0}, half, half, ma, i2d_vec2{float(c.va), 0});
        b = scene.dynamic_box(i2d_vec2{float(x), 0}, half, half, mb, i2d_vec2{float(c.vb), 0});
    } else {
        a = scene.dynamic_circle(i2d_vec2{float(-x), 0}, half, ma, i2d_vec2{float(c.va), 0});
        b = scene.dynamic_circle(i2d_vec2{float(x), 0}, half, mb, i2d_vec2{float(c.vb), 0});
    }
    HeadOnResult r{NAN, NAN, NAN, NAN};
    if (I2D_IS_NULL(a) || I2D_IS_NULL(b) || !scene.step(steps_for(seconds))) {
        return r;
    }
    r.mass_a = i2d_body_get_mass(a);
    r.mass_b = i2d_body_get_mass(b);
    r.va = velocity(a).x;
    r.vb = velocity(b).x;
    // Purely along x: nothing may push sideways.
    I2D_CHECK_NEAR(velocity(a).y, 0.0, 1e-6);
    I2D_CHECK_NEAR(velocity(b).y, 0.0, 1e-6);
    return r;
}

// Checks a finished head-on collision against the closed form for restitution e:
//   va' = (ma va + mb vb - mb e (va - vb)) / (ma + mb)
//   vb' = (ma va + mb vb + ma e (va - vb)) / (ma + mb)
// i.e. momentum conserved and separation speed vb' - va' = e (va - vb).
struct Worst {
    double momentum = 0, separation = 0, energy = 0;  // relative errors
};

void check_head_on(const HeadOn& c, double e, Worst& worst) {
    char what[160];
    snprintf(what, sizeof what, "%s, densities %g:%g, e = %g, va = %g, vb = %g", c.boxes ? "boxes" : "circles",
             c.density_a, c.density_b, e, c.va, c.vb);
    int before = i2d_check_failures;

    HeadOnResult r = run_head_on(c, 1.5);
    const double area = c.boxes ? 1.0 : pi * 0.25;
    const double ma = c.density_a * area, mb = c.density_b * area;
    I2D_CHECK_NEAR(r.mass_a, ma, 1e-5 * ma);
    I2D_CHECK_NEAR(r.mass_b, mb, 1e-5 * mb);

    const double approach = c.va - c.vb;
    const double p0 = ma * c.va + mb * c.vb;
    // Relative to the momentum scale sum(m |v|): total momentum may be near zero.
    const double p_scale = ma * std::fabs(c.va) + mb * std::fabs(c.vb);
    const double p1 = ma * r.va + mb * r.vb;
    I2D_CHECK_NEAR(p1 / p_scale, p0 / p_scale, 1e-5);

    const double separation = r.vb - r.va;
    I2D_CHECK_NEAR(separation, e * approach, std::max(0.01 * e * approach, 1e-3));
    worst.momentum = std::max(worst.momentum, std::fabs(p1 - p0) / p_scale);
    worst.separation = std::max(worst.separation, std::fabs(separation - e * approach) / approach);

    const double va_expected = (p0 - mb * e * approach) / (ma + mb);
    const double vb_expected = (p0 + ma * e * approach) / (ma + mb);
    I2D_CHECK_NEAR(r.va, va_expected, 0.01 * approach);
    I2D_CHECK_NEAR(r.vb, vb_expected, 0.01 * approach);

    if (e == 1.0) {
        const double ke0 = 0.5 * ma * c.va * c.va + 0.5 * mb * c.vb * c.vb;
        const double ke1 = 0.5 * ma * r.va * r.va + 0.5 * mb * r.vb * r.vb;
        I2D_CHECK_NEAR(ke1, ke0, 0.01 * ke0);
        worst.energy = std::max(worst.energy, std::fabs(ke1 - ke0) / ke0);
    }
    report_case(before, what);
}

void head_on_suite(bool boxes) {
    // Mass ratios 1:3 and 1:10 with the light and the heavy body moving first; approach
    // speed 4 m/s, well above the default restitution threshold of 1 m/s.
    const double ratios[][2] = {{1, 3}, {3, 1}, {1, 10}, {10, 1}};
    const float restitutions[] = {0.0f, 0.5f, 1.0f};
    Worst worst;
    for (const auto& ratio : ratios) {
        for (float e : restitutions) {
            check_head_on(HeadOn{boxes, ratio[0], ratio[1], e, 3.0, -1.0, 2.0}, e, worst);
        }
    }
    printf("    head-on %s: worst relative errors: momentum %.2g, separation speed %.2g (of approach), "
           "energy at e = 1 %.2g\n",
           boxes ? "boxes" : "circles", worst.momentum, worst.separation, worst.energy);
}

// Drops a unit-diameter ball from `height` (gap between its bottom and the ground) and
// returns the highest gap reached after it first hit the ground. The static ground's
// position must not change in any step.
double drop_ball(double height, float ball_e, float ground_e, double seconds) {
    Scene scene;
    const float r = 0.5f;
    i2d_body_id ground = scene.ground(0.0f, 50.0f, with_restitution(ground_e));
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, float(r + height)}, r, with_restitution(ball_e));
    if (I2D_IS_NULL(ground) || I2D_IS_NULL(ball)) {
        ++i2d_check_failures;
        return NAN;
    }
    const i2d_vec2 ground0 = position(ground);
    bool hit = false;
    double apex = -1.0;
    for (int i = 0; i < steps_for(seconds); ++i) {
        if (!scene.step()) {
            ++i2d_check_failures;
            return NAN;
        }
        const i2d_vec2 now = position(ground);
        if (!same_bits(now, ground0)) {
            ++i2d_check_failures;
            fprintf(stderr, "static ground moved to (%.9g, %.9g) at step %d\n", now.x, now.y, i);
            return NAN;
        }
        const double bottom = position(ball).y - r;
        // First contact: the ball reached the ground, or already bounced within this
        // step (we only see the state after 4 substeps; it was dropped from rest).
        if (!hit && (bottom <= 0.0 || velocity(ball).y > 0.0f)) {
            hit = true;
        }
        if (hit) {
            apex = std::max(apex, bottom);
        }
        // The ball must never fall through the ground.
        if (bottom < -0.1) {
            ++i2d_check_failures;
            fprintf(stderr, "ball sank to bottom %.6g at step %d\n", bottom, i);
            return NAN;
        }
    }
    if (!hit) {
        ++i2d_check_failures;
        fprintf(stderr, "ball never reached the ground\n");
    }
    return apex;
}

}  // namespace

I2D_TEST(phys_bounce_head_on_circles) { head_on_suite(false); }

I2D_TEST(phys_bounce_head_on_boxes) { head_on_suite(true); }

I2D_TEST(phys_bounce_restitution_is_min_of_shapes) {
    // Shapes with e = 1 and e = 0.25 collide as e = 0.25, whichever is A.
    Scene scene(Scene::zero_gravity_def());
    i2d_body_id a = scene.dynamic_circle(i2d_vec2{-1, 0}, 0.5f, with_restitution(1.0f), i2d_vec2{2, 0});
    i2d_body_id b = scene.dynamic_circle(i2d_vec2{1, 0}, 0.5f, with_restitution(0.25f), i2d_vec2{-2, 0});
    i2d_body_id c = scene.dynamic_circle(i2d_vec2{-1, 5}, 0.5f, with_restitution(0.25f), i2d_vec2{2, 0});
    i2d_body_id d = scene.dynamic_circle(i2d_vec2{1, 5}, 0.5f, with_restitution(1.0f), i2d_vec2{-2, 0});
    I2D_REQUIRE(!I2D_IS_NULL(a) && !I2D_IS_NULL(b) && !I2D_IS_NULL(c) && !I2D_IS_NULL(d));
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    // Equal masses, approach 4 m/s: each bounces back at e x 2 = 0.5 m/s.
    I2D_CHECK_NEAR(velocity(a).x, -0.5, 0.01);
    I2D_CHECK_NEAR(velocity(b).x, 0.5, 0.01);
    I2D_CHECK_NEAR(velocity(c).x, -0.5, 0.01);
    I2D_CHECK_NEAR(velocity(d).x, 0.5, 0.01);
}

I2D_TEST(phys_bounce_restitution_raised_while_touching_takes_effect) {
    // A ball resting on the ground in a world with no elastic contact, stepped long
    // enough for the step to settle into its usual stages. Then both shapes become
    // perfectly elastic and the ball is thrown at the ground at 4 m/s: the same contact,
    // now elastic, sends it back up at 4 m/s (no gravity, so nothing else changes it).
    Scene scene(Scene::zero_gravity_def());
    const float r = 0.5f;
    i2d_body_id ground = scene.ground(0.0f, 50.0f, with_restitution(0.0f));
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, r}, r, with_restitution(0.0f));
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(ball));
    I2D_REQUIRE(scene.step(10));
    I2D_CHECK_NEAR(velocity(ball).y, 0.0, 1e-6);
    I2D_REQUIRE(i2d_shape_set_restitution(only_shape(ground), 1.0f) == I2D_OK);
    I2D_REQUIRE(i2d_shape_set_restitution(only_shape(ball), 1.0f) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_linear_velocity(ball, i2d_vec2{0, -4}) == I2D_OK);
    I2D_REQUIRE(scene.step(steps_for(0.25)));
    I2D_CHECK_NEAR(velocity(ball).y, 4.0, 0.04);
}

I2D_TEST(phys_bounce_below_threshold_does_not_bounce) {
    // Elastic shapes approaching at 0.5 m/s, below the default threshold of 1 m/s: the
    // collision is perfectly inelastic, so both end with the centre-of-mass velocity.
    for (bool boxes : {false, true}) {
        int before = i2d_check_failures;
        HeadOn c{boxes, 1.0, 3.0, 1.0f, 0.5, 0.0, 0.2};
        HeadOnResult r = run_head_on(c, 1.5);
        const double area = boxes ? 1.0 : pi * 0.25;
        const double v_cm = (c.density_a * area * c.va) / ((c.density_a + c.density_b) * area);
        I2D_CHECK_NEAR(r.vb - r.va, 0.0, 0.01 * 0.5);
        I2D_CHECK_NEAR(r.va, v_cm, 0.01 * 0.5);
        I2D_CHECK_NEAR(r.vb, v_cm, 0.01 * 0.5);
        report_case(before, boxes ? "boxes at 0.5 m/s" : "circles at 0.5 m/s");
    }
}

I2D_TEST(phys_bounce_threshold_from_world_def) {
    // The world def's threshold is honoured: at 5 m/s an approach of 4 m/s does not
    // bounce; at 3 m/s it does (e = 1 swaps the velocities of equal masses).
    i2d_world_def def = Scene::zero_gravity_def();
    def.restitution_threshold = 5.0f;
    HeadOn c{false, 1.0, 1.0, 1.0f, 2.0, -2.0, 1.0};
    HeadOnResult r = run_head_on(c, 1.0, def);
    I2D_CHECK_NEAR(r.va, 0.0, 0.04);
    I2D_CHECK_NEAR(r.vb, 0.0, 0.04);

    def.restitution_threshold = 3.0f;
    r = run_head_on(c, 1.0, def);
    I2D_CHECK_NEAR(r.va, -2.0, 0.04);
    I2D_CHECK_NEAR(r.vb, 2.0, 0.04);
}

I2D_TEST(phys_bounce_ball_drop_apex) {
    // Dropped from h = 2 m, the ball hits at v = sqrt(2 g h), leaves at e v and rises to
    // (e v)^2 / 2g = e^2 h. Restitution 0.8 on the ball and 1 on the ground (the contact
    // takes the minimum, 0.8); then the other way round.
    const double h = 2.0;
    double apex = drop_ball(h, 0.8f, 1.0f, 2.5);
    printf("    ball drop: h = %.3f m, e = 0.8: apex %.4f m, expected %.4f m (ratio %.4f)\n", h, apex,
           0.64 * h, apex / (0.64 * h));
    I2D_CHECK_NEAR(apex, 0.64 * h, 0.05 * 0.64 * h);

    apex = drop_ball(h, 1.0f, 0.8f, 2.5);
    I2D_CHECK_NEAR(apex, 0.64 * h, 0.05 * 0.64 * h);

    // Half as bouncy: apex e^2 h = 0.25 h.
    apex = drop_ball(h, 0.5f, 1.0f, 2.5);
    printf("    ball drop: h = %.3f m, e = 0.5: apex %.4f m, expected %.4f m (ratio %.4f)\n", h, apex,
           0.25 * h, apex / (0.25 * h));
    I2D_CHECK_NEAR(apex, 0.25 * h, 0.05 * 0.25 * h);
}

I2D_TEST(phys_bounce_ball_on_inelastic_ground) {
    // A bouncy ball on ground with restitution 0: the minimum is 0, no bounce. The ball
    // may sit at most a slop into the ground, and must not rise off it.
    const double h = 2.0;
    double apex = drop_ball(h, 0.8f, 0.0f, 2.0);
    I2D_CHECK(apex <= 0.01 * h);
}

I2D_TEST(phys_bounce_slow_drop_does_not_bounce) {
    // From 2 cm the impact speed is sqrt(2 g h) = 0.63 m/s, below the 1 m/s threshold:
    // an elastic ball on elastic ground does not bounce (it would rise 2 cm if it did).
    const double h = 0.02;
    double apex = drop_ball(h, 1.0f, 1.0f, 1.0);
    I2D_CHECK(apex <= 0.1 * h);
}
