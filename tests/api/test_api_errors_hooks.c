/* SPDX-License-Identifier: MIT */
/* Bad input to the contact hooks and explosions (toolkit.h): NaN, infinities, negative
 * and huge sizes, NULL defs, stale ids and calls inside a query callback are refused
 * with a status and a message, the fixture world exactly as it was (its observable
 * snapshot and, after stepping, its twin). */
#include "test_api_errors.h"

static i2d_body_id ball(const fixture* f) { return f->body[FIX_BALL]; }
static i2d_shape_id ball_circle(const fixture* f) { return f->shape[FIX_BALL_CIRCLE]; }

static bool never(i2d_shape_id a, i2d_shape_id b, void* context) {
    (void)a, (void)b, (void)context;
    return false;
}

static bool never_pre_solve(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* m, void* context) {
    (void)a, (void)b, (void)m, (void)context;
    return false;
}

/* A blast that would reach and push the ball, but for the one bad field. */
static i2d_explosion_def blast_at_ball(const fixture* f) {
    i2d_explosion_def def = i2d_default_explosion_def();
    def.position = i2d_body_get_position(ball(f));
    def.radius = 3.0f;
    def.impulse_per_length = 5.0f;
    return def;
}

/* ---- Explosions with a bad field -------------------------------------------------------- */

static void run_explode_refused(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        const float bad = k_non_finite[k];
        i2d_explosion_def def = blast_at_ball(a);
        def.position.x = bad;
        CHECK_REFUSED("explode(position non-finite)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
        def = blast_at_ball(a);
        def.radius = bad;
        CHECK_REFUSED("explode(radius non-finite)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
        def = blast_at_ball(a);
        def.falloff = bad;
        CHECK_REFUSED("explode(falloff non-finite)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
        def = blast_at_ball(a);
        def.impulse_per_length = bad;
        CHECK_REFUSED("explode(impulse non-finite)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
    }
    i2d_explosion_def def = blast_at_ball(a);
    def.radius = -1.0f;
    CHECK_REFUSED("explode(negative radius)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
    def = blast_at_ball(a);
    def.falloff = -0.5f;
    CHECK_REFUSED("explode(negative falloff)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
    def = blast_at_ball(a);
    def.radius = 1e30f;
    CHECK_REFUSED("explode(radius beyond any level)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
    def = blast_at_ball(a);
    def.impulse_per_length = -1e30f;
    CHECK_REFUSED("explode(huge implosion)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
    def = blast_at_ball(a);
    def.position = v2(2e9f, 0.0f);
    CHECK_REFUSED("explode(position beyond the world)", i2d_world_explode(a->world, &def), I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("explode(NULL)", i2d_world_explode(a->world, NULL), I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("refused explosions", a, &before);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_hooks_explode_bad_values) { run_on_twins(run_explode_refused); }

/* ---- Stale ids ---------------------------------------------------------------------------- */

I2D_TEST(api_errors_hooks_stale_ids) {
    i2d_world_id world = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_body_id body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_id shape = i2d_shape_create_box(body, &sd, 0.5f, 0.5f);
    I2D_REQUIRE(i2d_body_destroy(body) == I2D_OK);
    const i2d_status stale = I2D_ERR_INVALID_HANDLE;
    CHECK_REFUSED("enable_pre_solve_events (destroyed shape)", i2d_shape_enable_pre_solve_events(shape, true), stale);
    I2D_CHECK(!i2d_shape_are_pre_solve_events_enabled(shape) && i2d_last_status() == stale);
    I2D_REQUIRE(i2d_world_destroy(world) == I2D_OK);
    const i2d_explosion_def def = i2d_default_explosion_def();
    CHECK_REFUSED("explode (destroyed world)", i2d_world_explode(world, &def), stale);
    CHECK_REFUSED("set_custom_filter_callback (destroyed world)",
                  i2d_world_set_custom_filter_callback(world, never, NULL), stale);
    CHECK_REFUSED("set_pre_solve_callback (destroyed world)",
                  i2d_world_set_pre_solve_callback(world, never_pre_solve, NULL), stale);
    const i2d_world_id null_world = I2D_NULL_WORLD_ID;
    CHECK_REFUSED("explode (null world)", i2d_world_explode(null_world, &def), stale);
}

/* ---- Inside a query callback ------------------------------------------------------------ */

typedef struct hook_lock_probe {
    const fixture* f;
    const snapshot* before;
    bool probed;
} hook_lock_probe;

static bool probe_hook_lock(i2d_shape_id shape, void* context) {
    (void)shape;
    hook_lock_probe* probe = (hook_lock_probe*)context;
    if (probe->probed) {
        return true;
    }
    probe->probed = true;
    const fixture* f = probe->f;
    const i2d_explosion_def def = blast_at_ball(f);
    CHECK_REFUSED("explode (locked)", i2d_world_explode(f->world, &def), I2D_ERR_WORLD_LOCKED);
    CHECK_REFUSED("set_custom_filter_callback (locked)", i2d_world_set_custom_filter_callback(f->world, never, NULL),
                  I2D_ERR_WORLD_LOCKED);
    CHECK_REFUSED("set_pre_solve_callback (locked)",
                  i2d_world_set_pre_solve_callback(f->world, never_pre_solve, NULL), I2D_ERR_WORLD_LOCKED);
    CHECK_REFUSED("enable_pre_solve_events (locked)", i2d_shape_enable_pre_solve_events(ball_circle(f), true),
                  I2D_ERR_WORLD_LOCKED);
    CHECK_UNCHANGED("hook and explosion calls inside a callback", f, probe->before);
    /* The getter answers inside a query callback. */
    I2D_CHECK(!i2d_shape_are_pre_solve_events_enabled(ball_circle(f)) && i2d_last_status() == I2D_OK);
    return true;
}

static void run_hooks_locked(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    hook_lock_probe probe = {a, &before, false};
    CHECK_ACCEPTED("i2d_world_overlap_aabb around a probing callback",
                   i2d_world_overlap_aabb(a->world, box(-100.0f, -100.0f, 100.0f, 100.0f),
                                          i2d_default_query_filter(), probe_hook_lock, &probe));
    I2D_CHECK(probe.probed);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_hooks_locked_in_query_callbacks) { run_on_twins(run_hooks_locked); }

/* ---- What the defaults are ------------------------------------------------------------ */

I2D_TEST(api_hooks_defaults_opt_out_and_explode_everything_within_a_metre) {
    const i2d_shape_def sd = i2d_default_shape_def();
    I2D_CHECK(!sd.enable_custom_filtering && !sd.enable_pre_solve_events);
    const i2d_explosion_def def = i2d_default_explosion_def();
    I2D_CHECK(def.mask_bits == UINT64_MAX);
    I2D_CHECK(def.radius == 1.0f && def.falloff == 0.0f && def.impulse_per_length == 1.0f);
    I2D_CHECK(def.position.x == 0.0f && def.position.y == 0.0f);
}
