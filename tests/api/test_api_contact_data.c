/* SPDX-License-Identifier: MIT */
/* C API contact and sensor data, shape distance and closest points: a resting box's
 * contact against closed form, the body and shape variants against each other, sensors
 * on every body type against their events, distances and closest points against closed
 * forms, and every bad input refused with the world untouched. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"
#include "test_api_errors.h"

/* ---- Scenes ----------------------------------------------------------------------- */

static const float k_gravity = 10.0f; /* m/s^2, down */

/* The ground of the contact tests: a static box 40 m wide whose top is at y = 0. */
static i2d_shape_id make_ground(i2d_world_id world) {
    const i2d_shape_def def = i2d_default_shape_def();
    return i2d_shape_create_box(make_body(world, I2D_BODY_STATIC, 0.0f, -1.0f), &def, 20.0f, 1.0f);
}

/* A box of the given half extents centred at `offset` on the body. */
static i2d_shape_id add_box(i2d_body_id body, float half_width, float half_height, i2d_vec2 offset) {
    const i2d_shape_def def = i2d_default_shape_def();
    return i2d_shape_create_offset_box(body, &def, half_width, half_height, offset, identity_rot());
}

static i2d_shape_id add_circle(i2d_body_id body, const i2d_shape_def* def, i2d_vec2 center, float radius) {
    i2d_circle circle;
    circle.center = center;
    circle.radius = radius;
    return i2d_shape_create_circle(body, def, &circle);
}

/* Two contact data entries are the same, field by field (a struct copy need not copy
 * padding, so no memcmp). */
static bool same_contact_data(const i2d_contact_data* a, const i2d_contact_data* b) {
    if (!I2D_ID_EQUALS(a->shape_a, b->shape_a) || !I2D_ID_EQUALS(a->shape_b, b->shape_b) ||
        a->manifold.normal.x != b->manifold.normal.x || a->manifold.normal.y != b->manifold.normal.y ||
        a->manifold.point_count != b->manifold.point_count) {
        return false;
    }
    for (int i = 0; i < 2; ++i) {
        const i2d_manifold_point* p = &a->manifold.points[i];
        const i2d_manifold_point* q = &b->manifold.points[i];
        if (p->point.x != q->point.x || p->point.y != q->point.y || p->penetration != q->penetration ||
            p->id != q->id || a->normal_impulses[i] != b->normal_impulses[i] ||
            a->tangent_impulses[i] != b->tangent_impulses[i]) {
            return false;
        }
    }
    return true;
}

static bool steps_ok(i2d_world_id world, int count) {
    for (int i = 0; i < count; ++i) {
        if (!step_ok(world)) {
            return false;
        }
    }
    return true;
}

/* ---- A box resting on the ground ---------------------------------------------------- */

static void run_resting_box(i2d_world_id world) {
    const i2d_shape_id ground = make_ground(world);
    const i2d_body_id body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.5f);
    const i2d_shape_id crate = add_box(body, 0.5f, 0.5f, v2(0.0f, 0.0f));
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(crate));
    I2D_REQUIRE(steps_ok(world, 60));

    i2d_contact_data data[4];
    I2D_REQUIRE(i2d_body_get_contact_data(body, data, 4) == 1);
    const i2d_contact_data* c = &data[0];
    I2D_CHECK(same_pair(c->shape_a, c->shape_b, ground, crate));
    /* The normal points from A to B: up when the ground is A. */
    const float up = I2D_ID_EQUALS(c->shape_a, ground) ? 1.0f : -1.0f;
    I2D_REQUIRE(c->manifold.point_count == 2);
    I2D_CHECK_NEAR(c->manifold.normal.x, 0.0f, 1e-6f);
    I2D_CHECK_NEAR(c->manifold.normal.y, up, 1e-6f);
    /* The points are the box's bottom corners, on the ground's top, one each side. */
    for (int i = 0; i < 2; ++i) {
        I2D_CHECK_NEAR(fabsf(c->manifold.points[i].point.x), 0.5f, 0.01f);
        I2D_CHECK_NEAR(c->manifold.points[i].point.y, 0.0f, 0.01f);
        I2D_CHECK(fabsf(c->manifold.points[i].penetration) <= 0.005f);
        I2D_CHECK_NEAR(c->tangent_impulses[i], 0.0f, 1e-6f); /* nothing pushes it sideways */
    }
    I2D_CHECK(c->manifold.points[0].point.x * c->manifold.points[1].point.x < 0.0f);
    /* At rest the substep's impulses carry the weight over the substep (i2d_contact_data):
     * m g dt over the step, within 1 %. */
    const float weight_impulse = i2d_body_get_mass(body) * k_gravity * k_dt;
    const float step_impulse = (c->normal_impulses[0] + c->normal_impulses[1]) * (float)SUBSTEPS;
    I2D_CHECK_NEAR(step_impulse, weight_impulse, 0.01f * weight_impulse);
    I2D_CHECK(c->normal_impulses[0] > 0.0f && c->normal_impulses[1] > 0.0f);
}

I2D_TEST(api_contact_data_resting_box_has_two_points_normal_up_and_its_weight) {
    run_in_world(-k_gravity, run_resting_box);
}

/* ---- Body and shape variants; capacity ---------------------------------------------- */

/* A plank of two 1 m boxes 2 m apart resting on the ground: two contacts, one per box. */
typedef struct plank {
    i2d_shape_id ground;
    i2d_body_id body;
    i2d_shape_id boxes[2];
} plank;

static bool plank_build(i2d_world_id world, plank* p) {
    p->ground = make_ground(world);
    p->body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.5f);
    p->boxes[0] = add_box(p->body, 0.5f, 0.5f, v2(-1.0f, 0.0f));
    p->boxes[1] = add_box(p->body, 0.5f, 0.5f, v2(1.0f, 0.0f));
    return !I2D_IS_NULL(p->ground) && !I2D_IS_NULL(p->boxes[0]) && !I2D_IS_NULL(p->boxes[1]) && steps_ok(world, 30);
}

/* Whether `entry` is among data[0..count). */
static bool contains_contact(const i2d_contact_data* data, int32_t count, const i2d_contact_data* entry) {
    for (int32_t i = 0; i < count; ++i) {
        if (same_contact_data(&data[i], entry)) {
            return true;
        }
    }
    return false;
}

static void run_variants_agree(i2d_world_id world) {
    plank p;
    I2D_REQUIRE(plank_build(world, &p));
    i2d_contact_data of_body[4], of_ground_body[4], of_ground[4], of_box[2][4];
    const int32_t body_count = i2d_body_get_contact_data(p.body, of_body, 4);
    I2D_REQUIRE(body_count == 2);
    const i2d_body_id ground_body = i2d_shape_get_body(p.ground);
    I2D_CHECK(i2d_body_get_contact_data(ground_body, of_ground_body, 4) == 2);
    I2D_CHECK(i2d_shape_get_contact_data(p.ground, of_ground, 4) == 2);
    for (int b = 0; b < 2; ++b) {
        /* Each box has its own contact, which its body and the ground list as well. */
        I2D_REQUIRE(i2d_shape_get_contact_data(p.boxes[b], of_box[b], 4) == 1);
        I2D_CHECK(same_pair(of_box[b][0].shape_a, of_box[b][0].shape_b, p.ground, p.boxes[b]));
        I2D_CHECK(contains_contact(of_body, body_count, &of_box[b][0]));
        I2D_CHECK(contains_contact(of_ground_body, 2, &of_box[b][0]));
        I2D_CHECK(contains_contact(of_ground, 2, &of_box[b][0]));
    }
    I2D_CHECK(!same_contact_data(&of_box[0][0], &of_box[1][0]));
    /* The same call twice gives the same entries in the same order. */
    i2d_contact_data again[4];
    I2D_CHECK(i2d_body_get_contact_data(p.body, again, 4) == 2);
    I2D_CHECK(same_contact_data(&again[0], &of_body[0]) && same_contact_data(&again[1], &of_body[1]));
}

I2D_TEST(api_contact_data_body_and_shape_variants_agree) { run_in_world(-k_gravity, run_variants_agree); }

static void run_short_capacity(i2d_world_id world) {
    plank p;
    I2D_REQUIRE(plank_build(world, &p));
    i2d_contact_data all[4];
    I2D_REQUIRE(i2d_body_get_contact_data(p.body, all, 4) == 2);

    /* Capacity 1 of 2: the first entry written, the count returned, nothing past it. */
    i2d_contact_data out[2];
    memset(out, 0xAB, sizeof out);
    unsigned char untouched[sizeof out[1]];
    memset(untouched, 0xAB, sizeof untouched);
    I2D_CHECK(i2d_body_get_contact_data(p.body, out, 1) == 2);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(same_contact_data(&out[0], &all[0]));
    I2D_CHECK(memcmp(&out[1], untouched, sizeof untouched) == 0);

    /* Capacity 0 (out may be NULL) only counts. */
    I2D_CHECK(i2d_body_get_contact_data(p.body, NULL, 0) == 2);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(i2d_shape_get_contact_data(p.ground, NULL, 0) == 2);
    I2D_CHECK(i2d_last_status() == I2D_OK);
}

I2D_TEST(api_contact_data_capacity_smaller_than_count_fills_only_capacity) {
    run_in_world(-k_gravity, run_short_capacity);
}

/* ---- Sensors on every body type ------------------------------------------------------- */

enum { MAX_VISITS = 16 };

/* The visits of one sensor that began and have not ended, kept from its events. */
typedef struct open_visits {
    i2d_shape_id sensor;
    i2d_shape_id visitors[MAX_VISITS];
    int count;
} open_visits;

static void follow_sensor_events(i2d_world_id world, open_visits* v) {
    const i2d_sensor_events e = i2d_world_get_sensor_events(world);
    for (int32_t i = 0; i < e.begin_count; ++i) {
        if (I2D_ID_EQUALS(e.begin_events[i].sensor_shape, v->sensor) && v->count < MAX_VISITS) {
            v->visitors[v->count++] = e.begin_events[i].visitor_shape;
        }
    }
    for (int32_t i = 0; i < e.end_count; ++i) {
        for (int k = 0; k < v->count; ++k) {
            if (I2D_ID_EQUALS(e.end_events[i].sensor_shape, v->sensor) &&
                I2D_ID_EQUALS(e.end_events[i].visitor_shape, v->visitors[k])) {
                v->visitors[k] = v->visitors[--v->count];
                break;
            }
        }
    }
}

static bool listed(const i2d_shape_id* list, int count, i2d_shape_id shape) {
    for (int i = 0; i < count; ++i) {
        if (I2D_ID_EQUALS(list[i], shape)) {
            return true;
        }
    }
    return false;
}

/* The sensor's overlaps are exactly `expected` and exactly the visits its events left
 * open. */
static void check_overlaps_at(int line, const char* when, const open_visits* v, const i2d_shape_id* expected,
                              int expected_count) {
    i2d_shape_id got[MAX_VISITS];
    const int32_t n = i2d_shape_get_sensor_overlaps(v->sensor, got, MAX_VISITS);
    bool same = n == expected_count && n == v->count && i2d_last_status() == I2D_OK;
    for (int i = 0; same && i < n; ++i) {
        same = listed(expected, expected_count, got[i]) && listed(v->visitors, v->count, got[i]);
    }
    if (!same) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: %d overlaps, expected %d, open visits by the events %d\n", __FILE__, line, when,
                (int)n, expected_count, v->count);
    }
}
#define CHECK_OVERLAPS(when, v, expected, count) check_overlaps_at(__LINE__, (when), (v), (expected), (count))

static bool step_following(i2d_world_id world, open_visits* v, int count) {
    for (int i = 0; i < count; ++i) {
        if (!step_ok(world)) {
            return false;
        }
        follow_sensor_events(world, v);
    }
    return true;
}

/* Without gravity: a sensor box [-2, 2]^2 on a body of the given type; inside it a
 * dynamic ball, a kinematic ball, a static block and a ball without sensor events; a
 * dynamic ball far away. The kinematic ball leaves, then the dynamic one; then the sensor
 * jumps onto the far ball. */
static void run_sensor_on(i2d_world_id world, i2d_body_type sensor_type) {
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    const i2d_body_id zone = make_body(world, sensor_type, 0.0f, 0.0f);
    open_visits v;
    v.sensor = i2d_shape_create_box(zone, &sensor_def, 2.0f, 2.0f);
    v.count = 0;

    const i2d_shape_def plain = i2d_default_shape_def();
    i2d_shape_def quiet = plain;
    quiet.enable_sensor_events = false;
    const i2d_body_id dynamic_ball = make_body(world, I2D_BODY_DYNAMIC, -1.0f, 0.0f);
    const i2d_body_id kinematic_ball = make_body(world, I2D_BODY_KINEMATIC, 1.0f, 0.0f);
    const i2d_shape_id dynamic_visitor = add_circle(dynamic_ball, &plain, v2(0.0f, 0.0f), 0.25f);
    const i2d_shape_id kinematic_visitor = add_circle(kinematic_ball, &plain, v2(0.0f, 0.0f), 0.25f);
    const i2d_shape_id block = add_box(make_body(world, I2D_BODY_STATIC, 0.0f, 1.0f), 0.25f, 0.25f, v2(0.0f, 0.0f));
    const i2d_shape_id unseen =
        add_circle(make_body(world, I2D_BODY_DYNAMIC, 0.0f, -1.0f), &quiet, v2(0.0f, 0.0f), 0.25f);
    const i2d_shape_id far_away =
        add_circle(make_body(world, I2D_BODY_DYNAMIC, 10.0f, 0.0f), &plain, v2(0.0f, 0.0f), 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(v.sensor) && !I2D_IS_NULL(dynamic_visitor) && !I2D_IS_NULL(kinematic_visitor) &&
                !I2D_IS_NULL(block) && !I2D_IS_NULL(unseen) && !I2D_IS_NULL(far_away));

    /* A static sensor does not see static shapes (static against static never pairs). */
    const bool sees_block = sensor_type != I2D_BODY_STATIC;
    I2D_REQUIRE(step_following(world, &v, 1));
    i2d_shape_id expected[3] = {dynamic_visitor, kinematic_visitor, block};
    CHECK_OVERLAPS("inside", &v, expected, sees_block ? 3 : 2);

    /* The kinematic ball leaves upwards at 20 m/s (2.25 m to go), clear of the far ball. */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(kinematic_ball, v2(0.0f, 20.0f)), I2D_OK);
    I2D_REQUIRE(step_following(world, &v, 10));
    expected[1] = block;
    CHECK_OVERLAPS("the kinematic ball left", &v, expected, sees_block ? 2 : 1);

    /* Then the dynamic one. */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(dynamic_ball, v2(-20.0f, 0.0f)), I2D_OK);
    I2D_REQUIRE(step_following(world, &v, 10));
    expected[0] = block;
    CHECK_OVERLAPS("both balls left", &v, expected, sees_block ? 1 : 0);

    /* The sensor moves onto the far ball, which rests there. */
    I2D_CHECK_STATUS(i2d_body_set_transform(zone, v2(10.0f, 0.0f), identity_rot()), I2D_OK);
    I2D_REQUIRE(step_following(world, &v, 1));
    expected[0] = far_away;
    CHECK_OVERLAPS("moved onto the far ball", &v, expected, 1);
}

static void run_static_sensor(i2d_world_id world) { run_sensor_on(world, I2D_BODY_STATIC); }
static void run_kinematic_sensor(i2d_world_id world) { run_sensor_on(world, I2D_BODY_KINEMATIC); }
static void run_dynamic_sensor(i2d_world_id world) { run_sensor_on(world, I2D_BODY_DYNAMIC); }

I2D_TEST(api_sensor_overlaps_on_static_body_list_visitors_and_follow_them_out) {
    run_in_world(0.0f, run_static_sensor);
}
I2D_TEST(api_sensor_overlaps_on_kinematic_body_list_visitors_and_follow_them_out) {
    run_in_world(0.0f, run_kinematic_sensor);
}
I2D_TEST(api_sensor_overlaps_on_dynamic_body_list_visitors_and_follow_them_out) {
    run_in_world(0.0f, run_dynamic_sensor);
}

/* ---- Distance and closest points against closed forms ---------------------------------- */

static i2d_transform placed(float x, float y, float angle) {
    i2d_transform xf;
    xf.p = v2(x, y);
    xf.q = i2d_make_rot(angle);
    return xf;
}

static i2d_shape_proxy point_proxy(float x, float y, float radius) {
    const i2d_vec2 p = v2(x, y);
    return i2d_make_proxy(&p, 1, radius);
}

/* A box of half extents (hw, hh) about its own origin, as a proxy. */
static i2d_shape_proxy box_proxy(float hw, float hh) {
    const i2d_vec2 corners[4] = {{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}};
    return i2d_make_proxy(corners, 4, 0.0f);
}

static void check_distance_at(int line, i2d_distance_result d, i2d_vec2 point_a, i2d_vec2 point_b, i2d_vec2 normal,
                              float distance) {
    const float tol = 1e-5f;
    if (!(fabsf(d.point_a.x - point_a.x) <= tol && fabsf(d.point_a.y - point_a.y) <= tol &&
          fabsf(d.point_b.x - point_b.x) <= tol && fabsf(d.point_b.y - point_b.y) <= tol &&
          fabsf(d.normal.x - normal.x) <= tol && fabsf(d.normal.y - normal.y) <= tol &&
          fabsf(d.distance - distance) <= tol && i2d_last_status() == I2D_OK)) {
        ++i2d_check_failures;
        fprintf(stderr,
                "%s:%d: distance %g, points (%g, %g) (%g, %g), normal (%g, %g); expected %g, (%g, %g) (%g, %g), "
                "(%g, %g)\n",
                __FILE__, line, d.distance, d.point_a.x, d.point_a.y, d.point_b.x, d.point_b.y, d.normal.x, d.normal.y,
                distance, point_a.x, point_a.y, point_b.x, point_b.y, normal.x, normal.y);
    }
}
#define CHECK_DISTANCE(d, pa, pb, n, dist) check_distance_at(__LINE__, (d), (pa), (pb), (n), (dist))

I2D_TEST(api_shape_distance_matches_closed_forms) {
    /* Circles of radius 1 at (0, 0) and 0.5 at (3, 4): 5 m between centres, 3.5 between
     * surfaces, along (0.6, 0.8). */
    const i2d_shape_proxy unit_circle = point_proxy(0.0f, 0.0f, 1.0f);
    const i2d_shape_proxy small_circle = point_proxy(0.0f, 0.0f, 0.5f);
    CHECK_DISTANCE(i2d_shape_distance(&unit_circle, placed(0, 0, 0), &small_circle, placed(3, 4, 0)), v2(0.6f, 0.8f),
                   v2(2.7f, 3.6f), v2(0.6f, 0.8f), 3.5f);

    /* A 2 x 1 box at the origin and a point to its right: from the face x = 1. */
    const i2d_shape_proxy slab = box_proxy(1.0f, 0.5f);
    const i2d_shape_proxy point = point_proxy(0.0f, 0.0f, 0.0f);
    CHECK_DISTANCE(i2d_shape_distance(&slab, placed(0, 0, 0), &point, placed(3.0f, 0.25f, 0)), v2(1.0f, 0.25f),
                   v2(3.0f, 0.25f), v2(1.0f, 0.0f), 2.0f);
    /* Beyond a corner: from the corner (1, 0.5), sqrt(2) away. */
    const float r = sqrtf(0.5f);
    CHECK_DISTANCE(i2d_shape_distance(&slab, placed(0, 0, 0), &point, placed(2.0f, 1.5f, 0)), v2(1.0f, 0.5f),
                   v2(2.0f, 1.5f), v2(r, r), sqrtf(2.0f));
    /* Turned a quarter about (1, 1), the box is 1 wide and 2 high: its top is at y = 2. */
    CHECK_DISTANCE(i2d_shape_distance(&slab, placed(1, 1, 1.5707963f), &point, placed(1.2f, 5.0f, 0)), v2(1.2f, 2.0f),
                   v2(1.2f, 5.0f), v2(0.0f, 1.0f), 3.0f);
    /* B first: the same distance, the normal from B to A. */
    CHECK_DISTANCE(i2d_shape_distance(&point, placed(3.0f, 0.25f, 0), &slab, placed(0, 0, 0)), v2(3.0f, 0.25f),
                   v2(1.0f, 0.25f), v2(-1.0f, 0.0f), 2.0f);

    /* Overlapping circles (centres 1 m apart, radii 1 and 0.5): distance 0, no normal,
     * one point that both hold. */
    const i2d_distance_result overlap =
        i2d_shape_distance(&unit_circle, placed(0, 0, 0), &small_circle, placed(1.0f, 0.0f, 0));
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(overlap.distance == 0.0f && overlap.normal.x == 0.0f && overlap.normal.y == 0.0f);
    I2D_CHECK(overlap.point_a.x == overlap.point_b.x && overlap.point_a.y == overlap.point_b.y);
    I2D_CHECK(hypotf(overlap.point_a.x, overlap.point_a.y) <= 1.0f &&
              hypotf(overlap.point_a.x - 1.0f, overlap.point_a.y) <= 0.5f);
    /* A point inside the box, and two boxes crossing: distance 0. */
    I2D_CHECK(i2d_shape_distance(&slab, placed(0, 0, 0), &point, placed(0.5f, 0.1f, 0)).distance == 0.0f);
    I2D_CHECK(i2d_shape_distance(&slab, placed(0, 0, 0), &slab, placed(0.5f, 0.5f, 0.3f)).distance == 0.0f);
    /* Touching circles: distance 0, with their normal. */
    CHECK_DISTANCE(i2d_shape_distance(&unit_circle, placed(0, 0, 0), &small_circle, placed(0.0f, 1.5f, 0)),
                   v2(0.0f, 1.0f), v2(0.0f, 1.0f), v2(0.0f, 1.0f), 0.0f);
}

static void check_closest_at(int line, i2d_shape_id shape, i2d_vec2 target, i2d_vec2 expected) {
    const i2d_vec2 p = i2d_shape_get_closest_point(shape, target);
    if (!(fabsf(p.x - expected.x) <= 1e-5f && fabsf(p.y - expected.y) <= 1e-5f && i2d_last_status() == I2D_OK)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: closest point to (%g, %g) is (%g, %g), expected (%g, %g) (%s)\n", __FILE__, line,
                target.x, target.y, p.x, p.y, expected.x, expected.y, i2d_last_error_message());
    }
}
#define CHECK_CLOSEST(shape, target, expected) check_closest_at(__LINE__, (shape), (target), (expected))

static void run_closest_points(i2d_world_id world) {
    const i2d_shape_def def = i2d_default_shape_def();
    /* A circle of radius 1 centred 1 m right of a body at (1, 0): centre (2, 0). */
    const i2d_shape_id circle = add_circle(make_body(world, I2D_BODY_STATIC, 1.0f, 0.0f), &def, v2(1.0f, 0.0f), 1.0f);
    /* A 2 x 1 box on a body at (0, 5) turned a quarter: 1 wide and 2 high. */
    i2d_body_def turned = i2d_default_body_def();
    turned.position = v2(0.0f, 5.0f);
    turned.rotation = i2d_make_rot(1.5707963f);
    const i2d_shape_id slab = add_box(i2d_body_create(world, &turned), 1.0f, 0.5f, v2(0.0f, 0.0f));
    const i2d_shape_id segment =
        i2d_shape_create_segment(make_body(world, I2D_BODY_STATIC, 0.0f, -5.0f), &def, v2(-1.0f, 0.0f), v2(1.0f, 0.0f));
    I2D_REQUIRE(!I2D_IS_NULL(circle) && !I2D_IS_NULL(slab) && !I2D_IS_NULL(segment));

    CHECK_CLOSEST(circle, v2(5.0f, 4.0f), v2(2.6f, 0.8f)); /* centre + (3, 4) / 5 */
    CHECK_CLOSEST(circle, v2(2.5f, 0.1f), v2(2.5f, 0.1f)); /* inside: the target itself */
    CHECK_CLOSEST(slab, v2(0.25f, 9.0f), v2(0.25f, 6.0f)); /* above the top face */
    CHECK_CLOSEST(slab, v2(3.0f, 8.0f), v2(0.5f, 6.0f));   /* beyond the corner */
    CHECK_CLOSEST(slab, v2(-0.2f, 4.1f), v2(-0.2f, 4.1f)); /* inside */
    CHECK_CLOSEST(segment, v2(0.3f, -2.0f), v2(0.3f, -5.0f));
    CHECK_CLOSEST(segment, v2(4.0f, -1.0f), v2(1.0f, -5.0f));
}

I2D_TEST(api_shape_closest_point_matches_closed_forms) { run_in_world(0.0f, run_closest_points); }

/* ---- Getters inside query callbacks ---------------------------------------------------- */

typedef struct inside_query {
    i2d_body_id body;
    i2d_shape_id shape;
    int32_t contacts, shape_contacts;
    i2d_vec2 closest;
    i2d_status status;
} inside_query;

static bool read_inside(i2d_shape_id shape, void* context) {
    inside_query* q = (inside_query*)context;
    (void)shape;
    i2d_contact_data data[4];
    q->contacts = i2d_body_get_contact_data(q->body, data, 4);
    q->status = i2d_last_status();
    q->shape_contacts = i2d_shape_get_contact_data(q->shape, data, 4);
    q->status = q->status != I2D_OK ? q->status : i2d_last_status();
    q->closest = i2d_shape_get_closest_point(q->shape, v2(0.0f, 10.0f));
    q->status = q->status != I2D_OK ? q->status : i2d_last_status();
    return false;
}

static void run_inside_query(i2d_world_id world) {
    make_ground(world);
    const i2d_body_id body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.5f);
    const i2d_shape_id crate = add_box(body, 0.5f, 0.5f, v2(0.0f, 0.0f));
    I2D_REQUIRE(!I2D_IS_NULL(crate) && steps_ok(world, 10));
    inside_query q = {body, crate, -1, -1, {0.0f, 0.0f}, I2D_ERR_INTERNAL};
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(world, box(-1.0f, -1.0f, 1.0f, 2.0f), i2d_default_query_filter(),
                                            read_inside, &q),
                     I2D_OK);
    I2D_CHECK(q.status == I2D_OK);
    I2D_CHECK(q.contacts == 1 && q.shape_contacts == 1);
    const i2d_vec2 outside = i2d_shape_get_closest_point(crate, v2(0.0f, 10.0f));
    I2D_CHECK(q.closest.x == outside.x && q.closest.y == outside.y);
}

I2D_TEST(api_contact_data_and_closest_point_work_inside_query_callbacks) {
    run_in_world(-k_gravity, run_inside_query);
}

/* ---- Bad input: refused, the world untouched ------------------------------------------ */

/* The call just made returned through i2d_last_status() `expected`, with a message. */
#define CHECK_LAST_REFUSED(what, expected) CHECK_REFUSED((what), i2d_last_status(), (expected))

static bool is_zero_result(i2d_distance_result d) {
    return d.point_a.x == 0.0f && d.point_a.y == 0.0f && d.point_b.x == 0.0f && d.point_b.y == 0.0f &&
           d.normal.x == 0.0f && d.normal.y == 0.0f && d.distance == 0.0f;
}

static void check_contact_getters_refuse(const fixture* f, i2d_body_id stale_body, i2d_shape_id stale_shape,
                                         i2d_shape_id sensor) {
    i2d_contact_data data[2];
    i2d_shape_id ids[2];
    I2D_CHECK(i2d_body_get_contact_data(stale_body, data, 2) == 0);
    CHECK_LAST_REFUSED("i2d_body_get_contact_data stale body", I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_body_get_contact_data(I2D_NULL_BODY_ID, data, 2) == 0);
    CHECK_LAST_REFUSED("i2d_body_get_contact_data null body", I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_body_get_contact_data(f->body[FIX_BALL], NULL, 2) == 0);
    CHECK_LAST_REFUSED("i2d_body_get_contact_data NULL out", I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_body_get_contact_data(f->body[FIX_BALL], data, -1) == 0);
    CHECK_LAST_REFUSED("i2d_body_get_contact_data capacity -1", I2D_ERR_INVALID_ARGUMENT);

    I2D_CHECK(i2d_shape_get_contact_data(stale_shape, data, 2) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_contact_data stale shape", I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_shape_get_contact_data(f->shape[FIX_BALL_CIRCLE], NULL, 1) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_contact_data NULL out", I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_shape_get_contact_data(f->shape[FIX_BALL_CIRCLE], data, -5) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_contact_data capacity -5", I2D_ERR_INVALID_ARGUMENT);

    I2D_CHECK(i2d_shape_get_sensor_overlaps(stale_shape, ids, 2) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_sensor_overlaps stale shape", I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_shape_get_sensor_overlaps(f->shape[FIX_BALL_CIRCLE], ids, 2) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_sensor_overlaps not a sensor", I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_shape_get_sensor_overlaps(sensor, NULL, 3) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_sensor_overlaps NULL out", I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_shape_get_sensor_overlaps(sensor, ids, -1) == 0);
    CHECK_LAST_REFUSED("i2d_shape_get_sensor_overlaps capacity -1", I2D_ERR_INVALID_ARGUMENT);
}

static void check_closest_point_refuses(const fixture* f, i2d_shape_id stale_shape) {
    i2d_vec2 p = i2d_shape_get_closest_point(stale_shape, v2(1.0f, 2.0f));
    CHECK_LAST_REFUSED("i2d_shape_get_closest_point stale shape", I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(p.x == 0.0f && p.y == 0.0f);
    for (int i = 0; i < NON_FINITE_COUNT; ++i) {
        p = i2d_shape_get_closest_point(f->shape[FIX_BALL_CIRCLE], v2(k_non_finite[i], 0.0f));
        CHECK_LAST_REFUSED("i2d_shape_get_closest_point non-finite target x", I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(p.x == 0.0f && p.y == 0.0f);
        p = i2d_shape_get_closest_point(f->shape[FIX_BALL_CIRCLE], v2(0.0f, k_non_finite[i]));
        CHECK_LAST_REFUSED("i2d_shape_get_closest_point non-finite target y", I2D_ERR_INVALID_ARGUMENT);
    }
}

static void check_distance_refuses(void) {
    const i2d_shape_proxy good = point_proxy(0.0f, 0.0f, 1.0f);
    const i2d_transform here = placed(0.0f, 0.0f, 0.0f);
    i2d_shape_proxy empty;
    memset(&empty, 0, sizeof empty); /* count 0: what i2d_make_proxy gives for bad input */
    I2D_CHECK(is_zero_result(i2d_shape_distance(&empty, here, &good, here)));
    CHECK_LAST_REFUSED("i2d_shape_distance count-0 proxy a", I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(is_zero_result(i2d_shape_distance(&good, here, &empty, here)));
    CHECK_LAST_REFUSED("i2d_shape_distance count-0 proxy b", I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(is_zero_result(i2d_shape_distance(NULL, here, &good, here)));
    CHECK_LAST_REFUSED("i2d_shape_distance NULL proxy", I2D_ERR_INVALID_ARGUMENT);
    for (int i = 0; i < NON_FINITE_COUNT; ++i) {
        i2d_shape_proxy bad = good;
        bad.points[0].y = k_non_finite[i];
        I2D_CHECK(is_zero_result(i2d_shape_distance(&bad, here, &good, here)));
        CHECK_LAST_REFUSED("i2d_shape_distance non-finite proxy point", I2D_ERR_INVALID_ARGUMENT);
        bad = good;
        bad.radius = k_non_finite[i];
        I2D_CHECK(is_zero_result(i2d_shape_distance(&good, here, &bad, here)));
        CHECK_LAST_REFUSED("i2d_shape_distance non-finite radius", I2D_ERR_INVALID_ARGUMENT);
        i2d_transform moved = here;
        moved.p.x = k_non_finite[i];
        I2D_CHECK(is_zero_result(i2d_shape_distance(&good, moved, &good, here)));
        CHECK_LAST_REFUSED("i2d_shape_distance non-finite position", I2D_ERR_INVALID_ARGUMENT);
    }
    for (int i = 0; i < k_bad_rotation_count; ++i) {
        i2d_transform turned = here;
        turned.q = rot(k_bad_rotations[i].c, k_bad_rotations[i].s);
        I2D_CHECK(is_zero_result(i2d_shape_distance(&good, here, &good, turned)));
        CHECK_LAST_REFUSED(k_bad_rotations[i].name, I2D_ERR_INVALID_ARGUMENT);
    }
}

static void run_refusals(const fixture* f) {
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    const i2d_shape_id sensor = i2d_shape_create_box(f->body[FIX_GROUND], &sensor_def, 1.0f, 1.0f);
    const i2d_body_id stale_body = make_body(f->world, I2D_BODY_DYNAMIC, 30.0f, 30.0f);
    const i2d_shape_id stale_shape = add_box(f->body[FIX_GROUND], 0.5f, 0.5f, v2(30.0f, 30.0f));
    I2D_REQUIRE(!I2D_IS_NULL(sensor) && !I2D_IS_NULL(stale_body) && !I2D_IS_NULL(stale_shape));
    I2D_REQUIRE(i2d_body_destroy(stale_body) == I2D_OK && i2d_shape_destroy(stale_shape) == I2D_OK);
    I2D_REQUIRE(step_ok(f->world));
    /* The calls below are refused for their input, not for want of contacts. */
    I2D_REQUIRE(i2d_body_get_contact_data(f->body[FIX_BALL], NULL, 0) > 0);

    snapshot before;
    snapshot_take(f, &before);
    const uint64_t hash = i2d_world_get_state_hash(f->world);
    check_contact_getters_refuse(f, stale_body, stale_shape, sensor);
    check_closest_point_refuses(f, stale_shape);
    check_distance_refuses();
    I2D_CHECK(i2d_world_get_state_hash(f->world) == hash);
    CHECK_UNCHANGED("after the refused contact, sensor and distance calls", f, &before);
}

I2D_TEST(api_contact_data_sensor_and_distance_calls_refuse_bad_input_world_untouched) {
    run_on_fixture(run_refusals);
}
