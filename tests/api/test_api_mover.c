/* SPDX-License-Identifier: MIT */
/* The character mover's refusals (toolkit.h): NaN and infinities in every vector and
 * float, a negative time step and a move too long, bad and stale ids, NULL pointers, a
 * def not made by i2d_default_character_def or out of its ranges, a bad capsule, bad
 * planes; each answered by a status and a message, with out zeroed and the world's state
 * hash as it was. A move that pushes is refused inside a query callback; one that does
 * not push, and the casts and collides, are queries and answer there. */
#include <impulse2d/impulse2d.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

/* A ground, and a dynamic crate right in front of a character walking into it: a move
 * accepted with pushing on changes the world, so an unchanged hash means a refusal
 * really left it alone. */
typedef struct mover_scene {
    i2d_world_id world;
    i2d_body_id crate;
    i2d_capsule capsule;
    i2d_vec2 position;
    i2d_vec2 velocity;
} mover_scene;

static const float k_non_finite_values[3] = {NAN, INFINITY, -INFINITY};

static bool scene_create(mover_scene* s) {
    const i2d_world_def def = i2d_default_world_def();
    s->world = i2d_world_create(&def);
    const i2d_shape_def sd = i2d_default_shape_def();
    const i2d_body_id ground = make_body(s->world, I2D_BODY_STATIC, 0.0f, -0.5f);
    s->crate = make_body(s->world, I2D_BODY_DYNAMIC, 1.0f, 0.5f);
    if (I2D_IS_NULL(i2d_shape_create_box(ground, &sd, 20.0f, 0.5f)) ||
        I2D_IS_NULL(i2d_shape_create_box(s->crate, &sd, 0.5f, 0.5f))) {
        return false;
    }
    s->capsule.center1 = v2(0.0f, 0.3f);
    s->capsule.center2 = v2(0.0f, 1.5f);
    s->capsule.radius = 0.3f;
    s->position = v2(0.185f, 0.014f); /* 1 cm from the crate's face at x = 0.5 */
    s->velocity = v2(3.0f, 0.0f);
    return true;
}

/* Whether every byte of the result is zero. */
static bool is_zeroed(const i2d_character_result* r) {
    static const i2d_character_result zero;
    return memcmp(r, &zero, sizeof zero) == 0;
}

/* A move refused with `expected`: status, message, out zeroed. */
static void check_move_refused_at(int line, const char* what, const mover_scene* s, const i2d_character_def* def,
                                  const i2d_capsule* capsule, i2d_vec2 position, i2d_vec2 velocity, float time_step,
                                  i2d_status expected) {
    i2d_character_result out;
    memset(&out, 0xAB, sizeof out);
    const i2d_status status = i2d_world_move_character(s->world, def, capsule, position, velocity, time_step, &out);
    check_refused_at(__FILE__, line, what, status, expected);
    if (!is_zeroed(&out)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: out was not zeroed\n", __FILE__, line, what);
    }
}
#define CHECK_MOVE_REFUSED(what, s, def, capsule, position, velocity, time_step, expected) \
    check_move_refused_at(__LINE__, (what), (s), (def), (capsule), (position), (velocity), (time_step), (expected))

I2D_TEST(api_mover_refuses_non_finite_input) {
    mover_scene s;
    I2D_REQUIRE(scene_create(&s));
    const uint64_t hash = i2d_world_get_state_hash(s.world);
    const i2d_character_def def = i2d_default_character_def();
    for (int k = 0; k < 3; ++k) {
        const float bad = k_non_finite_values[k];
        CHECK_MOVE_REFUSED("position.x", &s, &def, &s.capsule, v2(bad, 0.0f), s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
        CHECK_MOVE_REFUSED("position.y", &s, &def, &s.capsule, v2(0.0f, bad), s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
        CHECK_MOVE_REFUSED("velocity.x", &s, &def, &s.capsule, s.position, v2(bad, 0.0f), k_dt, I2D_ERR_INVALID_ARGUMENT);
        CHECK_MOVE_REFUSED("velocity.y", &s, &def, &s.capsule, s.position, v2(0.0f, bad), k_dt, I2D_ERR_INVALID_ARGUMENT);
        CHECK_MOVE_REFUSED("time_step", &s, &def, &s.capsule, s.position, s.velocity, bad, I2D_ERR_INVALID_ARGUMENT);
        i2d_capsule c = s.capsule;
        c.center1.y = bad;
        CHECK_MOVE_REFUSED("capsule center1", &s, &def, &c, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
        c = s.capsule;
        c.radius = bad;
        CHECK_MOVE_REFUSED("capsule radius", &s, &def, &c, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
        float* fields[] = {NULL, NULL, NULL, NULL, NULL};
        i2d_character_def d = def;
        fields[0] = &d.max_slope_angle;
        fields[1] = &d.step_height;
        fields[2] = &d.snap_distance;
        fields[3] = &d.skin;
        fields[4] = &d.push_mass;
        for (int f = 0; f < 5; ++f) {
            d = def;
            *fields[f] = bad;
            CHECK_MOVE_REFUSED("a def field", &s, &d, &s.capsule, s.position, s.velocity, k_dt,
                               I2D_ERR_INVALID_ARGUMENT);
        }
    }
    I2D_CHECK(i2d_world_get_state_hash(s.world) == hash);
    i2d_world_destroy(s.world);
}

I2D_TEST(api_mover_refuses_bad_time_steps_and_moves) {
    mover_scene s;
    I2D_REQUIRE(scene_create(&s));
    const uint64_t hash = i2d_world_get_state_hash(s.world);
    const i2d_character_def def = i2d_default_character_def();
    CHECK_MOVE_REFUSED("negative time step", &s, &def, &s.capsule, s.position, s.velocity, -k_dt,
                       I2D_ERR_INVALID_ARGUMENT);
    CHECK_MOVE_REFUSED("a time step of 2000 s", &s, &def, &s.capsule, s.position, s.velocity, 2000.0f,
                       I2D_ERR_INVALID_ARGUMENT);
    CHECK_MOVE_REFUSED("a move of 1.7e10 m", &s, &def, &s.capsule, s.position, v2(1e12f, 0.0f), k_dt,
                       I2D_ERR_INVALID_ARGUMENT);
    CHECK_MOVE_REFUSED("a position 2e9 m out", &s, &def, &s.capsule, v2(2e9f, 0.0f), s.velocity, k_dt,
                       I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_get_state_hash(s.world) == hash);
    i2d_world_destroy(s.world);
}

I2D_TEST(api_mover_refuses_bad_ids_and_null) {
    mover_scene s;
    I2D_REQUIRE(scene_create(&s));
    const uint64_t hash = i2d_world_get_state_hash(s.world);
    const i2d_character_def def = i2d_default_character_def();
    i2d_character_result out;

    mover_scene stale;
    I2D_REQUIRE(scene_create(&stale));
    i2d_world_destroy(stale.world);
    const i2d_world_id bad_worlds[] = {I2D_NULL_WORLD_ID, stale.world, {s.crate.bits}, {UINT64_C(0x123456789abcdef)}};
    for (size_t i = 0; i < sizeof bad_worlds / sizeof bad_worlds[0]; ++i) {
        memset(&out, 0xAB, sizeof out);
        check_refused_at(__FILE__, __LINE__, "a bad world id",
                         i2d_world_move_character(bad_worlds[i], &def, &s.capsule, s.position, s.velocity, k_dt, &out),
                         I2D_ERR_INVALID_HANDLE);
        I2D_CHECK(is_zeroed(&out));
        I2D_CHECK(i2d_world_cast_mover(bad_worlds[i], &s.capsule, v2(1, 0), i2d_default_query_filter()) == 0.0f);
        check_refused_at(__FILE__, __LINE__, "i2d_world_cast_mover(bad world)", i2d_last_status(),
                         I2D_ERR_INVALID_HANDLE);
        I2D_CHECK(i2d_world_collide_mover(bad_worlds[i], &s.capsule, i2d_default_query_filter(), NULL, 0) == 0);
        check_refused_at(__FILE__, __LINE__, "i2d_world_collide_mover(bad world)", i2d_last_status(),
                         I2D_ERR_INVALID_HANDLE);
    }
    CHECK_MOVE_REFUSED("def NULL", &s, NULL, &s.capsule, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    CHECK_MOVE_REFUSED("capsule NULL", &s, &def, NULL, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    check_refused_at(__FILE__, __LINE__, "out NULL",
                     i2d_world_move_character(s.world, &def, &s.capsule, s.position, s.velocity, k_dt, NULL),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_cast_mover(s.world, NULL, v2(1, 0), i2d_default_query_filter()) == 0.0f);
    check_refused_at(__FILE__, __LINE__, "i2d_world_cast_mover(NULL)", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_collide_mover(s.world, &s.capsule, i2d_default_query_filter(), NULL, 4) == 0);
    check_refused_at(__FILE__, __LINE__, "i2d_world_collide_mover(NULL out, capacity 4)", i2d_last_status(),
                     I2D_ERR_INVALID_ARGUMENT);
    i2d_collision_plane planes[2];
    I2D_CHECK(i2d_world_collide_mover(s.world, &s.capsule, i2d_default_query_filter(), planes, -1) == 0);
    check_refused_at(__FILE__, __LINE__, "i2d_world_collide_mover(capacity -1)", i2d_last_status(),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_get_state_hash(s.world) == hash);
    i2d_world_destroy(s.world);
}

I2D_TEST(api_mover_refuses_bad_defs_and_capsules) {
    mover_scene s;
    I2D_REQUIRE(scene_create(&s));
    const uint64_t hash = i2d_world_get_state_hash(s.world);
    const i2d_character_def good = i2d_default_character_def();
    i2d_character_def d;
    memset(&d, 0, sizeof d);
    CHECK_MOVE_REFUSED("a zeroed def", &s, &d, &s.capsule, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    d = good;
    d.internal_cookie ^= 1u;
    CHECK_MOVE_REFUSED("a def with a wrong cookie", &s, &d, &s.capsule, s.position, s.velocity, k_dt,
                       I2D_ERR_INVALID_ARGUMENT);
    const float slopes[] = {-0.01f, 1.5707964f, 2.0f};
    for (size_t i = 0; i < sizeof slopes / sizeof slopes[0]; ++i) {
        d = good;
        d.max_slope_angle = slopes[i];
        CHECK_MOVE_REFUSED("max_slope_angle outside [0, pi/2)", &s, &d, &s.capsule, s.position, s.velocity, k_dt,
                           I2D_ERR_INVALID_ARGUMENT);
    }
    d = good;
    d.skin = 0.0f;
    CHECK_MOVE_REFUSED("skin 0", &s, &d, &s.capsule, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    d = good;
    d.skin = -0.01f;
    CHECK_MOVE_REFUSED("skin -0.01", &s, &d, &s.capsule, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    d = good;
    d.step_height = -0.1f;
    CHECK_MOVE_REFUSED("step_height -0.1", &s, &d, &s.capsule, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    d = good;
    d.snap_distance = -0.1f;
    CHECK_MOVE_REFUSED("snap_distance -0.1", &s, &d, &s.capsule, s.position, s.velocity, k_dt,
                       I2D_ERR_INVALID_ARGUMENT);
    const int32_t iterations[] = {0, -1, 65};
    for (size_t i = 0; i < sizeof iterations / sizeof iterations[0]; ++i) {
        d = good;
        d.max_iterations = iterations[i];
        CHECK_MOVE_REFUSED("max_iterations outside [1, 64]", &s, &d, &s.capsule, s.position, s.velocity, k_dt,
                           I2D_ERR_INVALID_ARGUMENT);
    }
    d = good;
    d.push_mass = -1.0f;
    CHECK_MOVE_REFUSED("push_mass -1", &s, &d, &s.capsule, s.position, s.velocity, k_dt, I2D_ERR_INVALID_ARGUMENT);
    const float radii[] = {0.0f, -0.3f, 1e-5f, 2e5f};
    for (size_t i = 0; i < sizeof radii / sizeof radii[0]; ++i) {
        i2d_capsule c = s.capsule;
        c.radius = radii[i];
        CHECK_MOVE_REFUSED("a bad capsule radius", &s, &good, &c, s.position, s.velocity, k_dt,
                           I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(i2d_world_cast_mover(s.world, &c, v2(1, 0), i2d_default_query_filter()) == 0.0f);
        check_refused_at(__FILE__, __LINE__, "i2d_world_cast_mover(bad radius)", i2d_last_status(),
                         I2D_ERR_INVALID_ARGUMENT);
    }
    I2D_CHECK(i2d_world_get_state_hash(s.world) == hash);
    /* The same move, accepted, pushes the crate: the hash was worth watching. */
    i2d_character_result out;
    I2D_CHECK_STATUS(i2d_world_move_character(s.world, &good, &s.capsule, s.position, s.velocity, k_dt, &out), I2D_OK);
    I2D_CHECK(i2d_world_get_state_hash(s.world) != hash);
    i2d_world_destroy(s.world);
}

/* The pure calls: refused input gives zero and a status, and leaves the planes' pushes. */
I2D_TEST(api_mover_plane_calls_refuse_bad_planes) {
    i2d_collision_plane planes[2];
    const i2d_collision_plane floor = {{{0.0f, 1.0f}, 0.0f}, FLT_MAX, 7.0f, true};
    planes[0] = floor;
    planes[1] = floor;
    for (int k = 0; k < 3; ++k) {
        const float bad = k_non_finite_values[k];
        const i2d_plane_result r = i2d_solve_planes(v2(bad, 0.0f), planes, 2);
        check_refused_at(__FILE__, __LINE__, "i2d_solve_planes(non-finite delta)", i2d_last_status(),
                         I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(r.translation.x == 0.0f && r.translation.y == 0.0f && r.iteration_count == 0);
        const i2d_vec2 v = i2d_clip_vector(v2(1.0f, bad), planes, 2);
        check_refused_at(__FILE__, __LINE__, "i2d_clip_vector(non-finite vector)", i2d_last_status(),
                         I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(v.x == 0.0f && v.y == 0.0f);
        planes[1].plane.offset = bad;
        i2d_solve_planes(v2(0.0f, -1.0f), planes, 2);
        check_refused_at(__FILE__, __LINE__, "i2d_solve_planes(non-finite offset)", i2d_last_status(),
                         I2D_ERR_INVALID_ARGUMENT);
        planes[1] = floor;
        planes[1].plane.normal.x = bad;
        i2d_clip_vector(v2(0.0f, -1.0f), planes, 2);
        check_refused_at(__FILE__, __LINE__, "i2d_clip_vector(non-finite normal)", i2d_last_status(),
                         I2D_ERR_INVALID_ARGUMENT);
        planes[1] = floor;
        planes[1].push_limit = bad;
        i2d_solve_planes(v2(0.0f, -1.0f), planes, 2);
        check_refused_at(__FILE__, __LINE__, "i2d_solve_planes(bad push_limit)", i2d_last_status(),
                         I2D_ERR_INVALID_ARGUMENT);
        planes[1] = floor;
    }
    planes[1].plane.normal = v2(0.0f, 2.0f);
    i2d_solve_planes(v2(0.0f, -1.0f), planes, 2);
    check_refused_at(__FILE__, __LINE__, "i2d_solve_planes(normal of length 2)", i2d_last_status(),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(planes[0].push == 7.0f && planes[1].push == 7.0f); /* refused: untouched */
    planes[1] = floor;
    i2d_solve_planes(v2(0.0f, -1.0f), planes, -1);
    check_refused_at(__FILE__, __LINE__, "i2d_solve_planes(count -1)", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    i2d_solve_planes(v2(0.0f, -1.0f), NULL, 2);
    check_refused_at(__FILE__, __LINE__, "i2d_solve_planes(NULL, 2)", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    i2d_clip_vector(v2(0.0f, -1.0f), NULL, 1);
    check_refused_at(__FILE__, __LINE__, "i2d_clip_vector(NULL, 1)", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    /* Accepted: the floor pushes 1. */
    const i2d_plane_result r = i2d_solve_planes(v2(0.0f, -1.0f), planes, 2);
    I2D_CHECK_STATUS(i2d_last_status(), I2D_OK);
    I2D_CHECK(r.translation.y == 0.0f && planes[0].push + planes[1].push == 1.0f);
}

/* Inside a query callback the world is locked: a move that pushes is refused, one that
 * does not, and the casts and collides, answer. */
typedef struct locked_calls {
    mover_scene* scene;
    i2d_status pushing, not_pushing, cast, collide;
    int calls;
} locked_calls;

static bool call_mover_inside(i2d_shape_id shape, void* context) {
    (void)shape;
    locked_calls* c = (locked_calls*)context;
    mover_scene* s = c->scene;
    i2d_character_def def = i2d_default_character_def();
    i2d_character_result out;
    c->pushing = i2d_world_move_character(s->world, &def, &s->capsule, s->position, s->velocity, k_dt, &out);
    def.push_mass = 0.0f;
    c->not_pushing = i2d_world_move_character(s->world, &def, &s->capsule, s->position, s->velocity, k_dt, &out);
    i2d_world_cast_mover(s->world, &s->capsule, v2(1, 0), i2d_default_query_filter());
    c->cast = i2d_last_status();
    i2d_world_collide_mover(s->world, &s->capsule, i2d_default_query_filter(), NULL, 0);
    c->collide = i2d_last_status();
    ++c->calls;
    return false;
}

I2D_TEST(api_mover_pushing_refused_inside_query_callbacks) {
    mover_scene s;
    I2D_REQUIRE(scene_create(&s));
    const uint64_t hash = i2d_world_get_state_hash(s.world);
    locked_calls c = {&s, I2D_OK, I2D_OK, I2D_OK, I2D_OK, 0};
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(s.world, box(-1, -1, 2, 2), i2d_default_query_filter(), call_mover_inside, &c),
                     I2D_OK);
    I2D_REQUIRE(c.calls == 1);
    I2D_CHECK(c.pushing == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(c.not_pushing == I2D_OK);
    I2D_CHECK(c.cast == I2D_OK);
    I2D_CHECK(c.collide == I2D_OK);
    I2D_CHECK(i2d_world_get_state_hash(s.world) == hash);
    i2d_world_destroy(s.world);
}
