/* SPDX-License-Identifier: MIT */
/* Finite but extreme input: what fuzzing the API found. Huge velocities and impulses are
 * clamped where they enter (the world's maximum_linear_speed, max angular speed) so a
 * step never turns them into NaN; status values outside the enumeration are read as
 * integers; the pure collide functions refuse coordinates beyond their documented range
 * and give finite, unit-normal answers inside it. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

/* The fuzzer's scene: two dynamic boxes with restitution 0.5, one above the other. */
typedef struct bounce_pair {
    i2d_world_id world;
    i2d_body_id first, second;
} bounce_pair;

static i2d_body_id create_bouncy_box(i2d_world_id world, float x, float y) {
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position.x = x;
    def.position.y = y;
    i2d_body_id body = i2d_body_create(world, &def);
    i2d_shape_def shape = i2d_default_shape_def();
    shape.restitution = 0.5f;
    i2d_shape_create_box(body, &shape, 0.5f, 0.5f);
    return body;
}

static bounce_pair create_bounce_pair(void) {
    i2d_world_def def = i2d_default_world_def();
    bounce_pair p;
    p.world = i2d_world_create(&def);
    p.first = create_bouncy_box(p.world, 0.0f, 0.5f);
    p.second = create_bouncy_box(p.world, 0.25f, 1.5f);
    return p;
}

static bool vec_finite(i2d_vec2 v) { return isfinite(v.x) && isfinite(v.y); }

/* Both bodies finite after one step of 1/60 s. (Not within the speed limit: a clamped
 * 1e5 rad/s spin still pushes the other box hard within the step.) */
static void check_pair_after_step(bounce_pair* p, const char* what) {
    I2D_CHECK_STATUS(i2d_world_step(p->world, 1.0f / 60.0f, 4), I2D_OK);
    i2d_body_id bodies[2] = {p->first, p->second};
    for (int k = 0; k < 2; ++k) {
        i2d_vec2 v = i2d_body_get_linear_velocity(bodies[k]);
        i2d_vec2 x = i2d_body_get_position(bodies[k]);
        float w = i2d_body_get_angular_velocity(bodies[k]);
        if (!vec_finite(v) || !vec_finite(x) || !isfinite(w)) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: %s: body %d has v (%g, %g), w %g, x (%g, %g)\n", __FILE__, __LINE__, what, k,
                    (double)v.x, (double)v.y, (double)w, (double)x.x, (double)x.y);
        }
    }
    i2d_world_destroy(p->world);
}

I2D_TEST(api_extreme_linear_velocity_clamped) {
    bounce_pair p = create_bounce_pair();
    i2d_vec2 huge = {0.0f, 1e20f};
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(p.first, huge), I2D_OK);
    /* Clamped at once, direction kept. */
    i2d_vec2 v = i2d_body_get_linear_velocity(p.first);
    I2D_CHECK_NEAR(v.x, 0.0f, 0.0f);
    I2D_CHECK_NEAR(v.y, i2d_default_world_def().maximum_linear_speed, 1e-3);
    check_pair_after_step(&p, "linear velocity 1e20");

    p = create_bounce_pair();
    i2d_vec2 largest = {-3.4e38f, 3.4e38f};
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(p.first, largest), I2D_OK);
    v = i2d_body_get_linear_velocity(p.first);
    I2D_CHECK_NEAR(v.x, -v.y, 1e-3);
    check_pair_after_step(&p, "linear velocity near FLT_MAX");
}

I2D_TEST(api_extreme_angular_velocity_clamped) {
    bounce_pair p = create_bounce_pair();
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(p.first, 1e30f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(p.first) <= 1.0e5f);
    I2D_CHECK(i2d_body_get_angular_velocity(p.first) > 0.0f);
    check_pair_after_step(&p, "angular velocity 1e30");

    p = create_bounce_pair();
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(p.second, -1e30f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(p.second) >= -1.0e5f);
    check_pair_after_step(&p, "angular velocity -1e30");
}

I2D_TEST(api_extreme_impulse_clamped) {
    bounce_pair p = create_bounce_pair();
    i2d_vec2 impulse = {0.0f, 1e25f};
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(p.first, impulse, i2d_body_get_world_center_of_mass(p.first), true),
                     I2D_OK);
    check_pair_after_step(&p, "linear impulse 1e25");

    p = create_bounce_pair();
    i2d_vec2 off_centre = i2d_body_get_world_center_of_mass(p.first);
    off_centre.x += 0.4f;
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(p.first, impulse, off_centre, true), I2D_OK);
    check_pair_after_step(&p, "linear impulse 1e25 off centre");

    p = create_bounce_pair();
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(p.first, 1e25f, true), I2D_OK);
    check_pair_after_step(&p, "angular impulse 1e25");
}

/* Found by fuzzing: restitution estimates a point's impact speed from the pair's approach
 * acceleration, sqrt(v^2 + 2 a gap); a force near FLT_MAX (accepted: finite, no overflow
 * in the body's sum) made that infinite, and the restitution pass then wrote NaN (the
 * body was quarantined). The second box starts 5 cm above the first, falling. */
I2D_TEST(api_extreme_force_keeps_restitution_finite) {
    const float forces[] = {1e30f, 3e38f};
    for (int k = 0; k < 2; ++k) {
        bounce_pair p = create_bounce_pair();
        i2d_transform lifted = {{0.25f, 1.55f}, {1.0f, 0.0f}};
        I2D_CHECK_STATUS(i2d_body_set_transform(p.second, lifted.p, lifted.q), I2D_OK);
        I2D_CHECK_STATUS(i2d_body_set_linear_velocity(p.second, (i2d_vec2){0.0f, -3.0f}), I2D_OK);
        I2D_CHECK_STATUS(i2d_body_apply_force_to_center(p.second, (i2d_vec2){0.0f, -forces[k]}, true), I2D_OK);
        I2D_CHECK_STATUS(i2d_world_step(p.world, 1.0f / 60.0f, 4), I2D_OK);
        i2d_body_events events = i2d_world_get_body_events(p.world);
        I2D_CHECK(events.quarantine_count == 0);
        I2D_CHECK(!i2d_body_is_quarantined(p.first) && !i2d_body_is_quarantined(p.second));
        check_pair_after_step(&p, "force near FLT_MAX");
    }
}

I2D_TEST(api_extreme_body_def_velocity_clamped) {
    i2d_world_def wdef = i2d_default_world_def();
    bounce_pair p;
    p.world = i2d_world_create(&wdef);
    p.second = create_bouncy_box(p.world, 0.25f, 1.5f);
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position.y = 0.5f;
    def.linear_velocity.y = 1e20f;
    def.angular_velocity = 1e30f;
    p.first = i2d_body_create(p.world, &def);
    i2d_shape_def shape = i2d_default_shape_def();
    shape.restitution = 0.5f;
    i2d_shape_create_box(p.first, &shape, 0.5f, 0.5f);
    I2D_CHECK(i2d_body_get_linear_velocity(p.first).y <= wdef.maximum_linear_speed);
    check_pair_after_step(&p, "body def velocities 1e20, 1e30");
}

I2D_TEST(api_extreme_status_string_out_of_range) {
    /* A C caller may pass any int; each must give a fixed string, no undefined behaviour. */
    const int values[] = {139, -1, (int)I2D_ERR_INVALID_SNAPSHOT + 1, 1 << 30, -2147483647 - 1};
    for (size_t k = 0; k < sizeof values / sizeof values[0]; ++k) {
        i2d_status status;
        memcpy(&status, &values[k], sizeof status);
        const char* name = i2d_status_string(status);
        I2D_REQUIRE(name != NULL);
        I2D_CHECK(strcmp(name, "I2D_UNKNOWN_STATUS") == 0);
    }
    I2D_CHECK(strcmp(i2d_status_string(I2D_ERR_INTERNAL), "I2D_ERR_INTERNAL") == 0);
    I2D_CHECK(strcmp(i2d_status_string(I2D_ERR_OUT_OF_MEMORY), "I2D_ERR_OUT_OF_MEMORY") == 0);
    I2D_CHECK(strcmp(i2d_status_string(I2D_ERR_INVALID_SNAPSHOT), "I2D_ERR_INVALID_SNAPSHOT") == 0);
}

/* ---- The pure collide functions: a documented range, enforced ----------------------- */

static bool manifold_sane(i2d_manifold m) {
    if (m.point_count == 0) {
        return true;
    }
    const float n = sqrtf(m.normal.x * m.normal.x + m.normal.y * m.normal.y);
    bool ok = fabsf(n - 1.0f) < 1e-3f;
    for (int i = 0; i < m.point_count; ++i) {
        ok = ok && vec_finite(m.points[i].point) && isfinite(m.points[i].penetration);
    }
    return ok;
}

I2D_TEST(api_extreme_collide_refuses_out_of_range) {
    /* Around 1e19 the products inside overflowed into NaN points and zero normals. */
    const float far[] = {1.0e19f, -1.0e19f, 3.0e38f, 1.0000001e9f * 1.01f};
    for (size_t k = 0; k < sizeof far / sizeof far[0]; ++k) {
        i2d_circle a = {{far[k], 0.0f}, 1.0f};
        i2d_circle b = {{far[k], 0.5f}, 1.0f};
        i2d_manifold m = i2d_collide_circles(a, b);
        I2D_CHECK(m.point_count == 0);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);

        i2d_aabb box_a = {{far[k], 0.0f}, {far[k] * 1.0f + fabsf(far[k]) * 1e-6f, 1.0f}};
        if (box_a.min.x > box_a.max.x) {
            i2d_vec2 t = box_a.min;
            box_a.min.x = box_a.max.x;
            box_a.max.x = t.x;
        }
        i2d_aabb box_b = box_a;
        m = i2d_collide_aabbs(box_a, box_b);
        I2D_CHECK(m.point_count == 0);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
        m = i2d_collide_aabb_circle(box_a, b);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);

        /* A huge radius is refused like a huge centre. */
        i2d_circle big = {{0.0f, 0.0f}, fabsf(far[k])};
        m = i2d_collide_circles(big, a);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);

        i2d_polygon box1 = i2d_make_box(0.5f, 0.5f);
        i2d_transform xf = {{far[k], 0.0f}, {1.0f, 0.0f}};
        i2d_transform origin = {{0.0f, 0.0f}, {1.0f, 0.0f}};
        m = i2d_collide_polygons(&box1, xf, &box1, origin);
        I2D_CHECK(m.point_count == 0);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
        i2d_capsule cap = {{0.0f, 0.0f}, {far[k], 0.0f}, 0.5f};
        m = i2d_collide_capsules(&cap, origin, &cap, origin);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    }
}

/* Everything inside the documented range (|coordinate|, radius <= 1e9) gives finite
 * points and unit normals: random pairs of every world-space kind near the edge. */
I2D_TEST(api_extreme_collide_sane_within_range) {
    rng r = {18};
    g_reports_left = 10;
    const float edge = 1.0e9f;
    for (int k = 0; k < 20000; ++k) {
        float scale = k % 2 ? edge : rng_float(&r, 1.0f, edge);
        float cx = rng_float(&r, -scale, scale), cy = rng_float(&r, -scale, scale);
        i2d_circle a = {{cx, cy}, rng_float(&r, 0.0f, scale)};
        i2d_circle b = {{cx + rng_float(&r, -scale, scale) * 0.5f, cy}, rng_float(&r, 0.0f, scale)};
        if (fabsf(b.center.x) > edge) {
            b.center.x = cx;
        }
        i2d_manifold m = i2d_collide_circles(a, b);
        if (i2d_last_status() != I2D_OK || !manifold_sane(m)) {
            ++i2d_check_failures;
            report("circles %d: status %s, normal (%g, %g)", k, i2d_status_string(i2d_last_status()),
                   (double)m.normal.x, (double)m.normal.y);
        }
        i2d_aabb box_a = {{cx - a.radius * 0.5f, cy - a.radius * 0.5f}, {cx + a.radius * 0.5f, cy + a.radius * 0.5f}};
        if (fabsf(box_a.min.x) > edge || fabsf(box_a.max.x) > edge || fabsf(box_a.min.y) > edge ||
            fabsf(box_a.max.y) > edge) {
            continue;
        }
        m = i2d_collide_aabb_circle(box_a, b);
        if (i2d_last_status() != I2D_OK || !manifold_sane(m)) {
            ++i2d_check_failures;
            report("aabb-circle %d: status %s, normal (%g, %g)", k, i2d_status_string(i2d_last_status()),
                   (double)m.normal.x, (double)m.normal.y);
        }
        m = i2d_collide_aabbs(box_a, box_a);
        if (i2d_last_status() != I2D_OK || !manifold_sane(m)) {
            ++i2d_check_failures;
            report("aabbs %d: status %s", k, i2d_status_string(i2d_last_status()));
        }
    }
}

/* ---- Found by fuzzing ------------------------------------------------------------- */

/* A denormal time step (1e-45 s) was accepted: the solver's rates (substeps / step)
 * became infinite and a body resting on another turned NaN within the step. Positive
 * steps below 1e-6 s are refused now and change nothing; 1e-6 s itself is stepped. */
/* The fuzzer's joint tree: a disc hinged to a static body and welded to a triangle whose
 * far corner lies 100 km out (5e9 kg, its centre of mass 47 km from the disc). The exact
 * tree solve's factors are then too ill-conditioned for floats, and a pass threw the disc
 * from rest to 1e19 m/s and NaN the step after; the pass is now undone like a runaway
 * sweep's, and the bodies stay finite and never quarantined. */
I2D_TEST(api_extreme_joint_tree_with_far_mass_stays_finite) {
    i2d_world_def wdef = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&wdef);
    i2d_body_def def = i2d_default_body_def();
    def.position = (i2d_vec2){0.0f, -1.0f};
    i2d_body_id ground = i2d_body_create(world, &def);
    def.type = I2D_BODY_DYNAMIC;
    def.position = (i2d_vec2){-1.0f, -3.95532f};
    i2d_body_id disc = i2d_body_create(world, &def);
    def.position = (i2d_vec2){0.1875f, 1.0f};
    i2d_body_id far = i2d_body_create(world, &def);
    i2d_shape_def shape = i2d_default_shape_def();
    i2d_circle circle = {{-4.0f, -3.97290039f}, 1.08227539f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(disc, &shape, &circle)));
    const i2d_vec2 corners[3] = {{-3.24707031f, -3.24707031f}, {100000.0f, -3.80957031f}, {1.40129846e-45f, 100000.0f}};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_polygon(far, &shape, corners, 3)));
    i2d_revolute_joint_def hinge = i2d_default_revolute_joint_def();
    hinge.base.body_a = ground;
    hinge.base.body_b = disc;
    I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_revolute(world, &hinge)));
    i2d_weld_joint_def weld = i2d_default_weld_joint_def();
    weld.base.body_a = far;
    weld.base.body_b = disc;
    I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_weld(world, &weld)));
    int quarantined = 0, non_finite = 0;
    for (int step = 0; step < 60; ++step) {
        I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 4), I2D_OK);
        quarantined += i2d_world_get_body_events(world).quarantine_count;
        i2d_body_id bodies[2] = {disc, far};
        for (int k = 0; k < 2; ++k) {
            non_finite += !vec_finite(i2d_body_get_linear_velocity(bodies[k])) ||
                          !vec_finite(i2d_body_get_position(bodies[k])) ||
                          !isfinite(i2d_body_get_angular_velocity(bodies[k]));
        }
    }
    fprintf(stderr, "    quarantined %d, non-finite readings %d, disc at (%g, %g)\n", quarantined, non_finite,
            (double)i2d_body_get_position(disc).x, (double)i2d_body_get_position(disc).y);
    I2D_CHECK(quarantined == 0);
    I2D_CHECK(non_finite == 0);
    i2d_world_destroy(world);
}

/* Found by fuzzing: any finite gravity is accepted, and the integration holds a body to
 * the speed limit; but a fast body swept back to where it hit a wall handed back the
 * gravity of the time it lost as if it had been given in full: under 1e6 m/s^2 a ball
 * without restitution bounced off the wall at the speed limit, and near FLT_MAX it was
 * left at -5.7e36 m/s, which the impact could turn into NaN. A ball falls from rest into
 * a thin static wall 3 m away, along each axis both ways: the first step's impact stops
 * it at the wall, and it stays finite. (It is not asked to stay out of the wall: pressed
 * at the speed limit every substep, the soft contact gives and it creeps through.) */
I2D_TEST(api_extreme_gravity_stops_a_swept_body_at_the_wall) {
    const float magnitudes[2] = {1e6f, 3.4e38f};
    const i2d_vec2 directions[4] = {{1.0f, 0.0f}, {-1.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, -1.0f}};
    for (int k = 0; k < 8; ++k) {
        const i2d_vec2 toward = directions[k % 4];
        i2d_world_def wdef = i2d_default_world_def();
        wdef.gravity = (i2d_vec2){magnitudes[k / 4] * toward.x, magnitudes[k / 4] * toward.y};
        i2d_world_id world = i2d_world_create(&wdef);
        i2d_body_def def = i2d_default_body_def();
        def.position = (i2d_vec2){3.0f * toward.x, 3.0f * toward.y};
        def.rotation = toward.x != 0.0f ? identity_rot() : rot(0.0f, 1.0f);
        i2d_body_id wall = i2d_body_create(world, &def);
        i2d_shape_def shape = i2d_default_shape_def();
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(wall, &shape, 0.05f, 20.0f)));
        def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        i2d_body_id ball = i2d_body_create(world, &def);
        i2d_circle circle = {{0.0f, 0.0f}, 0.25f};
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(ball, &shape, &circle)));
        I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 4), I2D_OK);
        const i2d_vec2 at = i2d_body_get_position(ball), v = i2d_body_get_linear_velocity(ball);
        const float along = at.x * toward.x + at.y * toward.y, speed_along = v.x * toward.x + v.y * toward.y;
        if (!(along > 2.6f && along < 2.95f && speed_along > -1.0f && speed_along < 1.0f)) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: gravity %g along (%g, %g): after the hit the ball is %g m along at %g m/s\n",
                    __FILE__, __LINE__, (double)magnitudes[k / 4], (double)toward.x, (double)toward.y, (double)along,
                    (double)speed_along);
        }
        int non_finite = 0;
        for (int step = 0; step < 10; ++step) {
            I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 4), I2D_OK);
            non_finite += !vec_finite(i2d_body_get_linear_velocity(ball)) || !vec_finite(i2d_body_get_position(ball)) ||
                          i2d_body_is_quarantined(ball);
        }
        I2D_CHECK(non_finite == 0);
        i2d_world_destroy(world);
    }
}

I2D_TEST(api_extreme_tiny_time_step_refused) {
    const float tiny[] = {1.4e-45f, 1.1754944e-38f, 1e-30f, 9.9e-7f};
    for (size_t k = 0; k < sizeof tiny / sizeof tiny[0]; ++k) {
        bounce_pair p = create_bounce_pair();
        const i2d_vec2 before = i2d_body_get_position(p.first);
        I2D_CHECK_STATUS(i2d_world_step(p.world, tiny[k], 4), I2D_ERR_INVALID_ARGUMENT);
        const i2d_vec2 after = i2d_body_get_position(p.first);
        I2D_CHECK(before.x == after.x && before.y == after.y);
        I2D_CHECK_STATUS(i2d_world_step(p.world, 1e-6f, 1000), I2D_OK);
        I2D_CHECK_STATUS(i2d_world_step(p.world, 0.0f, 4), I2D_OK);
        check_pair_after_step(&p, "after a refused tiny step");
    }
}

/* Found by fuzzing: i2d_make_rot of a huge finite angle returned (inf, -inf). */
I2D_TEST(api_extreme_make_rot_far_angle) {
    const float far[] = {3.4028235e38f, -1e30f, 1e9f};
    for (size_t k = 0; k < sizeof far / sizeof far[0]; ++k) {
        i2d_rot q = i2d_make_rot(far[k]);
        I2D_CHECK(i2d_last_status() == I2D_OK);
        I2D_CHECK(isfinite(q.c) && isfinite(q.s));
        I2D_CHECK_NEAR(q.c * q.c + q.s * q.s, 1.0, 1e-6);
    }
}
