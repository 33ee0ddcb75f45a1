/* SPDX-License-Identifier: MIT */
/* C API tour: the README's hello world, a call to every public function, and the frozen struct layouts. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

static const double k_pi = 3.14159265358979323846;

static i2d_vec2 v2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static i2d_aabb box(float min_x, float min_y, float max_x, float max_y) {
    i2d_aabb b;
    b.min = v2(min_x, min_y);
    b.max = v2(max_x, max_y);
    return b;
}

/* ---- Hello world ------------------------------------------------------------------ */

I2D_TEST(api_world_hello) {
    /* A world with the default gravity, (0, -10) m/s^2. */
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(world));

    /* The ground: a static box 20 m wide and 2 m tall whose top is at y = 0. */
    i2d_body_def ground_def = i2d_default_body_def();
    ground_def.position = (i2d_vec2){0.0f, -1.0f};
    i2d_body_id ground = i2d_body_create(world, &ground_def);
    i2d_shape_def ground_shape = i2d_default_shape_def();
    i2d_shape_create_box(ground, &ground_shape, 10.0f, 1.0f);

    /* A ball of radius 0.5 m dropped from 4 m. */
    i2d_body_def ball_def = i2d_default_body_def();
    ball_def.type = I2D_BODY_DYNAMIC;
    ball_def.position = (i2d_vec2){0.0f, 4.0f};
    i2d_body_id ball = i2d_body_create(world, &ball_def);
    i2d_shape_def ball_shape = i2d_default_shape_def();
    i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    i2d_shape_create_circle(ball, &ball_shape, &circle);

    /* Two seconds at 60 Hz with 4 substeps. */
    for (int i = 0; i < 120; ++i) {
        I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 4), I2D_OK);
    }

    /* The ball rests on the ground: its centre one radius above the ground's top. */
    i2d_vec2 p = i2d_body_get_position(ball);
    printf("ball at (%.4f, %.4f)\n", p.x, p.y);
    I2D_CHECK_NEAR(p.y, 0.0 + 0.5, 0.01);
    I2D_CHECK_NEAR(p.x, 0.0, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(ball).y, 0.0, 0.05);

    i2d_world_counters counters = i2d_world_get_counters(world);
    I2D_CHECK(counters.body_count == 2);
    I2D_CHECK(counters.shape_count == 2);
    I2D_CHECK(counters.contact_count == 1);
    I2D_CHECK(counters.pair_count >= 0 && counters.pair_count <= 1); /* one possible pair */

    i2d_world_destroy(world);
}

/* ---- Coverage: every public function once, with sensible results ------------------- */

static bool contains_id(const i2d_shape_id* ids, int count, i2d_shape_id id) {
    for (int i = 0; i < count; ++i) {
        if (I2D_ID_EQUALS(ids[i], id)) {
            return true;
        }
    }
    return false;
}

typedef struct id_list {
    int count;
    i2d_shape_id ids[16];
} id_list;

static bool collect_id(i2d_shape_id shape, void* context) {
    id_list* list = (id_list*)context;
    if (list->count < 16) {
        list->ids[list->count] = shape;
    }
    ++list->count;
    return true;
}

static void cover_library_calls(void) {
    I2D_CHECK(i2d_version() == (uint32_t)I2D_VERSION);
    I2D_CHECK(strcmp(i2d_status_string(I2D_ERR_INVALID_HANDLE), "I2D_ERR_INVALID_HANDLE") == 0);
    i2d_world_destroy(I2D_NULL_WORLD_ID);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_last_error_message()[0] != '\0');
}

/* The defaults documented in types.h and capi.md. */
static void cover_defaults(void) {
    i2d_world_def w = i2d_default_world_def();
    I2D_CHECK(w.gravity.x == 0.0f && w.gravity.y == -10.0f);
    I2D_CHECK_NEAR(w.contact_slop, 0.005, 1e-9);
    I2D_CHECK_NEAR(w.contact_correction_percent, 0.8, 1e-7);
    I2D_CHECK(w.restitution_threshold == 1.0f);
    I2D_CHECK(w.maximum_linear_speed == 400.0f);
    I2D_CHECK(w.velocity_iterations == 10);
    I2D_CHECK(w.enable_sleep);
    I2D_CHECK(w.internal_cookie != 0);

    i2d_body_def b = i2d_default_body_def();
    I2D_CHECK(b.type == I2D_BODY_STATIC);
    I2D_CHECK(b.position.x == 0.0f && b.position.y == 0.0f);
    I2D_CHECK(b.rotation.c == 1.0f && b.rotation.s == 0.0f);
    I2D_CHECK(b.linear_velocity.x == 0.0f && b.linear_velocity.y == 0.0f);
    I2D_CHECK(b.angular_velocity == 0.0f);
    I2D_CHECK(b.linear_damping == 0.0f && b.angular_damping == 0.0f);
    I2D_CHECK(b.gravity_scale == 1.0f);
    I2D_CHECK(!b.fixed_rotation && b.enable_sleep && !b.is_bullet);
    I2D_CHECK(b.user_data == NULL);
    I2D_CHECK(b.internal_cookie != 0);

    i2d_shape_def s = i2d_default_shape_def();
    I2D_CHECK(s.density == 1.0f);
    I2D_CHECK_NEAR(s.friction, 0.6, 1e-7);
    I2D_CHECK(s.restitution == 0.0f);
    I2D_CHECK(!s.is_sensor && s.enable_contact_events);
    I2D_CHECK(s.filter.category_bits == 1 && s.filter.mask_bits == UINT64_MAX && s.filter.group_index == 0);
    I2D_CHECK(s.user_data == NULL);
    I2D_CHECK(s.internal_cookie != 0);

    i2d_filter f = i2d_default_filter();
    I2D_CHECK(f.category_bits == 1 && f.mask_bits == UINT64_MAX && f.group_index == 0);
    /* "A query filter that sees every shape": a shape is seen when its mask meets the
     * query's category, so the category must have every bit, like the mask. */
    i2d_query_filter q = i2d_default_query_filter();
    I2D_CHECK(q.category_bits == UINT64_MAX && q.mask_bits == UINT64_MAX);
}

/* The bodies and shapes of the coverage world. */
typedef struct tour {
    i2d_world_id world;
    i2d_body_id ground, compound, sensor_body, mover, empty;
    i2d_shape_id ground_box, circle, box, sensor;
} tour;

static int k_body_tag, k_circle_tag, k_other_tag;

/* Circle of the compound body: local centre (1, 0), radius 0.5, density 2. */
static const float k_circle_radius = 0.5f, k_circle_density = 2.0f;
/* Box of the compound body: half extents (0.5, 0.25), density 3. */
static const float k_box_hw = 0.5f, k_box_hh = 0.25f, k_box_density = 3.0f;

static bool tour_build(tour* t) {
    memset(t, 0, sizeof *t);
    i2d_world_def world_def = i2d_default_world_def();
    t->world = i2d_world_create(&world_def);
    if (I2D_IS_NULL(t->world)) {
        return false;
    }
    i2d_body_def def = i2d_default_body_def();
    def.position = v2(0.0f, -1.0f);
    t->ground = i2d_body_create(t->world, &def);

    def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position = v2(2.0f, 3.0f);
    def.user_data = &k_body_tag;
    t->compound = i2d_body_create(t->world, &def);

    def = i2d_default_body_def();
    def.position = v2(-5.0f, 5.0f);
    t->sensor_body = i2d_body_create(t->world, &def);

    def = i2d_default_body_def();
    def.type = I2D_BODY_KINEMATIC;
    def.position = v2(0.0f, 10.0f);
    def.linear_velocity = v2(1.0f, 0.0f);
    t->mover = i2d_body_create(t->world, &def);

    def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position = v2(-3.0f, 8.0f);
    t->empty = i2d_body_create(t->world, &def);

    i2d_shape_def shape_def = i2d_default_shape_def();
    t->ground_box = i2d_shape_create_box(t->ground, &shape_def, 10.0f, 1.0f);

    shape_def = i2d_default_shape_def();
    shape_def.density = k_circle_density;
    shape_def.friction = 0.3f;
    shape_def.restitution = 0.2f;
    shape_def.filter.category_bits = 2;
    shape_def.filter.mask_bits = 5;
    shape_def.filter.group_index = -3;
    shape_def.user_data = &k_circle_tag;
    i2d_circle circle = {{1.0f, 0.0f}, k_circle_radius};
    t->circle = i2d_shape_create_circle(t->compound, &shape_def, &circle);

    shape_def = i2d_default_shape_def();
    shape_def.density = k_box_density;
    t->box = i2d_shape_create_box(t->compound, &shape_def, k_box_hw, k_box_hh);

    shape_def = i2d_default_shape_def();
    shape_def.is_sensor = true;
    i2d_circle sensor_circle = {{0.0f, 0.0f}, 1.0f};
    t->sensor = i2d_shape_create_circle(t->sensor_body, &shape_def, &sensor_circle);

    return !I2D_IS_NULL(t->ground) && !I2D_IS_NULL(t->compound) && !I2D_IS_NULL(t->sensor_body) &&
           !I2D_IS_NULL(t->mover) && !I2D_IS_NULL(t->empty) && !I2D_IS_NULL(t->ground_box) &&
           !I2D_IS_NULL(t->circle) && !I2D_IS_NULL(t->box) && !I2D_IS_NULL(t->sensor);
}

static void check_aabb_near(i2d_aabb actual, i2d_aabb expected, double tol) {
    I2D_CHECK_NEAR(actual.min.x, expected.min.x, tol);
    I2D_CHECK_NEAR(actual.min.y, expected.min.y, tol);
    I2D_CHECK_NEAR(actual.max.x, expected.max.x, tol);
    I2D_CHECK_NEAR(actual.max.y, expected.max.y, tol);
}

static void cover_world_getters(const tour* t) {
    I2D_CHECK(i2d_world_is_valid(t->world));
    I2D_CHECK_STATUS(i2d_world_set_gravity(t->world, v2(0.5f, -5.0f)), I2D_OK);
    i2d_vec2 g = i2d_world_get_gravity(t->world);
    I2D_CHECK(g.x == 0.5f && g.y == -5.0f);
    i2d_world_counters counters = i2d_world_get_counters(t->world);
    I2D_CHECK(counters.body_count == 5);
    I2D_CHECK(counters.shape_count == 4);
    I2D_CHECK(counters.contact_count == 0); /* nothing stepped yet */
}

static void cover_body_getters(const tour* t) {
    I2D_CHECK(i2d_body_is_valid(t->compound));
    I2D_CHECK(I2D_ID_EQUALS(i2d_body_get_world(t->compound), t->world));
    I2D_CHECK(i2d_body_get_type(t->ground) == I2D_BODY_STATIC);
    I2D_CHECK(i2d_body_get_type(t->mover) == I2D_BODY_KINEMATIC);
    I2D_CHECK(i2d_body_get_type(t->compound) == I2D_BODY_DYNAMIC);
    i2d_vec2 p = i2d_body_get_position(t->compound);
    I2D_CHECK(p.x == 2.0f && p.y == 3.0f);
    i2d_rot q = i2d_body_get_rotation(t->compound);
    I2D_CHECK(q.c == 1.0f && q.s == 0.0f);
    i2d_transform xf = i2d_body_get_transform(t->compound);
    I2D_CHECK(xf.p.x == 2.0f && xf.p.y == 3.0f && xf.q.c == 1.0f && xf.q.s == 0.0f);
    i2d_vec2 v = i2d_body_get_linear_velocity(t->mover);
    I2D_CHECK(v.x == 1.0f && v.y == 0.0f);
    I2D_CHECK(i2d_body_get_angular_velocity(t->compound) == 0.0f);
    I2D_CHECK(i2d_body_get_user_data(t->compound) == &k_body_tag);
    I2D_CHECK(i2d_body_get_user_data(t->ground) == NULL);

    /* Static bodies sleep for good; the others are awake until sleeping lands. */
    I2D_CHECK(!i2d_body_is_awake(t->ground));
    I2D_CHECK(i2d_body_is_awake(t->compound));
    I2D_CHECK(i2d_body_is_awake(t->mover));
    I2D_CHECK(i2d_body_is_awake(t->empty));

    I2D_CHECK(i2d_body_get_shape_count(t->compound) == 2);
    I2D_CHECK(i2d_body_get_shape_count(t->empty) == 0);
    i2d_shape_id shapes[4] = {{0}, {0}, {0}, {0}};
    I2D_CHECK(i2d_body_get_shapes(t->compound, shapes, 4) == 2);
    I2D_CHECK(contains_id(shapes, 2, t->circle) && contains_id(shapes, 2, t->box));
    I2D_CHECK(shapes[2].bits == 0 && shapes[3].bits == 0);
    /* A short buffer: filled up to its capacity, the return value is still the count. */
    i2d_shape_id one[2] = {{0}, {0}};
    I2D_CHECK(i2d_body_get_shapes(t->compound, one, 1) == 2);
    I2D_CHECK(I2D_ID_EQUALS(one[0], t->circle) || I2D_ID_EQUALS(one[0], t->box));
    I2D_CHECK(one[1].bits == 0);
}

/* Mass is density x area summed; the centre of mass is the mass-weighted centroid. */
static void cover_mass(const tour* t) {
    const double circle_mass = k_circle_density * k_pi * k_circle_radius * k_circle_radius;
    const double box_mass = k_box_density * 4.0 * k_box_hw * k_box_hh;
    const double mass = circle_mass + box_mass;
    I2D_CHECK_NEAR(i2d_body_get_mass(t->compound), mass, 1e-5 * mass);
    i2d_vec2 com = i2d_body_get_world_center_of_mass(t->compound);
    /* Body at (2, 3); circle centred at local (1, 0), box at the origin. */
    I2D_CHECK_NEAR(com.x, 2.0 + circle_mass * 1.0 / mass, 1e-5);
    I2D_CHECK_NEAR(com.y, 3.0, 1e-5);

    /* No shapes: 1 kg at the body origin. Static and kinematic: 0. */
    I2D_CHECK(i2d_body_get_mass(t->empty) == 1.0f);
    i2d_vec2 empty_com = i2d_body_get_world_center_of_mass(t->empty);
    I2D_CHECK(empty_com.x == -3.0f && empty_com.y == 8.0f);
    I2D_CHECK(i2d_body_get_mass(t->ground) == 0.0f);
    I2D_CHECK(i2d_body_get_mass(t->sensor_body) == 0.0f);
    I2D_CHECK(i2d_body_get_mass(t->mover) == 0.0f);
}

static void cover_shape_getters(const tour* t) {
    I2D_CHECK(i2d_shape_is_valid(t->circle));
    I2D_CHECK(I2D_ID_EQUALS(i2d_shape_get_body(t->circle), t->compound));
    I2D_CHECK(I2D_ID_EQUALS(i2d_shape_get_body(t->box), t->compound));
    I2D_CHECK(i2d_shape_get_type(t->circle) == I2D_SHAPE_CIRCLE);
    I2D_CHECK(i2d_shape_get_type(t->box) == I2D_SHAPE_POLYGON);
    i2d_circle c = i2d_shape_get_circle(t->circle);
    I2D_CHECK(c.center.x == 1.0f && c.center.y == 0.0f && c.radius == k_circle_radius);
    /* A box is a polygon: corners counter-clockwise from the lower left. */
    i2d_polygon p = i2d_shape_get_polygon(t->box);
    I2D_CHECK(p.count == 4 && p.radius == 0.0f);
    I2D_CHECK(p.vertices[0].x == -k_box_hw && p.vertices[0].y == -k_box_hh);
    I2D_CHECK(p.vertices[2].x == k_box_hw && p.vertices[2].y == k_box_hh);
    I2D_CHECK(p.normals[1].x == 1.0f && p.normals[1].y == 0.0f);
    I2D_CHECK(p.centroid.x == 0.0f && p.centroid.y == 0.0f);

    /* Tight world bounds: body (2, 3). */
    check_aabb_near(i2d_shape_get_aabb(t->circle), box(2.5f, 2.5f, 3.5f, 3.5f), 1e-6);
    check_aabb_near(i2d_shape_get_aabb(t->box), box(1.5f, 2.75f, 2.5f, 3.25f), 1e-6);
    check_aabb_near(i2d_shape_get_aabb(t->ground_box), box(-10.0f, -2.0f, 10.0f, 0.0f), 1e-6);

    I2D_CHECK(i2d_shape_get_density(t->circle) == k_circle_density);
    I2D_CHECK(i2d_shape_get_density(t->box) == k_box_density);
    I2D_CHECK(i2d_shape_get_friction(t->circle) == 0.3f);
    I2D_CHECK(i2d_shape_get_restitution(t->circle) == 0.2f);
    i2d_filter f = i2d_shape_get_filter(t->circle);
    I2D_CHECK(f.category_bits == 2 && f.mask_bits == 5 && f.group_index == -3);
    I2D_CHECK(!i2d_shape_is_sensor(t->circle));
    I2D_CHECK(i2d_shape_is_sensor(t->sensor));
    I2D_CHECK(i2d_shape_get_user_data(t->circle) == &k_circle_tag);
    I2D_CHECK(i2d_shape_get_user_data(t->box) == NULL);
}

static void cover_setters(const tour* t) {
    I2D_CHECK_STATUS(i2d_shape_set_friction(t->box, 0.9f), I2D_OK);
    I2D_CHECK(i2d_shape_get_friction(t->box) == 0.9f);
    I2D_CHECK_STATUS(i2d_shape_set_restitution(t->box, 0.5f), I2D_OK);
    I2D_CHECK(i2d_shape_get_restitution(t->box) == 0.5f);
    i2d_filter filter = {8, 0xf0, 7};
    I2D_CHECK_STATUS(i2d_shape_set_filter(t->box, filter), I2D_OK);
    i2d_filter got = i2d_shape_get_filter(t->box);
    I2D_CHECK(got.category_bits == 8 && got.mask_bits == 0xf0 && got.group_index == 7);
    I2D_CHECK_STATUS(i2d_shape_set_filter(t->box, i2d_default_filter()), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_set_user_data(t->box, &k_other_tag), I2D_OK);
    I2D_CHECK(i2d_shape_get_user_data(t->box) == &k_other_tag);
    I2D_CHECK_STATUS(i2d_body_set_user_data(t->empty, &k_other_tag), I2D_OK);
    I2D_CHECK(i2d_body_get_user_data(t->empty) == &k_other_tag);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(t->compound, 0.0f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(t->compound) == 0.0f);

    /* Teleport the compound to (4, 3): its shapes' bounds and centre of mass follow. */
    I2D_CHECK_STATUS(i2d_body_set_transform(t->compound, v2(4.0f, 3.0f), (i2d_rot){1.0f, 0.0f}), I2D_OK);
    i2d_transform xf = i2d_body_get_transform(t->compound);
    I2D_CHECK(xf.p.x == 4.0f && xf.p.y == 3.0f && xf.q.c == 1.0f && xf.q.s == 0.0f);
    check_aabb_near(i2d_shape_get_aabb(t->circle), box(4.5f, 2.5f, 5.5f, 3.5f), 1e-6);
    check_aabb_near(i2d_shape_get_aabb(t->box), box(3.5f, 2.75f, 4.5f, 3.25f), 1e-6);
    const double circle_mass = k_circle_density * k_pi * k_circle_radius * k_circle_radius;
    const double mass = circle_mass + k_box_density * 4.0 * k_box_hw * k_box_hh;
    I2D_CHECK_NEAR(i2d_body_get_world_center_of_mass(t->compound).x, 4.0 + circle_mass / mass, 1e-5);
}

/* Queries on the compound at (4, 3): circle spans x [4.5, 5.5], box x [3.5, 4.5]. */
static void cover_queries(const tour* t) {
    const i2d_query_filter all = i2d_default_query_filter();
    id_list found = {0, {{0}}};
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(t->world, box(5.2f, 2.9f, 5.3f, 3.1f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 1 && I2D_ID_EQUALS(found.ids[0], t->circle));

    found.count = 0;
    I2D_CHECK_STATUS(i2d_world_overlap_point(t->world, v2(4.0f, 3.0f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 1 && I2D_ID_EQUALS(found.ids[0], t->box));

    i2d_shape_id ids[4] = {{0}, {0}, {0}, {0}};
    int32_t n = i2d_world_overlap_aabb_ids(t->world, box(3.4f, 2.6f, 5.6f, 3.4f), all, ids, 4);
    I2D_CHECK(n == 2);
    I2D_CHECK(contains_id(ids, 2, t->circle) && contains_id(ids, 2, t->box));

    /* From (10, 3) leftwards: enters the circle at x = 5.5, i.e. fraction 0.45. */
    i2d_ray_result r = i2d_world_cast_ray_closest(t->world, v2(10.0f, 3.0f), v2(-10.0f, 0.0f), all);
    I2D_CHECK(r.hit);
    I2D_CHECK(I2D_ID_EQUALS(r.shape, t->circle));
    I2D_CHECK_NEAR(r.fraction, 0.45, 1e-6);
    I2D_CHECK_NEAR(r.point.x, 5.5, 1e-5);
    I2D_CHECK_NEAR(r.point.y, 3.0, 1e-5);
    I2D_CHECK_NEAR(r.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(r.normal.y, 0.0, 1e-6);
}

/* Velocities, impulses, forces and gravity, checked after one step against closed form. */
static void cover_motion(const tour* t) {
    const float dt = 1.0f / 60.0f;
    I2D_CHECK_STATUS(i2d_world_set_gravity(t->world, v2(0.0f, 0.0f)), I2D_OK);
    const float mass = i2d_body_get_mass(t->compound);

    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(t->compound, v2(1.0f, 2.0f)), I2D_OK);
    /* An impulse changes the velocity at once by impulse / mass. */
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(t->compound, v2(mass, 0.0f), v2(4.0f, 3.0f), true), I2D_OK);
    i2d_vec2 v = i2d_body_get_linear_velocity(t->compound);
    I2D_CHECK_NEAR(v.x, 2.0, 1e-5);
    I2D_CHECK_NEAR(v.y, 2.0, 1e-5);
    /* A force acts during the next step: dv = F / m * dt. */
    I2D_CHECK_STATUS(i2d_body_apply_force(t->compound, v2(0.0f, 6.0f * mass), v2(4.0f, 3.0f), true), I2D_OK);
    /* Static bodies accept forces and velocities but never move. */
    I2D_CHECK_STATUS(i2d_body_apply_force(t->ground, v2(1000.0f, 1000.0f), v2(0.0f, 0.0f), true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(t->ground, v2(3.0f, 0.0f)), I2D_OK);

    I2D_CHECK_STATUS(i2d_world_step(t->world, dt, 4), I2D_OK);

    v = i2d_body_get_linear_velocity(t->compound);
    I2D_CHECK_NEAR(v.x, 2.0, 1e-5);
    I2D_CHECK_NEAR(v.y, 2.0 + 6.0 * dt, 1e-5);
    i2d_vec2 p = i2d_body_get_position(t->compound);
    I2D_CHECK_NEAR(p.x, 4.0 + 2.0 * dt, 1e-5);
    I2D_CHECK(p.y >= 3.0f + 2.0f * dt - 1e-5f && p.y <= 3.0f + (2.0f + 6.0f * dt) * dt + 1e-5f);
    /* The kinematic body moves by its velocity; the empty body floats without gravity. */
    i2d_vec2 mover = i2d_body_get_position(t->mover);
    I2D_CHECK_NEAR(mover.x, dt, 1e-6);
    I2D_CHECK_NEAR(mover.y, 10.0, 1e-6);
    i2d_vec2 empty = i2d_body_get_position(t->empty);
    I2D_CHECK(empty.x == -3.0f && empty.y == 8.0f);
    i2d_vec2 ground = i2d_body_get_position(t->ground);
    I2D_CHECK(ground.x == 0.0f && ground.y == -1.0f);

    /* Forces are cleared after the step; gravity now acts on the dynamic bodies only. */
    I2D_CHECK_STATUS(i2d_world_set_gravity(t->world, v2(0.0f, -5.0f)), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_step(t->world, dt, 4), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(t->compound).y, 2.0 + 6.0 * dt - 5.0 * dt, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(t->empty).y, -5.0 * dt, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(t->mover).y, 0.0, 1e-9);
    I2D_CHECK(i2d_body_get_position(t->empty).y < 8.0f);
}

/* Destroying a shape updates the body's mass; destroying a body removes its shapes. */
static void cover_destruction(tour* t) {
    I2D_CHECK_STATUS(i2d_shape_destroy(t->box), I2D_OK);
    I2D_CHECK(!i2d_shape_is_valid(t->box));
    I2D_CHECK(i2d_body_get_shape_count(t->compound) == 1);
    const double circle_mass = k_circle_density * k_pi * k_circle_radius * k_circle_radius;
    I2D_CHECK_NEAR(i2d_body_get_mass(t->compound), circle_mass, 1e-5 * circle_mass);
    i2d_vec2 p = i2d_body_get_position(t->compound);
    i2d_vec2 com = i2d_body_get_world_center_of_mass(t->compound);
    I2D_CHECK_NEAR(com.x, p.x + 1.0, 1e-5); /* now the circle's centre */
    I2D_CHECK_NEAR(com.y, p.y, 1e-5);

    I2D_CHECK_STATUS(i2d_body_destroy(t->sensor_body), I2D_OK);
    I2D_CHECK(!i2d_body_is_valid(t->sensor_body));
    I2D_CHECK(!i2d_shape_is_valid(t->sensor));
    i2d_world_counters counters = i2d_world_get_counters(t->world);
    I2D_CHECK(counters.body_count == 4);
    I2D_CHECK(counters.shape_count == 2);

    I2D_CHECK_STATUS(i2d_world_destroy(t->world), I2D_OK);
    I2D_CHECK(!i2d_world_is_valid(t->world));
    t->world.bits = 0;
}

/* The pure collision functions against closed form. */
static void cover_collision(void) {
    /* Two unit circles 1.5 apart on x: overlap 0.5, surfaces at x = 1 and 0.5. */
    i2d_circle a = {{0.0f, 0.0f}, 1.0f};
    i2d_circle b = {{1.5f, 0.0f}, 1.0f};
    i2d_manifold m = i2d_collide_circles(a, b);
    I2D_CHECK(m.point_count == 1);
    I2D_CHECK_NEAR(m.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(m.normal.y, 0.0, 1e-6);
    I2D_CHECK_NEAR(m.points[0].penetration, 0.5, 1e-6);
    I2D_CHECK_NEAR(m.points[0].point.x, 0.75, 1e-6);
    I2D_CHECK_NEAR(m.points[0].point.y, 0.0, 1e-6);
    b.center = v2(2.0f, 0.0f); /* touching */
    m = i2d_collide_circles(a, b);
    I2D_CHECK(m.point_count == 1);
    I2D_CHECK_NEAR(m.points[0].penetration, 0.0, 1e-6);
    b.center = v2(2.5f, 0.0f); /* apart */
    I2D_CHECK(i2d_collide_circles(a, b).point_count == 0);
    m = i2d_collide_circles(a, a); /* same centres: normal (1, 0) */
    I2D_CHECK(m.point_count == 1);
    I2D_CHECK_NEAR(m.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(m.points[0].penetration, 2.0, 1e-6);

    /* Boxes overlapping 0.5 on x and 1 on y: resolved along x, two points on the edge
     * x = (2 + 1.5) / 2 at the overlap's y range [0.5, 1.5]. */
    i2d_manifold mb = i2d_collide_aabbs(box(0.0f, 0.0f, 2.0f, 2.0f), box(1.5f, 0.5f, 3.5f, 1.5f));
    I2D_CHECK(mb.point_count == 2);
    I2D_CHECK_NEAR(mb.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(mb.normal.y, 0.0, 1e-6);
    for (int i = 0; i < mb.point_count && i < 2; ++i) {
        I2D_CHECK_NEAR(mb.points[i].penetration, 0.5, 1e-6);
        I2D_CHECK_NEAR(mb.points[i].point.x, 1.75, 1e-6);
    }
    I2D_CHECK_NEAR(fmin(mb.points[0].point.y, mb.points[1].point.y), 0.5, 1e-6);
    I2D_CHECK_NEAR(fmax(mb.points[0].point.y, mb.points[1].point.y), 1.5, 1e-6);
    I2D_CHECK(mb.points[0].id != mb.points[1].id);
    I2D_CHECK(i2d_collide_aabbs(box(0.0f, 0.0f, 1.0f, 1.0f), box(2.0f, 0.0f, 3.0f, 1.0f)).point_count == 0);

    /* Box [0, 2]^2 and a circle of radius 1.5 centred at (3, 1): 0.5 deep through x = 2. */
    i2d_circle c = {{3.0f, 1.0f}, 1.5f};
    i2d_manifold mc = i2d_collide_aabb_circle(box(0.0f, 0.0f, 2.0f, 2.0f), c);
    I2D_CHECK(mc.point_count == 1);
    I2D_CHECK_NEAR(mc.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(mc.normal.y, 0.0, 1e-6);
    I2D_CHECK_NEAR(mc.points[0].penetration, 0.5, 1e-6);
    I2D_CHECK_NEAR(mc.points[0].point.x, 1.75, 1e-6);
    I2D_CHECK_NEAR(mc.points[0].point.y, 1.0, 1e-6);
    /* A centre inside the box leaves through the nearest face (x = 2). */
    c.center = v2(1.8f, 1.0f);
    c.radius = 0.5f;
    mc = i2d_collide_aabb_circle(box(0.0f, 0.0f, 2.0f, 2.0f), c);
    I2D_CHECK(mc.point_count == 1);
    I2D_CHECK_NEAR(mc.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(mc.points[0].penetration, 0.7, 1e-6);
    c.center = v2(4.0f, 1.0f);
    c.radius = 1.0f;
    I2D_CHECK(i2d_collide_aabb_circle(box(0.0f, 0.0f, 2.0f, 2.0f), c).point_count == 0);
}

I2D_TEST(api_world_coverage) {
    cover_library_calls();
    cover_defaults();
    cover_collision();
    tour t;
    if (tour_build(&t)) {
        cover_world_getters(&t);
        cover_body_getters(&t);
        cover_mass(&t);
        cover_shape_getters(&t);
        cover_setters(&t);
        cover_queries(&t);
        cover_motion(&t);
        cover_destruction(&t);
    } else {
        I2D_CHECK(!"tour_build");
    }
    if (!I2D_IS_NULL(t.world)) {
        i2d_world_destroy(t.world);
    }
}

/* Mass rules on their own: zero-density shapes leave a dynamic body at 1 kg with its
 * centre of mass at the body origin; static and kinematic bodies with shapes weigh 0. */
static void run_mass_rules(i2d_world_id world) {
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position = v2(1.0f, 2.0f);
    i2d_body_id body = i2d_body_create(world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    shape_def.density = 0.0f;
    i2d_circle circle = {{3.0f, 0.0f}, 1.0f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(body, &shape_def, &circle)));
    I2D_CHECK(i2d_body_get_mass(body) == 1.0f);
    i2d_vec2 com = i2d_body_get_world_center_of_mass(body);
    I2D_CHECK(com.x == 1.0f && com.y == 2.0f);

    /* A second shape with density: mass and centre come from it alone. */
    shape_def.density = 4.0f;
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(body, &shape_def, 1.0f, 0.5f)));
    I2D_CHECK_NEAR(i2d_body_get_mass(body), 4.0 * 2.0 * 1.0, 1e-5);
    com = i2d_body_get_world_center_of_mass(body);
    I2D_CHECK_NEAR(com.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(com.y, 2.0, 1e-6);

    shape_def.density = 5.0f;
    static const i2d_body_type massless[] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC};
    for (int i = 0; i < 2; ++i) {
        def.type = massless[i];
        i2d_body_id b = i2d_body_create(world, &def);
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(b, &shape_def, &circle)));
        I2D_CHECK(i2d_body_get_mass(b) == 0.0f);
    }
}

I2D_TEST(api_world_mass_rules) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    run_mass_rules(world);
    i2d_world_destroy(world);
}

/* ---- Struct layout ---------------------------------------------------------------- */

/* Records one sizeof/offsetof against its value on x86-64 (System V, LP64), so that an
 * accidental layout change of a public struct fails here before it breaks bindings. */
#define CHECK_LAYOUT(expr, expected)                                                                   \
    do {                                                                                               \
        size_t layout_actual_ = (expr);                                                                \
        if (layout_actual_ != (size_t)(expected)) {                                                    \
            ++i2d_check_failures;                                                                      \
            fprintf(stderr, "%s:%d: %s = %zu, recorded %d\n", __FILE__, __LINE__, #expr, layout_actual_, \
                    (int)(expected));                                                                  \
        }                                                                                              \
    } while (0)

I2D_TEST(api_world_struct_layout) {
#if defined(__x86_64__) || defined(_M_X64)
    CHECK_LAYOUT(sizeof(i2d_vec2), 8);
    CHECK_LAYOUT(offsetof(i2d_vec2, x), 0);
    CHECK_LAYOUT(offsetof(i2d_vec2, y), 4);

    CHECK_LAYOUT(sizeof(i2d_rot), 8);
    CHECK_LAYOUT(offsetof(i2d_rot, c), 0);
    CHECK_LAYOUT(offsetof(i2d_rot, s), 4);

    CHECK_LAYOUT(sizeof(i2d_transform), 16);
    CHECK_LAYOUT(offsetof(i2d_transform, p), 0);
    CHECK_LAYOUT(offsetof(i2d_transform, q), 8);

    CHECK_LAYOUT(sizeof(i2d_aabb), 16);
    CHECK_LAYOUT(offsetof(i2d_aabb, min), 0);
    CHECK_LAYOUT(offsetof(i2d_aabb, max), 8);

    CHECK_LAYOUT(sizeof(i2d_world_id), 8);
    CHECK_LAYOUT(sizeof(i2d_body_id), 8);
    CHECK_LAYOUT(sizeof(i2d_shape_id), 8);
    CHECK_LAYOUT(offsetof(i2d_world_id, bits), 0);
    CHECK_LAYOUT(offsetof(i2d_body_id, bits), 0);
    CHECK_LAYOUT(offsetof(i2d_shape_id, bits), 0);

    CHECK_LAYOUT(sizeof(i2d_filter), 24);
    CHECK_LAYOUT(offsetof(i2d_filter, category_bits), 0);
    CHECK_LAYOUT(offsetof(i2d_filter, mask_bits), 8);
    CHECK_LAYOUT(offsetof(i2d_filter, group_index), 16);

    CHECK_LAYOUT(sizeof(i2d_query_filter), 16);
    CHECK_LAYOUT(offsetof(i2d_query_filter, category_bits), 0);
    CHECK_LAYOUT(offsetof(i2d_query_filter, mask_bits), 8);

    CHECK_LAYOUT(sizeof(i2d_circle), 12);
    CHECK_LAYOUT(offsetof(i2d_circle, center), 0);
    CHECK_LAYOUT(offsetof(i2d_circle, radius), 8);

    CHECK_LAYOUT(sizeof(i2d_manifold_point), 16);
    CHECK_LAYOUT(offsetof(i2d_manifold_point, point), 0);
    CHECK_LAYOUT(offsetof(i2d_manifold_point, penetration), 8);
    CHECK_LAYOUT(offsetof(i2d_manifold_point, id), 12);

    CHECK_LAYOUT(sizeof(i2d_manifold), 44);
    CHECK_LAYOUT(offsetof(i2d_manifold, normal), 0);
    CHECK_LAYOUT(offsetof(i2d_manifold, point_count), 8);
    CHECK_LAYOUT(offsetof(i2d_manifold, points), 12);

    CHECK_LAYOUT(sizeof(i2d_ray_result), 32);
    CHECK_LAYOUT(offsetof(i2d_ray_result, shape), 0);
    CHECK_LAYOUT(offsetof(i2d_ray_result, point), 8);
    CHECK_LAYOUT(offsetof(i2d_ray_result, normal), 16);
    CHECK_LAYOUT(offsetof(i2d_ray_result, fraction), 24);
    CHECK_LAYOUT(offsetof(i2d_ray_result, hit), 28);

    CHECK_LAYOUT(sizeof(i2d_world_counters), 28);
    CHECK_LAYOUT(offsetof(i2d_world_counters, body_count), 0);
    CHECK_LAYOUT(offsetof(i2d_world_counters, shape_count), 4);
    CHECK_LAYOUT(offsetof(i2d_world_counters, contact_count), 8);
    CHECK_LAYOUT(offsetof(i2d_world_counters, pair_count), 12);
    CHECK_LAYOUT(offsetof(i2d_world_counters, static_tree_height), 16);
    CHECK_LAYOUT(offsetof(i2d_world_counters, kinematic_tree_height), 20);
    CHECK_LAYOUT(offsetof(i2d_world_counters, dynamic_tree_height), 24);

    CHECK_LAYOUT(sizeof(i2d_world_def), 36);
    CHECK_LAYOUT(offsetof(i2d_world_def, gravity), 0);
    CHECK_LAYOUT(offsetof(i2d_world_def, contact_slop), 8);
    CHECK_LAYOUT(offsetof(i2d_world_def, contact_correction_percent), 12);
    CHECK_LAYOUT(offsetof(i2d_world_def, restitution_threshold), 16);
    CHECK_LAYOUT(offsetof(i2d_world_def, maximum_linear_speed), 20);
    CHECK_LAYOUT(offsetof(i2d_world_def, velocity_iterations), 24);
    CHECK_LAYOUT(offsetof(i2d_world_def, enable_sleep), 28);
    CHECK_LAYOUT(offsetof(i2d_world_def, internal_cookie), 32);

    CHECK_LAYOUT(sizeof(i2d_body_def), 64);
    CHECK_LAYOUT(offsetof(i2d_body_def, type), 0);
    CHECK_LAYOUT(offsetof(i2d_body_def, position), 4);
    CHECK_LAYOUT(offsetof(i2d_body_def, rotation), 12);
    CHECK_LAYOUT(offsetof(i2d_body_def, linear_velocity), 20);
    CHECK_LAYOUT(offsetof(i2d_body_def, angular_velocity), 28);
    CHECK_LAYOUT(offsetof(i2d_body_def, linear_damping), 32);
    CHECK_LAYOUT(offsetof(i2d_body_def, angular_damping), 36);
    CHECK_LAYOUT(offsetof(i2d_body_def, gravity_scale), 40);
    CHECK_LAYOUT(offsetof(i2d_body_def, fixed_rotation), 44);
    CHECK_LAYOUT(offsetof(i2d_body_def, enable_sleep), 45);
    CHECK_LAYOUT(offsetof(i2d_body_def, is_bullet), 46);
    CHECK_LAYOUT(offsetof(i2d_body_def, user_data), 48);
    CHECK_LAYOUT(offsetof(i2d_body_def, internal_cookie), 56);

    CHECK_LAYOUT(sizeof(i2d_shape_def), 56);
    CHECK_LAYOUT(offsetof(i2d_shape_def, density), 0);
    CHECK_LAYOUT(offsetof(i2d_shape_def, friction), 4);
    CHECK_LAYOUT(offsetof(i2d_shape_def, restitution), 8);
    CHECK_LAYOUT(offsetof(i2d_shape_def, is_sensor), 12);
    CHECK_LAYOUT(offsetof(i2d_shape_def, enable_contact_events), 13);
    CHECK_LAYOUT(offsetof(i2d_shape_def, enable_sensor_events), 14);
    CHECK_LAYOUT(offsetof(i2d_shape_def, filter), 16);
    CHECK_LAYOUT(offsetof(i2d_shape_def, user_data), 40);
    CHECK_LAYOUT(offsetof(i2d_shape_def, internal_cookie), 48);

    /* Events: ids are 8 bytes; the arrays are a pointer and an int32 count each. */
    CHECK_LAYOUT(sizeof(i2d_contact_begin_event), 16);
    CHECK_LAYOUT(offsetof(i2d_contact_begin_event, shape_a), 0);
    CHECK_LAYOUT(offsetof(i2d_contact_begin_event, shape_b), 8);

    CHECK_LAYOUT(sizeof(i2d_contact_end_event), 16);
    CHECK_LAYOUT(offsetof(i2d_contact_end_event, shape_a), 0);
    CHECK_LAYOUT(offsetof(i2d_contact_end_event, shape_b), 8);

    CHECK_LAYOUT(sizeof(i2d_contact_events), 32);
    CHECK_LAYOUT(offsetof(i2d_contact_events, begin_events), 0);
    CHECK_LAYOUT(offsetof(i2d_contact_events, begin_count), 8);
    CHECK_LAYOUT(offsetof(i2d_contact_events, end_events), 16);
    CHECK_LAYOUT(offsetof(i2d_contact_events, end_count), 24);

    CHECK_LAYOUT(sizeof(i2d_sensor_begin_event), 16);
    CHECK_LAYOUT(offsetof(i2d_sensor_begin_event, sensor_shape), 0);
    CHECK_LAYOUT(offsetof(i2d_sensor_begin_event, visitor_shape), 8);

    CHECK_LAYOUT(sizeof(i2d_sensor_end_event), 16);
    CHECK_LAYOUT(offsetof(i2d_sensor_end_event, sensor_shape), 0);
    CHECK_LAYOUT(offsetof(i2d_sensor_end_event, visitor_shape), 8);

    CHECK_LAYOUT(sizeof(i2d_sensor_events), 32);
    CHECK_LAYOUT(offsetof(i2d_sensor_events, begin_events), 0);
    CHECK_LAYOUT(offsetof(i2d_sensor_events, begin_count), 8);
    CHECK_LAYOUT(offsetof(i2d_sensor_events, end_events), 16);
    CHECK_LAYOUT(offsetof(i2d_sensor_events, end_count), 24);

    CHECK_LAYOUT(sizeof(i2d_body_move_event), 40);
    CHECK_LAYOUT(offsetof(i2d_body_move_event, transform), 0);
    CHECK_LAYOUT(offsetof(i2d_body_move_event, body), 16);
    CHECK_LAYOUT(offsetof(i2d_body_move_event, user_data), 24);
    CHECK_LAYOUT(offsetof(i2d_body_move_event, fell_asleep), 32);

    CHECK_LAYOUT(sizeof(i2d_body_events), 16);
    CHECK_LAYOUT(offsetof(i2d_body_events, move_events), 0);
    CHECK_LAYOUT(offsetof(i2d_body_events, move_count), 8);

    /* Enums cross the FFI as 32-bit integers. */
    CHECK_LAYOUT(sizeof(i2d_status), 4);
    CHECK_LAYOUT(sizeof(i2d_body_type), 4);
    CHECK_LAYOUT(sizeof(i2d_shape_type), 4);
    CHECK_LAYOUT(sizeof(bool), 1);
#else
    /* Elsewhere only the ids' size is fixed by the contract. */
    CHECK_LAYOUT(sizeof(i2d_body_id), 8);
#endif
}
