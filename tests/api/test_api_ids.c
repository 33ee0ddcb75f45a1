/* SPDX-License-Identifier: MIT */
/* C API handles: null, stale, recycled and foreign ids are refused; world capacity, version and status strings. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

/* ---- Small helpers ---------------------------------------------------------------- */

/* A check that also names the kind of bad id under test ("null body", "stale shape"...). */
#define CHECK_IN(ctx, cond)                                                                       \
    do {                                                                                          \
        if (!(cond)) {                                                                            \
            ++i2d_check_failures;                                                                 \
            fprintf(stderr, "%s:%d: [%s] check failed: %s\n", __FILE__, __LINE__, (ctx), #cond); \
        }                                                                                         \
    } while (0)

/* The call just made answered INVALID_HANDLE (return value, if any, and last status)
 * with a non-empty message. Reads status and message before any other i2d_ call. */
static void check_handle_refused_at(int line, const char* ctx, const char* call, i2d_status returned) {
    char what[512];
    snprintf(what, sizeof what, "[%s] %s", ctx, call);
    check_refused_at(__FILE__, line, what, returned, I2D_ERR_INVALID_HANDLE);
}
/* For calls that return a status. */
#define CHECK_HANDLE_REFUSED(ctx, call) check_handle_refused_at(__LINE__, (ctx), #call, (call))
/* For getters and creators: only the recorded status. */
#define CHECK_LAST_HANDLE_REFUSED(ctx, call) check_handle_refused_at(__LINE__, (ctx), (call), i2d_last_status())

static bool count_calls(i2d_shape_id shape, void* context) {
    (void)shape;
    ++*(int*)context;
    return true;
}

static bool is_zero_vec(i2d_vec2 v) { return v.x == 0.0f && v.y == 0.0f; }

static bool is_zero_aabb(i2d_aabb b) { return is_zero_vec(b.min) && is_zero_vec(b.max); }

/* Distinct values, so that a refused setter that hits a real object by mistake shows. */
static int k_marker;
static const i2d_vec2 k_odd_velocity = {12.5f, -7.25f};
static const float k_odd_friction = 0.123f;
static const float k_odd_restitution = 0.456f;

/* ---- Every call on a bad id ----------------------------------------------------------- */

/* Calls every function that takes a world id; each must refuse, and getters give zeros. */
static void check_world_id_refused(i2d_world_id w, const char* ctx) {
    const i2d_query_filter filter = i2d_default_query_filter();
    const i2d_aabb everything = box(-1000.0f, -1000.0f, 1000.0f, 1000.0f);

    CHECK_IN(ctx, !i2d_world_is_valid(w));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_is_valid");
    CHECK_HANDLE_REFUSED(ctx, i2d_world_step(w, 1.0f / 60.0f, 4));
    CHECK_HANDLE_REFUSED(ctx, i2d_world_set_gravity(w, v2(1.0f, 2.0f)));
    CHECK_HANDLE_REFUSED(ctx, i2d_world_shift_origin(w, v2(1.0f, 2.0f)));
    i2d_vec2 g = i2d_world_get_gravity(w);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_get_gravity");
    CHECK_IN(ctx, is_zero_vec(g));
    i2d_world_counters counters = i2d_world_get_counters(w);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_get_counters");
    CHECK_IN(ctx, counters.body_count == 0 && counters.shape_count == 0 && counters.contact_count == 0 &&
                      counters.pair_count == 0);
    const uint64_t hash = i2d_world_get_state_hash(w);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_get_state_hash");
    CHECK_IN(ctx, hash == 0);
    const i2d_simd_path path = i2d_world_get_simd_path(w);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_get_simd_path");
    CHECK_IN(ctx, path == I2D_SIMD_SCALAR);

    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_body_id body = i2d_body_create(w, &body_def);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_create");
    CHECK_IN(ctx, I2D_IS_NULL(body));

    int calls = 0;
    CHECK_HANDLE_REFUSED(ctx, i2d_world_overlap_aabb(w, everything, filter, count_calls, &calls));
    CHECK_HANDLE_REFUSED(ctx, i2d_world_overlap_point(w, v2(0.0f, 0.0f), filter, count_calls, &calls));
    CHECK_IN(ctx, calls == 0);
    i2d_shape_id out[4];
    out[0].bits = 777;
    int32_t n = i2d_world_overlap_aabb_ids(w, everything, filter, out, 4);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_overlap_aabb_ids");
    CHECK_IN(ctx, n == -1);
    CHECK_IN(ctx, out[0].bits == 777);
    i2d_ray_result ray = i2d_world_cast_ray_closest(w, v2(0.0f, 100.0f), v2(0.0f, -200.0f), filter);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_world_cast_ray_closest");
    CHECK_IN(ctx, !ray.hit && I2D_IS_NULL(ray.shape) && ray.fraction == 0.0f);

    CHECK_HANDLE_REFUSED(ctx, i2d_world_destroy(w));
}

/* Calls every function that takes a body id. */
static void check_body_id_refused(i2d_body_id b, const char* ctx) {
    CHECK_IN(ctx, !i2d_body_is_valid(b));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_is_valid");
    i2d_world_id world = i2d_body_get_world(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_world");
    CHECK_IN(ctx, I2D_IS_NULL(world));
    i2d_body_type type = i2d_body_get_type(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_type");
    CHECK_IN(ctx, type == (i2d_body_type)0);
    i2d_vec2 p = i2d_body_get_position(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_position");
    CHECK_IN(ctx, is_zero_vec(p));
    i2d_rot q = i2d_body_get_rotation(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_rotation");
    CHECK_IN(ctx, q.c == 0.0f && q.s == 0.0f); /* the zero value, not identity */
    i2d_transform t = i2d_body_get_transform(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_transform");
    CHECK_IN(ctx, is_zero_vec(t.p) && t.q.c == 0.0f && t.q.s == 0.0f);
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_transform(b, v2(4.0f, 5.0f), (i2d_rot){1.0f, 0.0f}));
    i2d_vec2 v = i2d_body_get_linear_velocity(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_linear_velocity");
    CHECK_IN(ctx, is_zero_vec(v));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_linear_velocity(b, k_odd_velocity));
    float w = i2d_body_get_angular_velocity(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_angular_velocity");
    CHECK_IN(ctx, w == 0.0f);
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_angular_velocity(b, 0.0f));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_angular_velocity(b, 2.5f));
    float mass = i2d_body_get_mass(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_mass");
    CHECK_IN(ctx, mass == 0.0f);
    float inertia = i2d_body_get_rotational_inertia(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_rotational_inertia");
    CHECK_IN(ctx, inertia == 0.0f);
    i2d_vec2 com = i2d_body_get_world_center_of_mass(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_world_center_of_mass");
    CHECK_IN(ctx, is_zero_vec(com));
    com = i2d_body_get_local_center_of_mass(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_local_center_of_mass");
    CHECK_IN(ctx, is_zero_vec(com));
    i2d_vec2 point = i2d_body_get_world_point(b, v2(1.0f, 2.0f));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_world_point");
    CHECK_IN(ctx, is_zero_vec(point));
    point = i2d_body_get_local_point(b, v2(1.0f, 2.0f));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_local_point");
    CHECK_IN(ctx, is_zero_vec(point));
    point = i2d_body_get_world_point_velocity(b, v2(1.0f, 2.0f));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_world_point_velocity");
    CHECK_IN(ctx, is_zero_vec(point));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_apply_force(b, v2(100.0f, 0.0f), v2(0.0f, 0.0f), true));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_apply_force_to_center(b, v2(100.0f, 0.0f), true));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_apply_torque(b, 100.0f, true));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_apply_linear_impulse(b, v2(100.0f, 0.0f), v2(0.0f, 0.0f), true));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_apply_angular_impulse(b, 100.0f, true));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_awake(b, false));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_awake(b, true));
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_type(b, I2D_BODY_DYNAMIC));
    bool awake = i2d_body_is_awake(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_is_awake");
    CHECK_IN(ctx, !awake);
    bool quarantined = i2d_body_is_quarantined(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_is_quarantined");
    CHECK_IN(ctx, !quarantined);
    void* data = i2d_body_get_user_data(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_user_data");
    CHECK_IN(ctx, data == NULL);
    CHECK_HANDLE_REFUSED(ctx, i2d_body_set_user_data(b, &k_marker));
    int32_t count = i2d_body_get_shape_count(b);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_shape_count");
    CHECK_IN(ctx, count == 0);
    i2d_shape_id shapes[2] = {{555}, {555}};
    count = i2d_body_get_shapes(b, shapes, 2);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_body_get_shapes");
    CHECK_IN(ctx, count == 0);
    CHECK_IN(ctx, shapes[0].bits == 555 && shapes[1].bits == 555);

    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_circle circle = {{0.0f, 0.0f}, 1.0f};
    i2d_shape_id shape = i2d_shape_create_circle(b, &shape_def, &circle);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_circle");
    CHECK_IN(ctx, I2D_IS_NULL(shape));
    shape = i2d_shape_create_box(b, &shape_def, 1.0f, 1.0f);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_box");
    CHECK_IN(ctx, I2D_IS_NULL(shape));
    shape = i2d_shape_create_offset_box(b, &shape_def, 1.0f, 1.0f, v2(1.0f, 0.0f), i2d_make_rot(0.5f));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_offset_box");
    CHECK_IN(ctx, I2D_IS_NULL(shape));
    const i2d_vec2 triangle[3] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
    shape = i2d_shape_create_polygon(b, &shape_def, triangle, 3);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_polygon");
    CHECK_IN(ctx, I2D_IS_NULL(shape));
    const i2d_polygon square = i2d_make_box(1.0f, 1.0f);
    shape = i2d_shape_create_polygon_from(b, &shape_def, &square);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_polygon_from");
    CHECK_IN(ctx, I2D_IS_NULL(shape));
    shape = i2d_shape_create_capsule(b, &shape_def, v2(-1.0f, 0.0f), v2(1.0f, 0.0f), 0.5f);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_capsule");
    CHECK_IN(ctx, I2D_IS_NULL(shape));
    shape = i2d_shape_create_segment(b, &shape_def, v2(-1.0f, 0.0f), v2(1.0f, 0.0f));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_create_segment");
    CHECK_IN(ctx, I2D_IS_NULL(shape));

    CHECK_HANDLE_REFUSED(ctx, i2d_body_destroy(b));
}

/* Calls every function that takes a shape id. */
static void check_shape_id_refused(i2d_shape_id s, const char* ctx) {
    CHECK_IN(ctx, !i2d_shape_is_valid(s));
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_is_valid");
    i2d_body_id body = i2d_shape_get_body(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_body");
    CHECK_IN(ctx, I2D_IS_NULL(body));
    i2d_shape_type type = i2d_shape_get_type(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_type");
    CHECK_IN(ctx, type == (i2d_shape_type)0);
    i2d_circle circle = i2d_shape_get_circle(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_circle");
    CHECK_IN(ctx, is_zero_vec(circle.center) && circle.radius == 0.0f);
    i2d_polygon polygon = i2d_shape_get_polygon(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_polygon");
    CHECK_IN(ctx, polygon.count == 0 && is_zero_vec(polygon.vertices[0]) && polygon.radius == 0.0f);
    i2d_capsule capsule = i2d_shape_get_capsule(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_capsule");
    CHECK_IN(ctx, is_zero_vec(capsule.center1) && is_zero_vec(capsule.center2) && capsule.radius == 0.0f);
    i2d_segment segment = i2d_shape_get_segment(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_segment");
    CHECK_IN(ctx, is_zero_vec(segment.point1) && is_zero_vec(segment.point2));
    i2d_aabb bounds = i2d_shape_get_aabb(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_aabb");
    CHECK_IN(ctx, is_zero_aabb(bounds));
    float density = i2d_shape_get_density(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_density");
    CHECK_IN(ctx, density == 0.0f);
    float friction = i2d_shape_get_friction(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_friction");
    CHECK_IN(ctx, friction == 0.0f);
    CHECK_HANDLE_REFUSED(ctx, i2d_shape_set_friction(s, k_odd_friction));
    float restitution = i2d_shape_get_restitution(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_restitution");
    CHECK_IN(ctx, restitution == 0.0f);
    CHECK_HANDLE_REFUSED(ctx, i2d_shape_set_restitution(s, k_odd_restitution));
    i2d_filter filter = i2d_shape_get_filter(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_filter");
    CHECK_IN(ctx, filter.category_bits == 0 && filter.mask_bits == 0 && filter.group_index == 0);
    i2d_filter odd_filter = {0x40, 0x40, -9};
    CHECK_HANDLE_REFUSED(ctx, i2d_shape_set_filter(s, odd_filter));
    bool sensor = i2d_shape_is_sensor(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_is_sensor");
    CHECK_IN(ctx, !sensor);
    void* data = i2d_shape_get_user_data(s);
    CHECK_LAST_HANDLE_REFUSED(ctx, "i2d_shape_get_user_data");
    CHECK_IN(ctx, data == NULL);
    CHECK_HANDLE_REFUSED(ctx, i2d_shape_set_user_data(s, &k_marker));
    CHECK_HANDLE_REFUSED(ctx, i2d_shape_destroy(s));
}

/* ---- A small world whose live objects must survive the bad calls ------------------- */

enum { SCENE_BODIES = 3 };

typedef struct scene {
    i2d_world_id world;
    i2d_body_id body[SCENE_BODIES]; /* static ground, dynamic ball, kinematic mover */
    i2d_shape_id shape[SCENE_BODIES]; /* one per body, same index */
} scene;

static int k_body_tags[SCENE_BODIES];

/* Creates the bodies first, then the shapes, so that body i and shape i likely share a
 * slot index: only the kind tag and generations tell their ids apart. */
static bool scene_create(scene* s) {
    memset(s, 0, sizeof *s);
    i2d_world_def world_def = i2d_default_world_def();
    s->world = i2d_world_create(&world_def);
    if (I2D_IS_NULL(s->world)) {
        return false;
    }
    static const i2d_body_type types[SCENE_BODIES] = {I2D_BODY_STATIC, I2D_BODY_DYNAMIC, I2D_BODY_KINEMATIC};
    for (int i = 0; i < SCENE_BODIES; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = types[i];
        def.position = v2(3.0f * (float)i, 1.0f);
        def.user_data = &k_body_tags[i];
        s->body[i] = i2d_body_create(s->world, &def);
    }
    i2d_shape_def shape_def = i2d_default_shape_def();
    for (int i = 0; i < SCENE_BODIES; ++i) {
        i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
        s->shape[i] = i2d_shape_create_circle(s->body[i], &shape_def, &circle);
        if (I2D_IS_NULL(s->body[i]) || I2D_IS_NULL(s->shape[i])) {
            return false;
        }
    }
    return true;
}

static void scene_destroy(scene* s) {
    if (!I2D_IS_NULL(s->world)) {
        i2d_world_destroy(s->world);
    }
}

/* The live objects of the scene are as scene_create left them. */
static void check_scene_intact(const scene* s, const char* ctx) {
    CHECK_IN(ctx, i2d_world_is_valid(s->world));
    i2d_vec2 g = i2d_world_get_gravity(s->world);
    CHECK_IN(ctx, g.x == 0.0f && g.y == -10.0f);
    i2d_world_counters counters = i2d_world_get_counters(s->world);
    CHECK_IN(ctx, counters.body_count == SCENE_BODIES && counters.shape_count == SCENE_BODIES);
    for (int i = 0; i < SCENE_BODIES; ++i) {
        CHECK_IN(ctx, i2d_body_is_valid(s->body[i]));
        i2d_vec2 p = i2d_body_get_position(s->body[i]);
        CHECK_IN(ctx, p.x == 3.0f * (float)i && p.y == 1.0f);
        CHECK_IN(ctx, is_zero_vec(i2d_body_get_linear_velocity(s->body[i])));
        CHECK_IN(ctx, i2d_body_get_angular_velocity(s->body[i]) == 0.0f);
        i2d_rot q = i2d_body_get_rotation(s->body[i]);
        CHECK_IN(ctx, q.c == 1.0f && q.s == 0.0f);
        CHECK_IN(ctx, i2d_body_get_user_data(s->body[i]) == &k_body_tags[i]);
        CHECK_IN(ctx, i2d_body_get_shape_count(s->body[i]) == 1);
        CHECK_IN(ctx, i2d_shape_is_valid(s->shape[i]));
        CHECK_IN(ctx, i2d_shape_get_friction(s->shape[i]) == 0.6f);
        CHECK_IN(ctx, i2d_shape_get_restitution(s->shape[i]) == 0.0f);
        CHECK_IN(ctx, i2d_shape_get_user_data(s->shape[i]) == NULL);
        CHECK_IN(ctx, i2d_shape_get_filter(s->shape[i]).group_index == 0);
    }
}

/* ---- Tests ---------------------------------------------------------------------------- */

I2D_TEST(api_ids_null) {
    scene s;
    bool built = scene_create(&s);
    CHECK_IN("scene", built);
    check_world_id_refused(I2D_NULL_WORLD_ID, "null world");
    check_body_id_refused(I2D_NULL_BODY_ID, "null body");
    check_shape_id_refused(I2D_NULL_SHAPE_ID, "null shape");
    if (built) {
        check_scene_intact(&s, "after the null-id calls");
    }
    scene_destroy(&s);
}

I2D_TEST(api_ids_stale_after_body_destroy) {
    scene s;
    if (scene_create(&s)) {
        i2d_body_id ball = s.body[1];
        i2d_shape_id ball_shape = s.shape[1];
        I2D_CHECK_STATUS(i2d_body_destroy(ball), I2D_OK);
        check_body_id_refused(ball, "destroyed body");
        /* Destroying a body destroys its shapes: their ids go stale too. */
        check_shape_id_refused(ball_shape, "shape of a destroyed body");
        i2d_world_counters counters = i2d_world_get_counters(s.world);
        I2D_CHECK(counters.body_count == SCENE_BODIES - 1 && counters.shape_count == SCENE_BODIES - 1);
        /* The other objects are untouched. */
        I2D_CHECK(i2d_body_is_valid(s.body[0]) && i2d_body_is_valid(s.body[2]));
        I2D_CHECK(i2d_shape_is_valid(s.shape[0]) && i2d_shape_is_valid(s.shape[2]));

        /* A new body likely reuses the slot; the old id must stay stale. */
        i2d_body_def def = i2d_default_body_def();
        i2d_body_id fresh = i2d_body_create(s.world, &def);
        I2D_CHECK(i2d_body_is_valid(fresh));
        I2D_CHECK(!I2D_ID_EQUALS(fresh, ball));
        check_body_id_refused(ball, "destroyed body after its slot is reused");
        I2D_CHECK(i2d_body_is_valid(fresh)); /* the refused calls did not hit the new body */
        I2D_CHECK(i2d_body_get_user_data(fresh) == NULL);
    } else {
        I2D_CHECK(!"scene_create");
    }
    scene_destroy(&s);
}

I2D_TEST(api_ids_stale_after_shape_destroy) {
    scene s;
    if (scene_create(&s)) {
        i2d_shape_id shape = s.shape[1];
        I2D_CHECK_STATUS(i2d_shape_destroy(shape), I2D_OK);
        check_shape_id_refused(shape, "destroyed shape");
        I2D_CHECK(i2d_body_is_valid(s.body[1]));
        I2D_CHECK(i2d_body_get_shape_count(s.body[1]) == 0);
        I2D_CHECK(i2d_world_get_counters(s.world).shape_count == SCENE_BODIES - 1);

        i2d_shape_def def = i2d_default_shape_def();
        i2d_shape_id fresh = i2d_shape_create_box(s.body[1], &def, 0.5f, 0.5f);
        I2D_CHECK(i2d_shape_is_valid(fresh));
        check_shape_id_refused(shape, "destroyed shape after its slot is reused");
        I2D_CHECK(i2d_shape_is_valid(fresh));
        I2D_CHECK(i2d_shape_get_friction(fresh) == 0.6f);
    } else {
        I2D_CHECK(!"scene_create");
    }
    scene_destroy(&s);
}

I2D_TEST(api_ids_stale_after_world_destroy) {
    scene s;
    if (scene_create(&s)) {
        I2D_CHECK_STATUS(i2d_world_destroy(s.world), I2D_OK);
        check_world_id_refused(s.world, "destroyed world");
        for (int i = 0; i < SCENE_BODIES; ++i) {
            check_body_id_refused(s.body[i], "body of a destroyed world");
            check_shape_id_refused(s.shape[i], "shape of a destroyed world");
        }
    } else {
        I2D_CHECK(!"scene_create");
        scene_destroy(&s);
    }
}

/* Worlds created and destroyed in a loop, keeping every old id: none may become valid
 * again, even when a new world takes the old one's slot and its bodies and shapes take
 * the same slot indices. Slots are taken round robin, so the tests hold every slot but
 * one with live worlds: each new world then really reuses the last one's slot. */
enum { RECYCLE_ROUNDS = 40, HELD_WORLDS = I2D_MAX_WORLDS - 1, SLOT_PERIOD = 255 };

static void check_capacity_refused_at(int line, const char* what);

static bool hold_all_slots_but_one(i2d_world_id* held) {
    for (int i = 0; i < HELD_WORLDS; ++i) {
        i2d_world_def def = i2d_default_world_def();
        held[i] = i2d_world_create(&def);
        if (I2D_IS_NULL(held[i])) {
            return false;
        }
    }
    return true;
}

static void release_held(i2d_world_id* held) {
    for (int i = 0; i < HELD_WORLDS; ++i) {
        if (!I2D_IS_NULL(held[i])) {
            I2D_CHECK_STATUS(i2d_world_destroy(held[i]), I2D_OK);
        }
    }
}

static void check_round_stale(const scene* old, int round) {
    char ctx[64];
    snprintf(ctx, sizeof ctx, "ids of round %d", round);
    CHECK_IN(ctx, !i2d_world_is_valid(old->world));
    for (int i = 0; i < SCENE_BODIES; ++i) {
        CHECK_IN(ctx, !i2d_body_is_valid(old->body[i]));
        CHECK_IN(ctx, !i2d_shape_is_valid(old->shape[i]));
        CHECK_IN(ctx, is_zero_vec(i2d_body_get_position(old->body[i])));
    }
}

I2D_TEST(api_ids_world_recycle) {
    static i2d_world_id held[HELD_WORLDS];
    I2D_REQUIRE(hold_all_slots_but_one(held));
    static scene rounds[RECYCLE_ROUNDS];
    for (int r = 0; r < RECYCLE_ROUNDS; ++r) {
        bool built = scene_create(&rounds[r]);
        CHECK_IN("recycled world", built);
        if (built) {
            check_scene_intact(&rounds[r], "new round");
        }
        for (int old = 0; old < r; ++old) {
            check_round_stale(&rounds[old], old);
            CHECK_IN("recycled world", !I2D_ID_EQUALS(rounds[old].world, rounds[r].world));
            CHECK_IN("recycled world", !I2D_ID_EQUALS(rounds[old].body[1], rounds[r].body[1]));
        }
        scene_destroy(&rounds[r]);
        check_round_stale(&rounds[r], r);
    }
    /* Every kind of call on the oldest ids, now that their slots have been reused. */
    check_world_id_refused(rounds[0].world, "world of round 0");
    check_body_id_refused(rounds[0].body[1], "body of round 0");
    check_shape_id_refused(rounds[0].shape[1], "shape of round 0");
    release_held(held);
}

/* The slot of a destroyed world, reused as often as its 8-bit generation allows before
 * it comes round (254 times): the old world's ids, bodies and shapes included, stay
 * refused every time. All other slots are held by live worlds, so the next world always
 * takes that one slot; creation then goes on across several wrap-arounds (no slot is
 * retired: a process may create worlds forever). */
static bool create_and_destroy_world(int cycle) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id w = i2d_world_create(&def);
    if (I2D_IS_NULL(w) || i2d_world_destroy(w) != I2D_OK) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: cycle %d: create or destroy failed: %s\n", __FILE__, __LINE__, cycle,
                i2d_last_error_message());
        return false;
    }
    return true;
}

I2D_TEST(api_ids_world_slot_reused_until_wrap) {
    static i2d_world_id held[HELD_WORLDS];
    I2D_REQUIRE(hold_all_slots_but_one(held));
    scene first;
    I2D_REQUIRE(scene_create(&first));
    scene_destroy(&first);
    int failures_before = i2d_check_failures;
    for (int c = 1; c < SLOT_PERIOD && i2d_check_failures == failures_before; ++c) {
        i2d_world_def def = i2d_default_world_def();
        i2d_world_id w = i2d_world_create(&def);
        I2D_CHECK(!I2D_ID_EQUALS(w, first.world));
        /* Same slot, as every other one is taken; its bodies take the same indices. */
        i2d_body_def body_def = i2d_default_body_def();
        i2d_body_id b = i2d_body_create(w, &body_def);
        I2D_CHECK(!I2D_ID_EQUALS(b, first.body[0]));
        check_round_stale(&first, 0);
        I2D_CHECK_STATUS(i2d_world_destroy(w), I2D_OK);
    }
    for (int c = 0; c < 3 * SLOT_PERIOD && i2d_check_failures == failures_before; ++c) {
        create_and_destroy_world(c);
    }
    /* The last free slot taken: the next world is refused, with the real reason. */
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id last = i2d_world_create(&def);
    I2D_CHECK(i2d_world_is_valid(last));
    check_capacity_refused_at(__LINE__, "the world past capacity, after wrap-arounds");
    I2D_CHECK(strstr(i2d_last_error_message(), "4096 worlds are alive") != NULL);
    I2D_CHECK_STATUS(i2d_world_destroy(last), I2D_OK);
    release_held(held);
}

/* A process may create and destroy worlds without limit (reinforcement learning and test
 * loops do). A registry that retired a slot whose generations ran out would refuse for
 * good after 1,044,480 cycles (4096 slots times 255 generations); the short test goes
 * just past that, the long one ten million cycles. */
static void create_worlds_forever(int cycles) {
    for (int c = 0; c < cycles; ++c) {
        if (!create_and_destroy_world(c)) {
            return;
        }
    }
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id w = i2d_world_create(&def);
    I2D_CHECK(i2d_world_is_valid(w));
    I2D_CHECK_STATUS(i2d_world_destroy(w), I2D_OK);
}

I2D_TEST(api_ids_world_create_past_the_old_cap) { create_worlds_forever(1100000); }

I2D_TEST(api_ids_world_create_forever_long_10m) { create_worlds_forever(10000000); }

/* Bodies created and destroyed many times in one world (more than a 16-bit slot
 * generation counts): the first id never becomes valid again. */
static void run_body_recycle(i2d_world_id world) {
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    i2d_body_id first = i2d_body_create(world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(first));
    I2D_CHECK_STATUS(i2d_body_destroy(first), I2D_OK);
    enum { CYCLES = 70000 };
    for (int c = 0; c < CYCLES; ++c) {
        i2d_body_id b = i2d_body_create(world, &def);
        if (I2D_IS_NULL(b) || I2D_ID_EQUALS(b, first) || i2d_body_is_valid(first)) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: cycle %d: new body null, equal to the first id, or first id valid again\n",
                    __FILE__, __LINE__, c);
            return;
        }
        if (i2d_body_destroy(b) != I2D_OK) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: cycle %d: destroy failed\n", __FILE__, __LINE__, c);
            return;
        }
    }
    I2D_CHECK(i2d_world_get_counters(world).body_count == 0);
    check_body_id_refused(first, "first body after 70000 recycles");
}

I2D_TEST(api_ids_body_slot_recycle) { run_in_default_world(run_body_recycle); }

/* An id of one kind passed where another is expected: refused, and the object the bits
 * really name is untouched. */
I2D_TEST(api_ids_foreign_kind) {
    scene s;
    if (scene_create(&s)) {
        for (int i = 0; i < SCENE_BODIES; ++i) {
            i2d_body_id shape_as_body = {s.shape[i].bits};
            i2d_shape_id body_as_shape = {s.body[i].bits};
            i2d_world_id body_as_world = {s.body[i].bits};
            i2d_world_id shape_as_world = {s.shape[i].bits};
            check_body_id_refused(shape_as_body, "shape id as body id");
            check_shape_id_refused(body_as_shape, "body id as shape id");
            check_world_id_refused(body_as_world, "body id as world id");
            check_world_id_refused(shape_as_world, "shape id as world id");
            check_scene_intact(&s, "after foreign ids");
        }
        i2d_body_id world_as_body = {s.world.bits};
        i2d_shape_id world_as_shape = {s.world.bits};
        check_body_id_refused(world_as_body, "world id as body id");
        check_shape_id_refused(world_as_shape, "world id as shape id");
        check_scene_intact(&s, "after foreign ids");
    } else {
        I2D_CHECK(!"scene_create");
    }
    scene_destroy(&s);
}

/* Two worlds at once: ids name their own world only. */
static void run_two_worlds(scene* a, scene* b) {
    for (int i = 0; i < SCENE_BODIES; ++i) {
        I2D_CHECK(I2D_ID_EQUALS(i2d_body_get_world(a->body[i]), a->world));
        I2D_CHECK(I2D_ID_EQUALS(i2d_body_get_world(b->body[i]), b->world));
        I2D_CHECK(!I2D_ID_EQUALS(a->body[i], b->body[i]));
        I2D_CHECK(!I2D_ID_EQUALS(a->shape[i], b->shape[i]));
        I2D_CHECK(I2D_ID_EQUALS(i2d_shape_get_body(a->shape[i]), a->body[i]));
    }
    I2D_CHECK(!I2D_ID_EQUALS(a->world, b->world));

    /* A change through A's id shows in A only. */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(a->body[1], v2(4.0f, 0.0f)), I2D_OK);
    I2D_CHECK(i2d_body_get_linear_velocity(a->body[1]).x == 4.0f);
    I2D_CHECK(i2d_body_get_linear_velocity(b->body[1]).x == 0.0f);
    I2D_CHECK_STATUS(i2d_body_destroy(a->body[2]), I2D_OK);
    I2D_CHECK(i2d_body_is_valid(b->body[2]));
    I2D_CHECK(i2d_world_get_counters(a->world).body_count == SCENE_BODIES - 1);
    I2D_CHECK(i2d_world_get_counters(b->world).body_count == SCENE_BODIES);

    /* Destroying B leaves A's ids valid and B's stale. */
    I2D_CHECK_STATUS(i2d_world_destroy(b->world), I2D_OK);
    I2D_CHECK(i2d_body_is_valid(a->body[0]) && i2d_body_is_valid(a->body[1]));
    I2D_CHECK(I2D_ID_EQUALS(i2d_body_get_world(a->body[0]), a->world));
    check_body_id_refused(b->body[0], "body of the destroyed second world");
    check_shape_id_refused(b->shape[0], "shape of the destroyed second world");
    memset(&b->world, 0, sizeof b->world);
}

I2D_TEST(api_ids_two_worlds) {
    scene a, b;
    bool built_a = scene_create(&a);
    bool built_b = scene_create(&b);
    if (built_a && built_b) {
        run_two_worlds(&a, &b);
    } else {
        I2D_CHECK(!"scene_create");
    }
    scene_destroy(&a);
    scene_destroy(&b);
}

I2D_TEST(api_ids_double_destroy) {
    scene s;
    if (scene_create(&s)) {
        I2D_CHECK_STATUS(i2d_shape_destroy(s.shape[0]), I2D_OK);
        CHECK_HANDLE_REFUSED("second shape destroy", i2d_shape_destroy(s.shape[0]));
        I2D_CHECK_STATUS(i2d_body_destroy(s.body[1]), I2D_OK);
        CHECK_HANDLE_REFUSED("second body destroy", i2d_body_destroy(s.body[1]));
        /* The shape went with its body. */
        CHECK_HANDLE_REFUSED("destroying the shape of a destroyed body", i2d_shape_destroy(s.shape[1]));
        i2d_world_counters counters = i2d_world_get_counters(s.world);
        I2D_CHECK(counters.body_count == SCENE_BODIES - 1 && counters.shape_count == SCENE_BODIES - 2);
        I2D_CHECK_STATUS(i2d_world_destroy(s.world), I2D_OK);
        CHECK_HANDLE_REFUSED("second world destroy", i2d_world_destroy(s.world));
    } else {
        I2D_CHECK(!"scene_create");
        scene_destroy(&s);
    }
}

/* I2D_MAX_WORLDS alive at once; one more is refused until one is destroyed. */
enum { WORLD_CAPACITY = I2D_MAX_WORLDS };

static void destroy_worlds(i2d_world_id* worlds, int count) {
    for (int i = 0; i < count; ++i) {
        if (!I2D_IS_NULL(worlds[i])) {
            I2D_CHECK_STATUS(i2d_world_destroy(worlds[i]), I2D_OK);
            worlds[i].bits = 0;
        }
    }
}

static void check_capacity_refused_at(int line, const char* what) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id extra = i2d_world_create(&def);
    i2d_status last = i2d_last_status();
    const char* message = i2d_last_error_message();
    bool has_message = message != NULL && message[0] != '\0';
    if (!I2D_IS_NULL(extra) || last != I2D_ERR_CAPACITY || !has_message) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: world %s, status %s, %s; expected null id, I2D_ERR_CAPACITY and a message\n",
                __FILE__, line, what, I2D_IS_NULL(extra) ? "null" : "created", i2d_status_string(last),
                has_message ? "a message" : "no message");
    }
    if (!I2D_IS_NULL(extra)) {
        i2d_world_destroy(extra);
    }
}

I2D_TEST(api_ids_world_capacity) {
    static i2d_world_id worlds[WORLD_CAPACITY];
    int created = 0;
    for (int i = 0; i < WORLD_CAPACITY; ++i) {
        i2d_world_def def = i2d_default_world_def();
        worlds[i] = i2d_world_create(&def);
        if (!I2D_IS_NULL(worlds[i])) {
            ++created;
        }
    }
    I2D_CHECK(created == WORLD_CAPACITY);
    if (created == WORLD_CAPACITY) {
        check_capacity_refused_at(__LINE__, "the world past capacity");
        /* Freeing one slot lets exactly one more world in. */
        I2D_CHECK_STATUS(i2d_world_destroy(worlds[100]), I2D_OK);
        i2d_world_def def = i2d_default_world_def();
        worlds[100] = i2d_world_create(&def);
        I2D_CHECK(i2d_world_is_valid(worlds[100]));
        check_capacity_refused_at(__LINE__, "the world past capacity after one was replaced");
        /* The worlds still work while the registry is full. */
        i2d_body_def body_def = i2d_default_body_def();
        I2D_CHECK(!I2D_IS_NULL(i2d_body_create(worlds[WORLD_CAPACITY - 1], &body_def)));
    }
    destroy_worlds(worlds, WORLD_CAPACITY);

    i2d_world_def def = i2d_default_world_def();
    i2d_world_id again = i2d_world_create(&def);
    I2D_CHECK(i2d_world_is_valid(again));
    i2d_world_destroy(again);
}

I2D_TEST(api_ids_version) {
    uint32_t version = i2d_version();
    I2D_CHECK(version == (uint32_t)I2D_VERSION);
    I2D_CHECK(version >> 16 == I2D_VERSION_MAJOR);
    I2D_CHECK(((version >> 8) & 0xffu) == I2D_VERSION_MINOR);
    I2D_CHECK((version & 0xffu) == I2D_VERSION_PATCH);
}

I2D_TEST(api_ids_status_strings) {
    /* The doc promises a fixed English name; the enum's own names are the natural ones. */
    static const char* const names[] = {"I2D_OK",
                                        "I2D_ERR_INVALID_ARGUMENT",
                                        "I2D_ERR_INVALID_HANDLE",
                                        "I2D_ERR_WORLD_LOCKED",
                                        "I2D_ERR_CAPACITY",
                                        "I2D_ERR_OUT_OF_MEMORY"};
    static const i2d_status statuses[] = {I2D_OK,
                                          I2D_ERR_INVALID_ARGUMENT,
                                          I2D_ERR_INVALID_HANDLE,
                                          I2D_ERR_WORLD_LOCKED,
                                          I2D_ERR_CAPACITY,
                                          I2D_ERR_OUT_OF_MEMORY};
    enum { COUNT = sizeof statuses / sizeof statuses[0] };
    const char* strings[COUNT];
    for (int i = 0; i < COUNT; ++i) {
        strings[i] = i2d_status_string(statuses[i]);
        I2D_REQUIRE(strings[i] != NULL);
        I2D_CHECK(strings[i][0] != '\0');
        if (strcmp(strings[i], names[i]) != 0) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: i2d_status_string(%d) = \"%s\", expected \"%s\"\n", __FILE__, __LINE__, i,
                    strings[i], names[i]);
        }
    }
    for (int i = 0; i < COUNT; ++i) {
        for (int j = i + 1; j < COUNT; ++j) {
            I2D_CHECK(strcmp(strings[i], strings[j]) != 0);
        }
    }
    /* "Never NULL", even for a value the enum does not name. */
    I2D_CHECK(i2d_status_string((i2d_status)99) != NULL);
    I2D_CHECK(i2d_status_string((i2d_status)-1) != NULL);
}

I2D_TEST(api_ids_last_status_after_success) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(strcmp(i2d_last_error_message(), "") == 0);

    /* A failure sets a message; the next successful call clears status and message. */
    i2d_world_step(I2D_NULL_WORLD_ID, 1.0f / 60.0f, 4);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_last_error_message()[0] != '\0');
    i2d_vec2 g = i2d_world_get_gravity(world);
    I2D_CHECK(g.x == 0.0f && g.y == -10.0f);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(strcmp(i2d_last_error_message(), "") == 0);

    i2d_world_step(world, NAN, 4);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    i2d_body_def body_def = i2d_default_body_def();
    i2d_body_id body = i2d_body_create(world, &body_def);
    I2D_CHECK(!I2D_IS_NULL(body));
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(strcmp(i2d_last_error_message(), "") == 0);

    i2d_body_get_mass(I2D_NULL_BODY_ID);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_world_step(world, 1.0f / 60.0f, 4) == I2D_OK);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(strcmp(i2d_last_error_message(), "") == 0);
    i2d_world_destroy(world);
}

/* Every kind of id reads the same as a signed and an unsigned 64-bit integer: bindings
 * that get ids as signed from returns and unsigned from event arrays (JavaScript's
 * BigInt, Java's long) compare them equal. The last world slot and a high generation
 * fill the other bits. */
static bool top_bit_clear(uint64_t bits) { return (bits >> 63) == 0; }

I2D_TEST(api_ids_top_bit_is_clear_for_every_kind) {
    static i2d_world_id held[I2D_MAX_WORLDS - 1];
    int count = 0;
    for (; count < I2D_MAX_WORLDS - 1; ++count) {
        i2d_world_def def = i2d_default_world_def();
        held[count] = i2d_world_create(&def);
        I2D_CHECK(top_bit_clear(held[count].bits));
    }
    i2d_world_id world = make_world(-10.0f); /* the last slot */
    I2D_REQUIRE(!I2D_IS_NULL(world));
    I2D_CHECK(top_bit_clear(world.bits));
    i2d_body_id a = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    i2d_body_id b = make_body(world, I2D_BODY_STATIC, 1.0f, 0.0f);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_shape_id shape = i2d_shape_create_box(a, &shape_def, 0.5f, 0.5f);
    i2d_revolute_joint_def joint_def = i2d_default_revolute_joint_def();
    joint_def.base.body_a = a;
    joint_def.base.body_b = b;
    i2d_joint_id joint = i2d_joint_create_revolute(world, &joint_def);
    const i2d_vec2 points[4] = {v2(3, 0), v2(2, 0), v2(-2, 0), v2(-3, 0)};
    i2d_chain_def chain_def = i2d_default_chain_def();
    chain_def.points = points;
    chain_def.count = 4;
    i2d_chain_id chain = i2d_chain_create(b, &chain_def);
    I2D_CHECK(!I2D_IS_NULL(joint) && !I2D_IS_NULL(chain) && !I2D_IS_NULL(shape));
    I2D_CHECK(top_bit_clear(a.bits) && top_bit_clear(shape.bits) && top_bit_clear(joint.bits) &&
              top_bit_clear(chain.bits));
    i2d_world_destroy(world);
    destroy_worlds(held, count);
}
