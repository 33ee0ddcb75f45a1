/* SPDX-License-Identifier: MIT */
/* C API tour: the README's hello world, a call to every public function, and the frozen struct layouts. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

static const double k_pi = 3.14159265358979323846;

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

typedef struct ray_hits {
    int count;
    float fractions[4];
    i2d_shape_id shapes[4];
} ray_hits;

/* Records each hit and lets the ray go on unclipped. */
static float collect_hit(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    ray_hits* hits = (ray_hits*)context;
    (void)point;
    (void)normal;
    if (hits->count < 4) {
        hits->shapes[hits->count] = shape;
        hits->fractions[hits->count] = fraction;
    }
    ++hits->count;
    return 1.0f;
}

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
    I2D_CHECK(w.contact_hertz == 60.0f);
    I2D_CHECK(w.contact_damping_ratio == 10.0f);
    I2D_CHECK(w.contact_push_max_speed == 3.0f);
    I2D_CHECK(w.restitution_threshold == 1.0f);
    I2D_CHECK(w.maximum_linear_speed == 400.0f);
    I2D_CHECK(w.friction_mixing == I2D_MIX_GEOMETRIC_MEAN);
    I2D_CHECK(w.restitution_mixing == I2D_MIX_MINIMUM);
    I2D_CHECK(w.enable_sleep);
    I2D_CHECK_NEAR(w.sleep_speed_threshold, 0.05, 1e-9);
    I2D_CHECK(w.time_to_sleep == 0.5f);
    I2D_CHECK(w.enable_continuous);
    I2D_CHECK(w.enable_impact_chains);
    I2D_CHECK(w.hit_event_threshold == 1.0f);
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
    I2D_CHECK(!s.is_sensor && s.enable_contact_events && !s.enable_hit_events);
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

    /* Rotational inertia about the centre of mass: each shape's own (m r^2 / 2 for the
     * circle, m (w^2 + h^2) / 12 for the box) moved by the parallel axis theorem. */
    const double com_x = circle_mass * 1.0 / mass;
    const double inertia = circle_mass * k_circle_radius * k_circle_radius / 2.0 +
                           circle_mass * (1.0 - com_x) * (1.0 - com_x) +
                           box_mass * (4.0 * k_box_hw * k_box_hw + 4.0 * k_box_hh * k_box_hh) / 12.0 +
                           box_mass * com_x * com_x;
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(t->compound), inertia, 1e-5 * inertia);
    i2d_vec2 local_com = i2d_body_get_local_center_of_mass(t->compound);
    I2D_CHECK_NEAR(local_com.x, com_x, 1e-6);
    I2D_CHECK_NEAR(local_com.y, 0.0, 1e-6);
    /* Static and kinematic bodies never turn. */
    I2D_CHECK(i2d_body_get_rotational_inertia(t->ground) == 0.0f);
    I2D_CHECK(i2d_body_get_rotational_inertia(t->mover) == 0.0f);

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

    /* The same ray through a callback that lets it go on: the circle at 0.45, then the
     * box at x = 4.5, fraction 0.55. */
    ray_hits hits = {0, {0.0f, 0.0f, 0.0f, 0.0f}, {{0}, {0}, {0}, {0}}};
    I2D_CHECK_STATUS(i2d_world_cast_ray(t->world, v2(10.0f, 3.0f), v2(-10.0f, 0.0f), all, collect_hit, &hits), I2D_OK);
    I2D_CHECK(hits.count == 2);
    for (int i = 0; i < hits.count && i < 4; ++i) {
        bool is_circle = I2D_ID_EQUALS(hits.shapes[i], t->circle);
        I2D_CHECK(is_circle || I2D_ID_EQUALS(hits.shapes[i], t->box));
        I2D_CHECK_NEAR(hits.fractions[i], is_circle ? 0.45 : 0.55, 1e-6);
    }

    /* Rebuilding the static tree changes no answer. */
    I2D_CHECK_STATUS(i2d_world_rebuild_static_tree(t->world), I2D_OK);
    found.count = 0;
    I2D_CHECK_STATUS(i2d_world_overlap_point(t->world, v2(3.0f, -1.0f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 1 && I2D_ID_EQUALS(found.ids[0], t->ground_box));
}

/* Velocities, impulses, forces and gravity, checked after one step against closed form.
 * Impulses and forces act at the centre of mass here, so the compound does not turn
 * (off-centre ones are covered by cover_turning). */
static void cover_motion(const tour* t) {
    const float dt = 1.0f / 60.0f;
    I2D_CHECK_STATUS(i2d_world_set_gravity(t->world, v2(0.0f, 0.0f)), I2D_OK);
    const float mass = i2d_body_get_mass(t->compound);
    const i2d_vec2 com = i2d_body_get_world_center_of_mass(t->compound);

    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(t->compound, v2(1.0f, 2.0f)), I2D_OK);
    /* An impulse changes the velocity at once by impulse / mass. */
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(t->compound, v2(mass, 0.0f), com, true), I2D_OK);
    i2d_vec2 v = i2d_body_get_linear_velocity(t->compound);
    I2D_CHECK_NEAR(v.x, 2.0, 1e-5);
    I2D_CHECK_NEAR(v.y, 2.0, 1e-5);
    I2D_CHECK(i2d_body_get_angular_velocity(t->compound) == 0.0f);
    /* A force acts during the next step: dv = F / m * dt. */
    I2D_CHECK_STATUS(i2d_body_apply_force(t->compound, v2(0.0f, 6.0f * mass), com, true), I2D_OK);
    /* Static bodies accept forces and velocities but never move. */
    I2D_CHECK_STATUS(i2d_body_apply_force(t->ground, v2(1000.0f, 1000.0f), v2(0.0f, 0.0f), true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(t->ground, v2(3.0f, 0.0f)), I2D_OK);

    I2D_CHECK_STATUS(i2d_world_step(t->world, dt, 4), I2D_OK);

    /* Events of the step: the compound and the mover moved (the empty body floats still
     * without gravity); nothing touched. */
    i2d_body_events moves = i2d_world_get_body_events(t->world);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(moves.move_count == 2);
    for (int i = 0; i < moves.move_count && i < 2; ++i) {
        const i2d_body_move_event* e = &moves.move_events[i];
        I2D_CHECK(I2D_ID_EQUALS(e->body, t->compound) || I2D_ID_EQUALS(e->body, t->mover));
        i2d_transform now = i2d_body_get_transform(e->body);
        I2D_CHECK(e->transform.p.x == now.p.x && e->transform.p.y == now.p.y && e->transform.q.c == now.q.c &&
                  e->transform.q.s == now.q.s);
        I2D_CHECK(e->user_data == i2d_body_get_user_data(e->body) && !e->fell_asleep);
    }
    i2d_contact_events contacts = i2d_world_get_contact_events(t->world);
    I2D_CHECK(i2d_last_status() == I2D_OK && contacts.begin_count == 0 && contacts.end_count == 0);
    i2d_sensor_events sensors = i2d_world_get_sensor_events(t->world);
    I2D_CHECK(i2d_last_status() == I2D_OK && sensors.begin_count == 0 && sensors.end_count == 0);

    v = i2d_body_get_linear_velocity(t->compound);
    I2D_CHECK_NEAR(v.x, 2.0, 1e-5);
    I2D_CHECK_NEAR(v.y, 2.0 + 6.0 * dt, 1e-5);
    i2d_vec2 p = i2d_body_get_position(t->compound);
    I2D_CHECK_NEAR(p.x, 4.0 + 2.0 * dt, 1e-5);
    I2D_CHECK(p.y >= 3.0f + 2.0f * dt - 1e-5f && p.y <= 3.0f + (2.0f + 6.0f * dt) * dt + 1e-5f);
    /* No torque about the centre of mass: no spin, no turn. */
    I2D_CHECK(i2d_body_get_angular_velocity(t->compound) == 0.0f);
    i2d_rot q = i2d_body_get_rotation(t->compound);
    I2D_CHECK(q.c == 1.0f && q.s == 0.0f);
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

/* ---- Rotation: rotations, turning bodies, torques and angular impulses ------------- */

static double angle_of(i2d_rot q) { return atan2((double)q.s, (double)q.c); }

/* i2d_make_rot and i2d_rot_get_angle against cos, sin and atan2. */
static void cover_rotations(void) {
    i2d_rot q = i2d_make_rot(0.3f);
    I2D_CHECK_NEAR(q.c, cos(0.3), 1e-6);
    I2D_CHECK_NEAR(q.s, sin(0.3), 1e-6);
    I2D_CHECK_NEAR(i2d_rot_get_angle(q), 0.3, 1e-6);
    q = i2d_make_rot(0.0f);
    I2D_CHECK(q.c == 1.0f && q.s == 0.0f);
    q = i2d_make_rot(-2.0f);
    I2D_CHECK_NEAR(q.c, cos(-2.0), 1e-6);
    I2D_CHECK_NEAR(q.s, sin(-2.0), 1e-6);
    I2D_CHECK_NEAR(i2d_rot_get_angle(q), -2.0, 1e-6);
    /* Angles outside (-pi, pi] come back wrapped into it. */
    I2D_CHECK_NEAR(i2d_rot_get_angle(i2d_make_rot(4.0f)), 4.0 - 2.0 * k_pi, 1e-5);
    /* A half turn is +pi, the top of the range. */
    i2d_rot half = {-1.0f, 0.0f};
    I2D_CHECK_NEAR(i2d_rot_get_angle(half), k_pi, 1e-6);
    i2d_rot quarter = {0.0f, 1.0f};
    I2D_CHECK_NEAR(i2d_rot_get_angle(quarter), 0.5 * k_pi, 1e-6);
    I2D_CHECK(i2d_last_status() == I2D_OK);
}

/* The world point of local (x, y) on a body at p turned by angle a, in closed form. */
static i2d_vec2 rotate_about(i2d_vec2 p, double a, double x, double y) {
    return v2((float)(p.x + cos(a) * x - sin(a) * y), (float)(p.y + sin(a) * x + cos(a) * y));
}

/* A box body turned by 0.5 rad: frames, inertia, point velocities, and the effect of
 * every way of making it spin, against closed form. Zero gravity. */
static void run_turning_body(i2d_world_id world) {
    const float dt = 1.0f / 60.0f;
    const double angle = 0.5;
    /* Box 2 x 1 m, density 1.5: m = 3 kg, I = m (w^2 + h^2) / 12 = 1.25 kg m^2, centred
     * at (0.5, 0) in the body frame. */
    const double m = 3.0, inertia = 3.0 * (4.0 + 1.0) / 12.0;
    const i2d_vec2 origin = v2(2.0f, 3.0f);
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position = origin;
    def.rotation = i2d_make_rot((float)angle);
    i2d_body_id body = i2d_body_create(world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    shape_def.density = 1.5f;
    i2d_rot identity = {1.0f, 0.0f};
    i2d_shape_id box_shape = i2d_shape_create_offset_box(body, &shape_def, 1.0f, 0.5f, v2(0.5f, 0.0f), identity);
    I2D_REQUIRE(!I2D_IS_NULL(box_shape));

    i2d_rot q = i2d_body_get_rotation(body);
    I2D_CHECK_NEAR(q.c, cos(angle), 1e-6);
    I2D_CHECK_NEAR(q.s, sin(angle), 1e-6);
    i2d_transform xf = i2d_body_get_transform(body);
    I2D_CHECK(xf.p.x == origin.x && xf.p.y == origin.y && xf.q.c == q.c && xf.q.s == q.s);
    I2D_CHECK_NEAR(i2d_body_get_mass(body), m, 1e-5 * m);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(body), inertia, 1e-5 * inertia);
    i2d_vec2 local_com = i2d_body_get_local_center_of_mass(body);
    I2D_CHECK_NEAR(local_com.x, 0.5, 1e-6);
    I2D_CHECK_NEAR(local_com.y, 0.0, 1e-6);
    i2d_vec2 com = i2d_body_get_world_center_of_mass(body);
    i2d_vec2 expected_com = rotate_about(origin, angle, 0.5, 0.0);
    I2D_CHECK_NEAR(com.x, expected_com.x, 1e-6);
    I2D_CHECK_NEAR(com.y, expected_com.y, 1e-6);
    /* The box turns with the body: its bounds are those of the turned corners. */
    i2d_aabb bounds = i2d_shape_get_aabb(box_shape);
    double ex = cos(angle) * 1.0 + sin(angle) * 0.5, ey = sin(angle) * 1.0 + cos(angle) * 0.5;
    check_aabb_near(bounds, box((float)(com.x - ex), (float)(com.y - ey), (float)(com.x + ex), (float)(com.y + ey)),
                    1e-5);

    /* Body frame and world frame. */
    i2d_vec2 w = i2d_body_get_world_point(body, v2(1.0f, 2.0f));
    i2d_vec2 expected = rotate_about(origin, angle, 1.0, 2.0);
    I2D_CHECK_NEAR(w.x, expected.x, 1e-5);
    I2D_CHECK_NEAR(w.y, expected.y, 1e-5);
    i2d_vec2 back = i2d_body_get_local_point(body, w);
    I2D_CHECK_NEAR(back.x, 1.0, 1e-5);
    I2D_CHECK_NEAR(back.y, 2.0, 1e-5);
    i2d_vec2 l = i2d_body_get_local_point(body, v2(0.0f, 0.0f));
    w = i2d_body_get_world_point(body, l);
    I2D_CHECK_NEAR(w.x, 0.0, 1e-5);
    I2D_CHECK_NEAR(w.y, 0.0, 1e-5);
    I2D_CHECK_NEAR(l.x * l.x + l.y * l.y, 13.0, 1e-4); /* |(0, 0) - (2, 3)|^2: a rigid motion */

    /* Velocity of the material at a point: v + w x (point - centre of mass). */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(body, v2(1.0f, 0.0f)), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(body, 2.0f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 2.0f);
    i2d_vec2 at = v2(com.x + 1.0f, com.y + 3.0f);
    i2d_vec2 pv = i2d_body_get_world_point_velocity(body, at);
    I2D_CHECK_NEAR(pv.x, 1.0 - 2.0 * 3.0, 1e-5);
    I2D_CHECK_NEAR(pv.y, 0.0 + 2.0 * 1.0, 1e-5);
    pv = i2d_body_get_world_point_velocity(body, com);
    I2D_CHECK_NEAR(pv.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(pv.y, 0.0, 1e-6);

    /* Impulses act at once: an angular impulse J changes w by J / I... */
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(body, 0.5f, true), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), 2.0 + 0.5 / inertia, 1e-5);
    /* ...and a linear impulse at r from the centre changes v by J / m and w by r x J / I. */
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(body, v2(0.0f, 3.0f), v2(com.x + 1.0f, com.y), true), I2D_OK);
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    I2D_CHECK_NEAR(v.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(v.y, 3.0 / m, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), 2.0 + 0.5 / inertia + 3.0 / inertia, 1e-5);

    /* A torque T acts during the next step: w = T / I * dt; the body turns by
     * h * (w_1 + ... + w_4) over the four substeps (w_k = k h T / I), nothing else moves. */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(body, v2(0.0f, 0.0f)), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(body, 0.0f), I2D_OK);
    const double torque = 2.5, alpha = torque / inertia, h = dt / 4.0;
    I2D_CHECK_STATUS(i2d_body_apply_torque(body, (float)torque, true), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 0.0f); /* not before the step */
    I2D_CHECK_STATUS(i2d_world_step(world, dt, 4), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), alpha * dt, 1e-6);
    I2D_CHECK_NEAR(angle_of(i2d_body_get_rotation(body)), angle + alpha * h * h * 10.0, 1e-6);
    i2d_vec2 com_after = i2d_body_get_world_center_of_mass(body);
    I2D_CHECK_NEAR(com_after.x, com.x, 1e-6);
    I2D_CHECK_NEAR(com_after.y, com.y, 1e-6);
    v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == 0.0f && v.y == 0.0f);

    /* A force at the centre pushes without turning; a force F at r from the centre adds
     * the torque r x F: here (-1, 0) x (0, 3) = -3 N m. */
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(body, 0.0f), I2D_OK);
    com = i2d_body_get_world_center_of_mass(body);
    I2D_CHECK_STATUS(i2d_body_apply_force_to_center(body, v2(6.0f, 0.0f), true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_force(body, v2(0.0f, 3.0f), v2(com.x - 1.0f, com.y), true), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_step(world, dt, 4), I2D_OK);
    v = i2d_body_get_linear_velocity(body);
    I2D_CHECK_NEAR(v.x, 6.0 / m * dt, 1e-6);
    I2D_CHECK_NEAR(v.y, 3.0 / m * dt, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), -3.0 / inertia * dt, 1e-6);
    /* Forces and torques are cleared after the step: the next one coasts. */
    const float w_coast = i2d_body_get_angular_velocity(body);
    I2D_CHECK_STATUS(i2d_world_step(world, dt, 4), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), w_coast, 1e-7);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(body).x, 6.0 / m * dt, 1e-6);
}

/* Bodies that do not turn: static (ignores spins), fixed rotation (ignores spins and
 * torques), and kinematic (turns at the angular velocity it is given). */
static void run_non_turning_bodies(i2d_world_id world) {
    const float dt = 1.0f / 60.0f;
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_body_def def = i2d_default_body_def();
    def.rotation.c = -1.0f; /* a half turn, exactly */
    def.rotation.s = 0.0f;
    i2d_body_id ground = i2d_body_create(world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(ground, &shape_def, 1.0f, 1.0f)));
    i2d_rot q = i2d_body_get_rotation(ground);
    I2D_CHECK(q.c == -1.0f && q.s == 0.0f);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(ground, 5.0f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(ground) == 0.0f);
    I2D_CHECK_STATUS(i2d_body_apply_torque(ground, 10.0f, true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(ground, 10.0f, true), I2D_OK);
    I2D_CHECK(i2d_body_get_rotational_inertia(ground) == 0.0f);

    def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position = v2(10.0f, 0.0f);
    def.fixed_rotation = true;
    i2d_body_id fixed = i2d_body_create(world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(fixed, &shape_def, 1.0f, 0.5f)));
    I2D_CHECK_NEAR(i2d_body_get_mass(fixed), 2.0, 1e-6);
    I2D_CHECK(i2d_body_get_rotational_inertia(fixed) == 0.0f);
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(fixed, 3.0f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(fixed) == 0.0f);
    I2D_CHECK_STATUS(i2d_body_apply_torque(fixed, 10.0f, true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(fixed, 10.0f, true), I2D_OK);
    /* An off-centre impulse moves it by J / m but does not turn it. */
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(fixed, v2(0.0f, 2.0f), v2(11.0f, 0.0f), true), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(fixed).y, 1.0, 1e-6);
    I2D_CHECK(i2d_body_get_angular_velocity(fixed) == 0.0f);

    def = i2d_default_body_def();
    def.type = I2D_BODY_KINEMATIC;
    def.position = v2(-10.0f, 0.0f);
    def.angular_velocity = 1.5f;
    i2d_body_id spinner = i2d_body_create(world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(spinner, &shape_def, 1.0f, 0.5f)));
    I2D_CHECK(i2d_body_get_angular_velocity(spinner) == 1.5f);
    I2D_CHECK(i2d_body_get_rotational_inertia(spinner) == 0.0f);

    I2D_CHECK_STATUS(i2d_world_step(world, dt, 4), I2D_OK);
    q = i2d_body_get_rotation(ground);
    I2D_CHECK(q.c == -1.0f && q.s == 0.0f);
    q = i2d_body_get_rotation(fixed);
    I2D_CHECK(q.c == 1.0f && q.s == 0.0f);
    I2D_CHECK(i2d_body_get_angular_velocity(fixed) == 0.0f);
    I2D_CHECK_NEAR(angle_of(i2d_body_get_rotation(spinner)), 1.5 * dt, 1e-6);
    I2D_CHECK(i2d_body_get_angular_velocity(spinner) == 1.5f);
    /* A kinematic body takes a new spin at once. */
    I2D_CHECK_STATUS(i2d_body_set_angular_velocity(spinner, -0.5f), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(spinner) == -0.5f);
}

static void run_turning_bodies(i2d_world_id world) {
    run_turning_body(world);
    run_non_turning_bodies(world);
}

static void cover_turning(void) { run_in_world(0.0f, run_turning_bodies); }

/* ---- Shapes beyond circles and boxes ------------------------------------------------- */

/* Capsule of half length hl (between the centres) and radius r, density 1: a rectangle
 * plus two half discs; the half discs' centroids lie 4 r / (3 pi) beyond the centres. */
static double capsule_mass(double hl, double r) { return 4.0 * hl * r + k_pi * r * r; }
static double capsule_inertia(double hl, double r) {
    const double rect = 4.0 * hl * r, disc = k_pi * r * r, lc = 4.0 * r / (3.0 * k_pi);
    return rect * (4.0 * hl * hl + 4.0 * r * r) / 12.0 + disc * (0.5 * r * r + hl * hl + 2.0 * hl * lc);
}

static void cover_shape_kinds(i2d_world_id world) {
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;

    /* An offset box turned a quarter: 1 x 0.5 m at (1, 0), now 0.5 wide and 1 tall. */
    i2d_body_id a = i2d_body_create(world, &def);
    shape_def.density = 2.0f;
    i2d_shape_id offset_box =
        i2d_shape_create_offset_box(a, &shape_def, 0.5f, 0.25f, v2(1.0f, 0.0f), i2d_make_rot(1.5707963f));
    I2D_REQUIRE(!I2D_IS_NULL(offset_box));
    I2D_CHECK(i2d_shape_get_type(offset_box) == I2D_SHAPE_POLYGON);
    i2d_polygon p = i2d_shape_get_polygon(offset_box);
    I2D_CHECK(p.count == 4 && p.radius == 0.0f);
    I2D_CHECK_NEAR(p.centroid.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(p.centroid.y, 0.0, 1e-6);
    check_aabb_near(i2d_shape_get_aabb(offset_box), box(0.75f, -0.5f, 1.25f, 0.5f), 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_mass(a), 1.0, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_local_center_of_mass(a).x, 1.0, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(a), 1.0 * (1.0 + 0.25) / 12.0, 1e-6);

    /* A polygon from points: the right triangle (0, 0), (1, 0), (0, 1) with an interior
     * point that the hull drops. Area 1/2, centroid (1/3, 1/3), I = m (a^2 + b^2) / 18. */
    def.position = v2(5.0f, 0.0f);
    i2d_body_id b = i2d_body_create(world, &def);
    const i2d_vec2 points[4] = {{0.0f, 1.0f}, {0.2f, 0.2f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    i2d_shape_id triangle = i2d_shape_create_polygon(b, &shape_def, points, 4);
    I2D_REQUIRE(!I2D_IS_NULL(triangle));
    p = i2d_shape_get_polygon(triangle);
    I2D_CHECK(p.count == 3);
    double area2 = 0.0; /* twice the signed area: positive when counter-clockwise */
    for (int i = 0; i < p.count && i < 3; ++i) {
        i2d_vec2 u = p.vertices[i], w = p.vertices[(i + 1) % 3];
        area2 += (double)u.x * w.y - (double)u.y * w.x;
        double ex = w.x - u.x, ey = w.y - u.y, len = sqrt(ex * ex + ey * ey);
        I2D_CHECK_NEAR(p.normals[i].x, ey / len, 1e-6); /* outward: the edge turned clockwise */
        I2D_CHECK_NEAR(p.normals[i].y, -ex / len, 1e-6);
    }
    I2D_CHECK_NEAR(area2, 1.0, 1e-6);
    I2D_CHECK_NEAR(p.centroid.x, 1.0 / 3.0, 1e-6);
    I2D_CHECK_NEAR(p.centroid.y, 1.0 / 3.0, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_mass(b), 1.0, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(b), 2.0 / 18.0, 1e-6);
    check_aabb_near(i2d_shape_get_aabb(triangle), box(5.0f, 0.0f, 6.0f, 1.0f), 1e-6);

    /* A rounded square from i2d_make_polygon: 1 x 1 grown by 0.1, area 1 + 4 (0.1) + pi 0.01. */
    def.position = v2(10.0f, 0.0f);
    i2d_body_id c = i2d_body_create(world, &def);
    const i2d_vec2 square[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
    i2d_polygon rounded;
    I2D_CHECK_STATUS(i2d_make_polygon(square, 4, 0.1f, &rounded), I2D_OK);
    shape_def.density = 1.0f;
    i2d_shape_id rounded_shape = i2d_shape_create_polygon_from(c, &shape_def, &rounded);
    I2D_REQUIRE(!I2D_IS_NULL(rounded_shape));
    p = i2d_shape_get_polygon(rounded_shape);
    I2D_CHECK(p.count == 4);
    I2D_CHECK_NEAR(p.radius, 0.1, 1e-7);
    I2D_CHECK_NEAR(i2d_body_get_mass(c), 1.0 + 0.4 + k_pi * 0.01, 1e-5);
    check_aabb_near(i2d_shape_get_aabb(rounded_shape), box(9.4f, -0.6f, 10.6f, 0.6f), 1e-5);

    /* A capsule: centres 2 m apart, radius 0.5. */
    def.position = v2(15.0f, 0.0f);
    i2d_body_id d = i2d_body_create(world, &def);
    i2d_shape_id capsule = i2d_shape_create_capsule(d, &shape_def, v2(-1.0f, 0.0f), v2(1.0f, 0.0f), 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(capsule));
    I2D_CHECK(i2d_shape_get_type(capsule) == I2D_SHAPE_CAPSULE);
    i2d_capsule cap = i2d_shape_get_capsule(capsule);
    I2D_CHECK(cap.center1.x == -1.0f && cap.center1.y == 0.0f && cap.center2.x == 1.0f && cap.center2.y == 0.0f);
    I2D_CHECK(cap.radius == 0.5f);
    I2D_CHECK_NEAR(i2d_body_get_mass(d), capsule_mass(1.0, 0.5), 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(d), capsule_inertia(1.0, 0.5), 1e-5);
    check_aabb_near(i2d_shape_get_aabb(capsule), box(13.5f, -0.5f, 16.5f, 0.5f), 1e-6);

    /* A segment has no mass: the body keeps its circle's. */
    def.position = v2(20.0f, 0.0f);
    i2d_body_id e = i2d_body_create(world, &def);
    i2d_circle disc = {{0.0f, 0.0f}, 0.5f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(e, &shape_def, &disc)));
    i2d_shape_id stick = i2d_shape_create_segment(e, &shape_def, v2(0.0f, 1.0f), v2(0.0f, 3.0f));
    I2D_REQUIRE(!I2D_IS_NULL(stick));
    I2D_CHECK_NEAR(i2d_body_get_mass(e), k_pi * 0.25, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(e), k_pi * 0.25 * 0.25 / 2.0, 1e-6);

    /* A segment on a static body turned a quarter: local (0, 0)-(2, 0) is world x = 30,
     * y from 0 to 2. */
    def = i2d_default_body_def();
    def.position = v2(30.0f, 0.0f);
    def.rotation.c = 0.0f;
    def.rotation.s = 1.0f;
    i2d_body_id wall = i2d_body_create(world, &def);
    i2d_shape_id segment = i2d_shape_create_segment(wall, &shape_def, v2(0.0f, 0.0f), v2(2.0f, 0.0f));
    I2D_REQUIRE(!I2D_IS_NULL(segment));
    I2D_CHECK(i2d_shape_get_type(segment) == I2D_SHAPE_SEGMENT);
    i2d_segment seg = i2d_shape_get_segment(segment);
    I2D_CHECK(seg.point1.x == 0.0f && seg.point1.y == 0.0f && seg.point2.x == 2.0f && seg.point2.y == 0.0f);
    check_aabb_near(i2d_shape_get_aabb(segment), box(30.0f, 0.0f, 30.0f, 2.0f), 1e-6);

    /* Queries see the new kinds where they are. */
    const i2d_query_filter all = i2d_default_query_filter();
    id_list found = {0, {{0}}};
    I2D_CHECK_STATUS(i2d_world_overlap_point(world, v2(16.2f, 0.3f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 1 && I2D_ID_EQUALS(found.ids[0], capsule)); /* in the right half disc */
    found.count = 0;
    I2D_CHECK_STATUS(i2d_world_overlap_point(world, v2(16.45f, 0.45f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 0); /* in the capsule's bounds, outside the half disc */
    found.count = 0;
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(world, box(0.5f, 0.6f, 1.5f, 1.0f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 0); /* the unturned offset box would reach y = 0.25 only... */
    found.count = 0;
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(world, box(0.5f, 0.4f, 1.5f, 1.0f), all, collect_id, &found), I2D_OK);
    I2D_CHECK(found.count == 1 && I2D_ID_EQUALS(found.ids[0], offset_box)); /* ...the turned one to 0.5 */
    i2d_ray_result r = i2d_world_cast_ray_closest(world, v2(35.0f, 1.0f), v2(-10.0f, 0.0f), all);
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, segment));
    I2D_CHECK_NEAR(r.fraction, 0.5, 1e-6);
    I2D_CHECK_NEAR(r.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(r.normal.y, 0.0, 1e-6);
}

static void cover_shapes(void) { run_in_world(0.0f, cover_shape_kinds); }

/* ---- The pure functions of collision.h for placed shapes ---------------------------- */

static i2d_transform xform(float x, float y, i2d_rot q) {
    i2d_transform t;
    t.p = v2(x, y);
    t.q = q;
    return t;
}

/* One manifold against closed form: the normal n, and every point at depth `penetration`
 * with its coordinate along n at `along` and its coordinate along (n.y, -n.x) (x when n
 * is (0, 1)) in [lo, hi]. */
static void check_manifold_at(int line, const char* what, i2d_manifold m, int min_points, double nx, double ny,
                              double penetration, double along, double lo, double hi) {
    int before = i2d_check_failures;
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(m.point_count >= min_points && m.point_count <= 2);
    I2D_CHECK_NEAR(m.normal.x, nx, 1e-5);
    I2D_CHECK_NEAR(m.normal.y, ny, 1e-5);
    for (int i = 0; i < m.point_count && i < 2; ++i) {
        const i2d_manifold_point* mp = &m.points[i];
        double a = mp->point.x * nx + mp->point.y * ny, t = mp->point.x * ny - mp->point.y * nx;
        I2D_CHECK_NEAR(mp->penetration, penetration, 1e-5);
        I2D_CHECK_NEAR(a, along, 1e-5);
        I2D_CHECK(t >= lo - 1e-5 && t <= hi + 1e-5);
    }
    if (m.point_count == 2) {
        I2D_CHECK(m.points[0].id != m.points[1].id);
    }
    if (i2d_check_failures != before) {
        fprintf(stderr, "%s:%d: (the manifold of %s)\n", __FILE__, line, what);
    }
}
#define CHECK_MANIFOLD(what, m, min_points, nx, ny, pen, along, lo, hi) \
    check_manifold_at(__LINE__, (what), (m), (min_points), (nx), (ny), (pen), (along), (lo), (hi))

static void check_cast_at(int line, const char* what, i2d_cast_output out, double fraction, double px, double py,
                          double nx, double ny) {
    int before = i2d_check_failures;
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(out.hit);
    I2D_CHECK_NEAR(out.fraction, fraction, 1e-6);
    I2D_CHECK_NEAR(out.point.x, px, 1e-5);
    I2D_CHECK_NEAR(out.point.y, py, 1e-5);
    I2D_CHECK_NEAR(out.normal.x, nx, 1e-5);
    I2D_CHECK_NEAR(out.normal.y, ny, 1e-5);
    if (i2d_check_failures != before) {
        fprintf(stderr, "%s:%d: (the ray cast of %s)\n", __FILE__, line, what);
    }
}
#define CHECK_CAST(what, out, fraction, px, py, nx, ny) \
    check_cast_at(__LINE__, (what), (out), (fraction), (px), (py), (nx), (ny))

static void cover_pure_functions(void) {
    const double root2 = 1.41421356237309505;
    const i2d_rot identity = {1.0f, 0.0f};
    const i2d_rot quarter = i2d_make_rot(1.5707963f);
    const i2d_rot eighth = i2d_make_rot(0.785398163f);

    /* Boxes as polygons: corners counter-clockwise from the lower left, outward normals. */
    i2d_polygon b = i2d_make_box(1.0f, 0.5f);
    I2D_CHECK(b.count == 4 && b.radius == 0.0f);
    I2D_CHECK(b.vertices[0].x == -1.0f && b.vertices[0].y == -0.5f);
    I2D_CHECK(b.vertices[2].x == 1.0f && b.vertices[2].y == 0.5f);
    I2D_CHECK(b.normals[0].x == 0.0f && b.normals[0].y == -1.0f);
    I2D_CHECK(b.centroid.x == 0.0f && b.centroid.y == 0.0f);
    i2d_polygon ob = i2d_make_offset_box(1.0f, 0.5f, v2(2.0f, 3.0f), quarter);
    I2D_CHECK(ob.count == 4);
    I2D_CHECK_NEAR(ob.vertices[0].x, 2.5, 1e-6); /* (-1, -0.5) turned a quarter, moved to (2, 3) */
    I2D_CHECK_NEAR(ob.vertices[0].y, 2.0, 1e-6);
    I2D_CHECK_NEAR(ob.normals[0].x, 1.0, 1e-6);
    I2D_CHECK_NEAR(ob.normals[0].y, 0.0, 1e-6);
    I2D_CHECK_NEAR(ob.centroid.x, 2.0, 1e-6);
    I2D_CHECK_NEAR(ob.centroid.y, 3.0, 1e-6);
    /* A hull: the interior point is dropped, the 2 x 1 rectangle remains. */
    const i2d_vec2 points[5] = {{1.0f, 0.5f}, {2.0f, 1.0f}, {0.0f, 0.0f}, {2.0f, 0.0f}, {0.0f, 1.0f}};
    i2d_polygon hull;
    I2D_CHECK_STATUS(i2d_make_polygon(points, 5, 0.0f, &hull), I2D_OK);
    I2D_CHECK(hull.count == 4);

    /* Mass: density 3 on the 2 x 1 rectangle: m = 6, I = m (w^2 + h^2) / 12 = 2.5. */
    i2d_mass_data md = i2d_compute_polygon_mass(&hull, 3.0f);
    I2D_CHECK_NEAR(md.mass, 6.0, 1e-5);
    I2D_CHECK_NEAR(md.center.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(md.center.y, 0.5, 1e-6);
    I2D_CHECK_NEAR(md.rotational_inertia, 2.5, 1e-5);
    const i2d_circle circle = {{1.0f, 2.0f}, 0.5f};
    md = i2d_compute_circle_mass(&circle, 2.0f);
    I2D_CHECK_NEAR(md.mass, k_pi / 2.0, 1e-6);
    I2D_CHECK_NEAR(md.center.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(md.center.y, 2.0, 1e-6);
    I2D_CHECK_NEAR(md.rotational_inertia, k_pi / 16.0, 1e-6);
    const i2d_capsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    md = i2d_compute_capsule_mass(&capsule, 1.0f);
    I2D_CHECK_NEAR(md.mass, capsule_mass(1.0, 0.5), 1e-5);
    I2D_CHECK_NEAR(md.center.x, 0.0, 1e-6);
    I2D_CHECK_NEAR(md.rotational_inertia, capsule_inertia(1.0, 0.5), 1e-5);

    /* Ray casts of placed shapes. */
    const i2d_circle unit = {{0.0f, 0.0f}, 1.0f};
    CHECK_CAST("circle at (5, 0)",
               i2d_ray_cast_circle(&unit, xform(5.0f, 0.0f, identity), v2(0.0f, 0.0f), v2(10.0f, 0.0f)), 0.4, 4.0,
               0.0, -1.0, 0.0);
    /* The capsule turned a quarter at (0, 5): upright from (0, 4) to (0, 6), 0.5 thick. */
    CHECK_CAST("upright capsule",
               i2d_ray_cast_capsule(&capsule, xform(0.0f, 5.0f, quarter), v2(-5.0f, 5.0f), v2(10.0f, 0.0f)), 0.45,
               -0.5, 5.0, -1.0, 0.0);
    /* The segment turned a quarter at (3, 0): x = 3, y in [-1, 1], hit from both sides. */
    const i2d_segment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
    CHECK_CAST("upright segment from the left",
               i2d_ray_cast_segment(&segment, xform(3.0f, 0.0f, quarter), v2(0.0f, 0.5f), v2(10.0f, 0.0f)), 0.3, 3.0,
               0.5, -1.0, 0.0);
    CHECK_CAST("upright segment from the right",
               i2d_ray_cast_segment(&segment, xform(3.0f, 0.0f, quarter), v2(10.0f, 0.5f), v2(-10.0f, 0.0f)), 0.7, 3.0,
               0.5, 1.0, 0.0);
    /* The unit square turned by 45 degrees: the diamond |x| + |y| <= sqrt(2). */
    const i2d_polygon square = i2d_make_box(1.0f, 1.0f);
    CHECK_CAST("diamond", i2d_ray_cast_polygon(&square, xform(0.0f, 0.0f, eighth), v2(-5.0f, 0.5f), v2(10.0f, 0.0f)),
               (5.5 - root2) / 10.0, 0.5 - root2, 0.5, -1.0 / root2, 1.0 / root2);
    i2d_cast_output miss = i2d_ray_cast_polygon(&square, xform(0.0f, 0.0f, eighth), v2(-5.0f, 1.45f), v2(10.0f, 0.0f));
    I2D_CHECK(i2d_last_status() == I2D_OK && !miss.hit);

    /* Manifolds: normal from A to B; points midway between the surfaces. Shape A sits at
     * the origin (o), unturned unless said. */
    const i2d_transform o = xform(0.0f, 0.0f, identity);
    const i2d_circle small = {{0.0f, 0.0f}, 0.5f};
    i2d_manifold m = i2d_collide_capsule_circle(&capsule, o, &small, xform(0.0f, 0.8f, identity));
    CHECK_MANIFOLD("capsule-circle", m, 1, 0.0, 1.0, 0.2, 0.4, 0.0, 0.0);
    m = i2d_collide_segment_circle(&segment, o, &small, xform(0.5f, 0.4f, identity));
    CHECK_MANIFOLD("segment-circle", m, 1, 0.0, 1.0, 0.1, -0.05, 0.5, 0.5);
    /* A 4 x 1 box turned upright (|x| <= 0.5, |y| <= 2) and a circle at (0.8, 0). */
    const i2d_polygon long_box = i2d_make_box(2.0f, 0.5f);
    m = i2d_collide_polygon_circle(&long_box, xform(0.0f, 0.0f, quarter), &small, xform(0.8f, 0.0f, identity));
    CHECK_MANIFOLD("polygon-circle", m, 1, 1.0, 0.0, 0.2, 0.4, 0.0, 0.0);
    /* Two capsules along each other, 0.9 apart: both ends of the overlap. */
    m = i2d_collide_capsules(&capsule, o, &capsule, xform(0.5f, 0.9f, identity));
    CHECK_MANIFOLD("capsules", m, 2, 0.0, 1.0, 0.1, 0.45, -0.5, 1.0);
    const i2d_segment long_segment = {{-2.0f, 0.0f}, {2.0f, 0.0f}};
    m = i2d_collide_segment_capsule(&long_segment, o, &capsule, xform(0.0f, 0.3f, identity));
    CHECK_MANIFOLD("segment-capsule", m, 1, 0.0, 1.0, 0.2, -0.1, -1.0, 1.0);
    const i2d_capsule short_capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
    m = i2d_collide_polygon_capsule(&square, o, &short_capsule, xform(0.0f, 1.15f, identity));
    CHECK_MANIFOLD("polygon-capsule", m, 1, 0.0, 1.0, 0.1, 0.95, -0.5, 0.5);
    /* A box turned a half turn still lies flat, its bottom 0.1 below the segment. */
    const i2d_polygon flat = i2d_make_box(1.0f, 0.5f);
    const i2d_rot half = {-1.0f, 0.0f};
    m = i2d_collide_segment_polygon(&long_segment, o, &flat, xform(0.0f, 0.4f, half));
    CHECK_MANIFOLD("segment-polygon", m, 1, 0.0, 1.0, 0.1, -0.05, -1.0, 1.0);
    /* Two unit squares 1.8 apart, the second turned a quarter: 0.2 deep along x, the
     * contact edge x = 0.9 from y = -1 to 1. */
    m = i2d_collide_polygons(&square, o, &square, xform(1.8f, 0.0f, quarter));
    CHECK_MANIFOLD("polygons", m, 2, 1.0, 0.0, 0.2, 0.9, -1.0, 1.0);
    i2d_manifold apart = i2d_collide_polygons(&square, o, &square, xform(3.0f, 0.0f, eighth));
    I2D_CHECK(i2d_last_status() == I2D_OK && apart.point_count == 0);
}

I2D_TEST(api_world_coverage) {
    cover_library_calls();
    cover_defaults();
    cover_collision();
    cover_rotations();
    cover_pure_functions();
    cover_turning();
    cover_shapes();
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

I2D_TEST(api_world_mass_rules) { run_in_default_world(run_mass_rules); }

/* Timing costs nothing until asked for: a world that never read its profile (nor set
 * enable_profile) reports zeros; the first read turns timing on for the next step, and
 * enable_profile times from the first step. */
I2D_TEST(api_world_profile_only_when_asked) {
    i2d_world_def world_def = i2d_default_world_def();
    I2D_CHECK(!world_def.enable_profile);
    i2d_world_id quiet = i2d_world_create(&world_def);
    world_def.enable_profile = true;
    i2d_world_id timed = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(quiet) && !I2D_IS_NULL(timed));
    for (int s = 0; s < 3; ++s) {
        I2D_CHECK_STATUS(i2d_world_step(quiet, 1.0f / 60.0f, 4), I2D_OK);
        I2D_CHECK_STATUS(i2d_world_step(timed, 1.0f / 60.0f, 4), I2D_OK);
    }
    I2D_CHECK(i2d_world_get_profile(quiet).step == 0.0f);
    I2D_CHECK(i2d_world_get_profile(timed).step > 0.0f);
    I2D_CHECK_STATUS(i2d_world_step(quiet, 1.0f / 60.0f, 4), I2D_OK);
    I2D_CHECK(i2d_world_get_profile(quiet).step > 0.0f);
    i2d_world_destroy(quiet);
    i2d_world_destroy(timed);
}

/* The profile splits one step's wall time into stages measured by the same clock: every
 * stage is non-negative and together they cannot exceed the whole step. */
I2D_TEST(api_world_profile) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_profile before = i2d_world_get_profile(world);
    I2D_CHECK(before.step == 0.0f && before.solve == 0.0f);
    i2d_body_def body_def = i2d_default_body_def();
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_body_id ground = i2d_body_create(world, &body_def);
    i2d_shape_create_box(ground, &shape_def, 20.0f, 0.5f);
    body_def.type = I2D_BODY_DYNAMIC;
    for (int i = 0; i < 50; ++i) {
        body_def.position.x = -10.0f + 0.45f * (float)i;
        body_def.position.y = 1.0f + 0.3f * (float)(i % 5);
        i2d_body_id b = i2d_body_create(world, &body_def);
        i2d_shape_create_box(b, &shape_def, 0.2f, 0.2f);
    }
    for (int s = 0; s < 30; ++s) {
        I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 4), I2D_OK);
    }
    i2d_profile p = i2d_world_get_profile(world);
    I2D_CHECK_STATUS(i2d_last_status(), I2D_OK);
    I2D_CHECK(p.step > 0.0f);
    I2D_CHECK(p.pairs >= 0.0f && p.collide >= 0.0f && p.solve > 0.0f && p.update_bounds >= 0.0f && p.events >= 0.0f);
    I2D_CHECK(p.pairs + p.collide + p.solve + p.update_bounds + p.events <= p.step * 1.001f + 1e-4f);
    i2d_world_destroy(world);
    p = i2d_world_get_profile(world);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(p.step == 0.0f && p.solve == 0.0f);
}
