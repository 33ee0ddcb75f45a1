/* SPDX-License-Identifier: MIT */
/* C API bad input, part 3: the runtime setters of bodies, shapes and the world (issue 40).
 * Each refusal answers its status with a message and leaves the fixture as it was, every
 * getter's bits and the state hash included (test_api_errors.h); the twins then step alike,
 * which catches hidden state a refused call might have touched. */
#include "test_api_errors.h"
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- Values out of range -------------------------------------------------------------- */

/* A call with one argument replaced by `value`; every other argument is valid. */
typedef i2d_status (*runtime_call)(const fixture* f, float value);
typedef struct runtime_call_row {
    const char* name;
    runtime_call call;
} runtime_call_row;

static i2d_body_id ball(const fixture* f) { return f->body[FIX_BALL]; }
static i2d_body_id mover(const fixture* f) { return f->body[FIX_MOVER]; }
static i2d_shape_id ball_circle(const fixture* f) { return f->shape[FIX_BALL_CIRCLE]; }

static i2d_mass_data mass_data(float mass, float center_x, float inertia) {
    i2d_mass_data m;
    m.mass = mass;
    m.center = v2(center_x, 0.0f);
    m.rotational_inertia = inertia;
    return m;
}
static i2d_status call_mass(const fixture* f, float v) { return i2d_body_set_mass_data(ball(f), mass_data(v, 0, 1)); }
static i2d_status call_mass_center(const fixture* f, float v) {
    return i2d_body_set_mass_data(ball(f), mass_data(2.0f, v, 1.0f));
}
static i2d_status call_mass_inertia(const fixture* f, float v) {
    return i2d_body_set_mass_data(ball(f), mass_data(2.0f, 0.0f, v));
}
static i2d_transform target(float x, float c, float s) {
    i2d_transform t;
    t.p = v2(x, 2.0f);
    t.q = rot(c, s);
    return t;
}
static i2d_status call_target_x(const fixture* f, float v) {
    return i2d_body_set_target_transform(mover(f), target(v, 1, 0), k_dt);
}
static i2d_status call_target_qc(const fixture* f, float v) {
    return i2d_body_set_target_transform(mover(f), target(1, v, 0), k_dt);
}
static i2d_status call_target_step(const fixture* f, float v) {
    return i2d_body_set_target_transform(mover(f), target(1, 1, 0), v);
}
static i2d_status call_sleep_threshold(const fixture* f, float v) { return i2d_body_set_sleep_threshold(ball(f), v); }
static i2d_status call_gravity_scale(const fixture* f, float v) { return i2d_body_set_gravity_scale(ball(f), v); }
static i2d_status call_linear_damping(const fixture* f, float v) { return i2d_body_set_linear_damping(ball(f), v); }
static i2d_status call_angular_damping(const fixture* f, float v) { return i2d_body_set_angular_damping(ball(f), v); }
static i2d_status call_density(const fixture* f, float v) { return i2d_shape_set_density(ball_circle(f), v, true); }

static i2d_surface_material good_material(void) {
    i2d_surface_material m;
    m.friction = 0.5f;
    m.restitution = 0.1f;
    m.rolling_resistance = 0.0f;
    m.tangent_speed = 0.0f;
    return m;
}
static i2d_status call_material_field(const fixture* f, size_t offset, float v) {
    i2d_surface_material m = good_material();
    set_float_at(&m, offset, v);
    return i2d_shape_set_material(ball_circle(f), m);
}
static i2d_status call_friction(const fixture* f, float v) {
    return call_material_field(f, offsetof(i2d_surface_material, friction), v);
}
static i2d_status call_restitution(const fixture* f, float v) {
    return call_material_field(f, offsetof(i2d_surface_material, restitution), v);
}
static i2d_status call_rolling(const fixture* f, float v) {
    return call_material_field(f, offsetof(i2d_surface_material, rolling_resistance), v);
}
static i2d_status call_tangent_speed(const fixture* f, float v) {
    return call_material_field(f, offsetof(i2d_surface_material, tangent_speed), v);
}
static i2d_status call_circle_radius(const fixture* f, float v) {
    i2d_circle c;
    c.center = v2(0.0f, 0.0f);
    c.radius = v;
    return i2d_shape_set_circle(ball_circle(f), &c);
}
static i2d_status call_circle_center(const fixture* f, float v) {
    i2d_circle c;
    c.center = v2(v, 0.0f);
    c.radius = 0.5f;
    return i2d_shape_set_circle(ball_circle(f), &c);
}
static i2d_status call_capsule_radius(const fixture* f, float v) {
    i2d_capsule c;
    c.center1 = v2(-0.5f, 0.0f);
    c.center2 = v2(0.5f, 0.0f);
    c.radius = v;
    return i2d_shape_set_capsule(ball_circle(f), &c);
}
static i2d_status call_segment_end(const fixture* f, float v) {
    i2d_segment s;
    s.point1 = v2(0.0f, 0.0f);
    s.point2 = v2(v, 0.0f);
    return i2d_shape_set_segment(ball_circle(f), &s);
}
static i2d_status call_polygon_radius(const fixture* f, float v) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.radius = v;
    return i2d_shape_set_polygon(ball_circle(f), &p);
}
static i2d_status call_contact_hertz(const fixture* f, float v) {
    return i2d_world_set_contact_tuning(f->world, v, 10.0f, 3.0f);
}
static i2d_status call_contact_damping(const fixture* f, float v) {
    return i2d_world_set_contact_tuning(f->world, 30.0f, v, 3.0f);
}
static i2d_status call_push_speed(const fixture* f, float v) {
    return i2d_world_set_contact_tuning(f->world, 30.0f, 10.0f, v);
}
static i2d_status call_joint_hertz(const fixture* f, float v) { return i2d_world_set_joint_tuning(f->world, v, 2.0f); }
static i2d_status call_joint_damping(const fixture* f, float v) {
    return i2d_world_set_joint_tuning(f->world, 60.0f, v);
}
static i2d_status call_restitution_threshold(const fixture* f, float v) {
    return i2d_world_set_restitution_threshold(f->world, v);
}
static i2d_status call_hit_threshold(const fixture* f, float v) {
    return i2d_world_set_hit_event_threshold(f->world, v);
}

/* Every float argument of the runtime setters: each refuses NaN and both infinities. */
static const runtime_call_row k_runtime_float_calls[] = {
    {"i2d_body_set_mass_data mass", call_mass},
    {"i2d_body_set_mass_data center.x", call_mass_center},
    {"i2d_body_set_mass_data rotational_inertia", call_mass_inertia},
    {"i2d_body_set_target_transform p.x", call_target_x},
    {"i2d_body_set_target_transform q.c", call_target_qc},
    {"i2d_body_set_target_transform time_step", call_target_step},
    {"i2d_body_set_sleep_threshold", call_sleep_threshold},
    {"i2d_body_set_gravity_scale", call_gravity_scale},
    {"i2d_body_set_linear_damping", call_linear_damping},
    {"i2d_body_set_angular_damping", call_angular_damping},
    {"i2d_shape_set_density", call_density},
    {"i2d_shape_set_material friction", call_friction},
    {"i2d_shape_set_material restitution", call_restitution},
    {"i2d_shape_set_material rolling_resistance", call_rolling},
    {"i2d_shape_set_material tangent_speed", call_tangent_speed},
    {"i2d_shape_set_circle radius", call_circle_radius},
    {"i2d_shape_set_circle center.x", call_circle_center},
    {"i2d_shape_set_capsule radius", call_capsule_radius},
    {"i2d_shape_set_segment point2.x", call_segment_end},
    {"i2d_shape_set_polygon radius", call_polygon_radius},
    {"i2d_world_set_contact_tuning hertz", call_contact_hertz},
    {"i2d_world_set_contact_tuning damping_ratio", call_contact_damping},
    {"i2d_world_set_contact_tuning push_max_speed", call_push_speed},
    {"i2d_world_set_joint_tuning hertz", call_joint_hertz},
    {"i2d_world_set_joint_tuning damping_ratio", call_joint_damping},
    {"i2d_world_set_restitution_threshold", call_restitution_threshold},
    {"i2d_world_set_hit_event_threshold", call_hit_threshold},
};

typedef struct runtime_call_value {
    const char* name;
    runtime_call call;
    float value;
} runtime_call_value;

/* Finite values outside the documented ranges. */
static const runtime_call_value k_runtime_out_of_range[] = {
    {"i2d_body_set_mass_data mass", call_mass, 0.0f},
    {"i2d_body_set_mass_data mass", call_mass, -1.0f},
    {"i2d_body_set_mass_data mass", call_mass, 2e20f},
    {"i2d_body_set_mass_data center.x", call_mass_center, 2e5f},
    {"i2d_body_set_mass_data rotational_inertia", call_mass_inertia, -1.0f},
    {"i2d_body_set_mass_data rotational_inertia", call_mass_inertia, 2e30f},
    {"i2d_body_set_target_transform p.x", call_target_x, 2e9f},
    {"i2d_body_set_target_transform q.c (not unit)", call_target_qc, 0.5f},
    {"i2d_body_set_target_transform time_step", call_target_step, 0.0f},
    {"i2d_body_set_target_transform time_step", call_target_step, -1.0f / 60.0f},
    {"i2d_body_set_sleep_threshold", call_sleep_threshold, -0.01f},
    {"i2d_body_set_sleep_threshold", call_sleep_threshold, 2e5f},
    {"i2d_body_set_linear_damping", call_linear_damping, -0.1f},
    {"i2d_body_set_angular_damping", call_angular_damping, -0.1f},
    {"i2d_shape_set_density", call_density, -1.0f},
    {"i2d_shape_set_density", call_density, 2e10f},
    {"i2d_shape_set_material friction", call_friction, -0.1f},
    {"i2d_shape_set_material restitution", call_restitution, 100.5f},
    {"i2d_shape_set_material rolling_resistance", call_rolling, -1.0f},
    {"i2d_shape_set_material tangent_speed", call_tangent_speed, 2e5f},
    {"i2d_shape_set_circle radius", call_circle_radius, 0.0f},
    {"i2d_shape_set_circle radius", call_circle_radius, -0.5f},
    {"i2d_shape_set_circle center.x", call_circle_center, 2e5f},
    {"i2d_shape_set_capsule radius", call_capsule_radius, -1.0f},
    {"i2d_shape_set_segment point2.x (zero length)", call_segment_end, 0.0f},
    {"i2d_shape_set_polygon radius", call_polygon_radius, -0.1f},
    {"i2d_world_set_contact_tuning hertz", call_contact_hertz, 0.0f},
    {"i2d_world_set_contact_tuning damping_ratio", call_contact_damping, -1.0f},
    {"i2d_world_set_contact_tuning push_max_speed", call_push_speed, -1.0f},
    {"i2d_world_set_joint_tuning hertz", call_joint_hertz, 2e5f},
    {"i2d_world_set_joint_tuning damping_ratio", call_joint_damping, -0.5f},
    {"i2d_world_set_restitution_threshold", call_restitution_threshold, -1.0f},
    {"i2d_world_set_hit_event_threshold", call_hit_threshold, 2e5f},
};

static void run_runtime_setters_refused(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    char what[160];
    for (size_t i = 0; i < sizeof k_runtime_float_calls / sizeof k_runtime_float_calls[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            snprintf(what, sizeof what, "%s = %g", k_runtime_float_calls[i].name, k_non_finite[k]);
            CHECK_REFUSED(what, k_runtime_float_calls[i].call(a, k_non_finite[k]), I2D_ERR_INVALID_ARGUMENT);
            CHECK_UNCHANGED(what, a, &before);
        }
    }
    for (size_t i = 0; i < sizeof k_runtime_out_of_range / sizeof k_runtime_out_of_range[0]; ++i) {
        const runtime_call_value* row = &k_runtime_out_of_range[i];
        snprintf(what, sizeof what, "%s = %g", row->name, row->value);
        CHECK_REFUSED(what, row->call(a, row->value), I2D_ERR_INVALID_ARGUMENT);
        CHECK_UNCHANGED(what, a, &before);
    }
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_runtime_setters_bad_values) { run_on_twins(run_runtime_setters_refused); }

/* ---- Calls that do not apply to the body or shape they name ---------------------------- */

static void run_runtime_wrong_targets(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    /* Only a dynamic body has a mass to set; only a kinematic one moves to a target. */
    CHECK_REFUSED("i2d_body_set_mass_data(static)", i2d_body_set_mass_data(a->body[FIX_GROUND], mass_data(2, 0, 1)),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_body_set_mass_data(kinematic)", i2d_body_set_mass_data(mover(a), mass_data(2, 0, 1)),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_body_set_target_transform(dynamic)",
                  i2d_body_set_target_transform(ball(a), target(1, 1, 0), k_dt), I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_body_set_target_transform(static)",
                  i2d_body_set_target_transform(a->body[FIX_GROUND], target(1, 1, 0), k_dt),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("calls on the wrong kind of body", a, &before);
    /* NULL geometry. */
    CHECK_REFUSED("i2d_shape_set_circle(NULL)", i2d_shape_set_circle(ball_circle(a), NULL), I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_shape_set_capsule(NULL)", i2d_shape_set_capsule(ball_circle(a), NULL),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_shape_set_segment(NULL)", i2d_shape_set_segment(ball_circle(a), NULL),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_shape_set_polygon(NULL)", i2d_shape_set_polygon(ball_circle(a), NULL),
                  I2D_ERR_INVALID_ARGUMENT);
    /* A polygon that is not convex, or has a bad count. */
    {
        i2d_polygon p = i2d_make_box(0.5f, 0.5f);
        p.vertices[2] = v2(0.0f, 0.0f);
        CHECK_REFUSED("i2d_shape_set_polygon(not convex)", i2d_shape_set_polygon(ball_circle(a), &p),
                      I2D_ERR_INVALID_ARGUMENT);
        p = i2d_make_box(0.5f, 0.5f);
        p.count = 9;
        CHECK_REFUSED("i2d_shape_set_polygon(count 9)", i2d_shape_set_polygon(ball_circle(a), &p),
                      I2D_ERR_INVALID_ARGUMENT);
    }
    CHECK_UNCHANGED("bad geometry", a, &before);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_runtime_wrong_targets) { run_on_twins(run_runtime_wrong_targets); }

/* A chain's segment keeps its geometry: it shares ghost points with its neighbours. */
static void run_chain_segment_geometry_refused(i2d_world_id world) {
    i2d_body_id ground = make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    const i2d_vec2 points[5] = {{4.0f, 0.0f}, {2.0f, 0.0f}, {0.0f, 0.0f}, {-2.0f, 0.0f}, {-4.0f, 0.0f}};
    i2d_chain_def def = i2d_default_chain_def();
    def.points = points;
    def.count = 5;
    i2d_chain_id chain = i2d_chain_create(ground, &def);
    I2D_REQUIRE(!I2D_IS_NULL(chain));
    i2d_shape_id segments[4];
    I2D_REQUIRE(i2d_chain_get_segments(chain, segments, 4) >= 1);
    const uint64_t hash = i2d_world_get_state_hash(world);
    i2d_segment s;
    s.point1 = v2(0.0f, 0.0f);
    s.point2 = v2(1.0f, 0.0f);
    CHECK_REFUSED("i2d_shape_set_segment(chain segment)", i2d_shape_set_segment(segments[0], &s),
                  I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_shape_get_type(segments[0]) == I2D_SHAPE_CHAIN_SEGMENT);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
}

I2D_TEST(api_errors_runtime_chain_segment_geometry_refused) {
    run_in_world(-10.0f, run_chain_segment_geometry_refused);
}

/* ---- Stale ids -------------------------------------------------------------------------- */

I2D_TEST(api_errors_runtime_stale_ids) {
    i2d_world_id world = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_body_id body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_id shape = i2d_shape_create_box(body, &sd, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    I2D_REQUIRE(i2d_body_destroy(body) == I2D_OK);
    const i2d_status stale = I2D_ERR_INVALID_HANDLE;
    const i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    CHECK_REFUSED("set_mass_data", i2d_body_set_mass_data(body, mass_data(2, 0, 1)), stale);
    CHECK_REFUSED("apply_mass_from_shapes", i2d_body_apply_mass_from_shapes(body), stale);
    CHECK_REFUSED("set_target_transform", i2d_body_set_target_transform(body, target(0, 1, 0), k_dt), stale);
    CHECK_REFUSED("set_bullet", i2d_body_set_bullet(body, true), stale);
    CHECK_REFUSED("enable_sleep", i2d_body_enable_sleep(body, false), stale);
    CHECK_REFUSED("set_sleep_threshold", i2d_body_set_sleep_threshold(body, 0.1f), stale);
    CHECK_REFUSED("set_gravity_scale", i2d_body_set_gravity_scale(body, 0.0f), stale);
    CHECK_REFUSED("set_linear_damping", i2d_body_set_linear_damping(body, 1.0f), stale);
    CHECK_REFUSED("set_angular_damping", i2d_body_set_angular_damping(body, 1.0f), stale);
    CHECK_REFUSED("set_fixed_rotation", i2d_body_set_fixed_rotation(body, true), stale);
    CHECK_REFUSED("disable", i2d_body_disable(body), stale);
    CHECK_REFUSED("enable", i2d_body_enable(body), stale);
    CHECK_REFUSED("set_circle", i2d_shape_set_circle(shape, &circle), stale);
    CHECK_REFUSED("set_density", i2d_shape_set_density(shape, 2.0f, true), stale);
    CHECK_REFUSED("set_material", i2d_shape_set_material(shape, good_material()), stale);
    CHECK_REFUSED("enable_hit_events", i2d_shape_enable_hit_events(shape, true), stale);
    /* Getters give zero values and the same status. */
    I2D_CHECK(i2d_body_get_gravity_scale(body) == 0.0f && i2d_last_status() == stale);
    I2D_CHECK(i2d_body_get_mass_data(body).mass == 0.0f && i2d_last_status() == stale);
    I2D_CHECK(!i2d_body_is_enabled(body) && i2d_last_status() == stale);
    I2D_CHECK(!i2d_shape_are_contact_events_enabled(shape) && i2d_last_status() == stale);
    I2D_REQUIRE(i2d_world_destroy(world) == I2D_OK);
    CHECK_REFUSED("enable_sleeping (destroyed world)", i2d_world_enable_sleeping(world, false), stale);
    CHECK_REFUSED("set_user_data (destroyed world)", i2d_world_set_user_data(world, &world), stale);
    I2D_CHECK(i2d_world_get_settings(world).internal_cookie == 0 && i2d_last_status() == stale);
}

/* ---- Inside a query callback: every runtime setter is refused ---------------------------- */

typedef struct runtime_lock_probe {
    const fixture* f;
    const snapshot* before;
    bool probed;
} runtime_lock_probe;

#define CHECK_RUNTIME_LOCKED(f, before, call)                          \
    do {                                                               \
        CHECK_REFUSED(#call, (call), I2D_ERR_WORLD_LOCKED);            \
        CHECK_UNCHANGED(#call, (f), (before));                         \
    } while (0)

static void try_runtime_changes_while_locked(const fixture* f, const snapshot* before) {
    const i2d_circle circle = {{0.0f, 0.0f}, 0.75f};
    const i2d_polygon square = i2d_make_box(0.25f, 0.25f);
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_mass_data(ball(f), mass_data(2.0f, 0.0f, 1.0f)));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_apply_mass_from_shapes(ball(f)));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_target_transform(mover(f), target(1, 1, 0), k_dt));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_bullet(ball(f), true));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_enable_sleep(ball(f), false));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_sleep_threshold(ball(f), 1.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_gravity_scale(ball(f), 0.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_linear_damping(ball(f), 1.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_angular_damping(ball(f), 1.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_set_fixed_rotation(ball(f), true));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_disable(ball(f)));
    CHECK_RUNTIME_LOCKED(f, before, i2d_body_enable(ball(f)));  /* refused before it would be a no-op */
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_set_circle(ball_circle(f), &circle));
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_set_polygon(ball_circle(f), &square));
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_set_density(ball_circle(f), 3.0f, true));
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_set_material(ball_circle(f), good_material()));
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_enable_sensor_events(ball_circle(f), false));
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_enable_contact_events(ball_circle(f), false));
    CHECK_RUNTIME_LOCKED(f, before, i2d_shape_enable_hit_events(ball_circle(f), true));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_enable_sleeping(f->world, false));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_enable_continuous(f->world, false));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_enable_impact_chains(f->world, false));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_set_contact_tuning(f->world, 30.0f, 5.0f, 1.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_set_joint_tuning(f->world, 30.0f, 1.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_set_restitution_threshold(f->world, 2.0f));
    CHECK_RUNTIME_LOCKED(f, before, i2d_world_set_hit_event_threshold(f->world, 2.0f));
    /* The getters answer inside a callback. */
    I2D_CHECK(i2d_body_get_gravity_scale(ball(f)) == 1.0f && i2d_last_status() == I2D_OK);
    I2D_CHECK(i2d_world_get_settings(f->world).enable_sleep && i2d_last_status() == I2D_OK);
}

static bool probe_runtime_lock(i2d_shape_id shape, void* context) {
    (void)shape;
    runtime_lock_probe* probe = (runtime_lock_probe*)context;
    if (!probe->probed) {
        probe->probed = true;
        try_runtime_changes_while_locked(probe->f, probe->before);
    }
    return true;
}

static void run_runtime_locked(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    runtime_lock_probe probe = {a, &before, false};
    CHECK_ACCEPTED("i2d_world_overlap_aabb around a probing callback",
                   i2d_world_overlap_aabb(a->world, box(-100.0f, -100.0f, 100.0f, 100.0f),
                                          i2d_default_query_filter(), probe_runtime_lock, &probe));
    I2D_CHECK(probe.probed);
    CHECK_UNCHANGED("the runtime setters inside a callback", a, &before);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_runtime_setters_locked_in_query_callbacks) { run_on_twins(run_runtime_locked); }
