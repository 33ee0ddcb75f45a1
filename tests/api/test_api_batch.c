/* SPDX-License-Identifier: MIT */
/* i2d_worlds_step: a batch steps each world as i2d_world_step would, and bad input (a bad
 * def, count or step, a null, stale, wrong-kind, repeated or locked world among good
 * ones) is refused as a whole, with a message naming the entry, and no world moved. */
#include <string.h>

#include "test_api_errors.h"

enum { BATCH_STEPS = 30 };

/* The fixture's twin a stepped by the batch (with a second world beside it), b alone. */
static void run_batch_steps_like_alone(const fixture* a, const fixture* b) {
    i2d_world_id other = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(other));
    i2d_world_id batch[2] = {other, a->world};
    i2d_batch_def def = i2d_default_batch_def();
    const uint64_t unstepped = i2d_world_get_state_hash(a->world);
    for (int s = 0; s < BATCH_STEPS; ++s) {
        I2D_CHECK_STATUS(i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &def), I2D_OK);
        I2D_CHECK(step_ok(b->world));
    }
    I2D_CHECK(i2d_world_get_state_hash(a->world) == i2d_world_get_state_hash(b->world));
    I2D_CHECK(i2d_world_get_state_hash(a->world) != unstepped);
    I2D_CHECK_STATUS(i2d_worlds_step(batch, 0, k_dt, SUBSTEPS, &def), I2D_OK); /* an empty batch */
    I2D_CHECK_STATUS(i2d_worlds_step(NULL, 0, k_dt, SUBSTEPS, &def), I2D_OK);
    i2d_world_destroy(other);
}

I2D_TEST(api_batch_steps_each_world_as_alone) { run_on_twins(run_batch_steps_like_alone); }

/* Refused with the status and a message holding `needle`; a and its twin b unchanged. */
static void check_batch_refused_at(int line, const char* what, i2d_status returned, i2d_status expected,
                                   const char* needle, const fixture* a, const snapshot* before) {
    check_refused_at(__FILE__, line, what, returned, expected);
    const char* message = i2d_last_error_message();
    if (needle != NULL && (message == NULL || strstr(message, needle) == NULL)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: message \"%s\" lacks \"%s\"\n", __FILE__, line, what,
                message != NULL ? message : "(null)", needle);
    }
    CHECK_UNCHANGED(what, a, before);
}
#define CHECK_BATCH_REFUSED(what, returned, expected, needle) \
    check_batch_refused_at(__LINE__, (what), (returned), (expected), (needle), a, &before)

static void run_bad_batches(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    i2d_batch_def def = i2d_default_batch_def();
    i2d_world_id batch[3] = {a->world, I2D_NULL_WORLD_ID, I2D_NULL_WORLD_ID};

    CHECK_BATCH_REFUSED("null id", i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &def), I2D_ERR_INVALID_HANDLE,
                        "worlds[1]: world id is null");
    i2d_world_id gone = make_world(-10.0f);
    i2d_world_destroy(gone);
    batch[1] = gone;
    CHECK_BATCH_REFUSED("stale id", i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &def), I2D_ERR_INVALID_HANDLE,
                        "worlds[1]: world id is stale");
    batch[1].bits = a->body[FIX_BALL].bits;
    CHECK_BATCH_REFUSED("body id as a world", i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &def),
                        I2D_ERR_INVALID_HANDLE, "worlds[1]");
    i2d_world_id other = make_world(-10.0f);
    batch[1] = other;
    batch[2] = a->world;
    CHECK_BATCH_REFUSED("listed twice", i2d_worlds_step(batch, 3, k_dt, SUBSTEPS, &def), I2D_ERR_INVALID_ARGUMENT,
                        "worlds[2]: the world is listed twice");
    CHECK_BATCH_REFUSED("NULL worlds", i2d_worlds_step(NULL, 1, k_dt, SUBSTEPS, &def), I2D_ERR_INVALID_ARGUMENT,
                        "worlds is NULL");
    CHECK_BATCH_REFUSED("negative count", i2d_worlds_step(batch, -1, k_dt, SUBSTEPS, &def),
                        I2D_ERR_INVALID_ARGUMENT, "count is -1");
    CHECK_BATCH_REFUSED("count past I2D_MAX_WORLDS", i2d_worlds_step(batch, I2D_MAX_WORLDS + 1, k_dt, SUBSTEPS, &def),
                        I2D_ERR_INVALID_ARGUMENT, "count is");
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        CHECK_BATCH_REFUSED("non-finite time step", i2d_worlds_step(batch, 2, k_non_finite[k], SUBSTEPS, &def),
                            I2D_ERR_INVALID_ARGUMENT, "time_step");
    }
    CHECK_BATCH_REFUSED("negative time step", i2d_worlds_step(batch, 2, -k_dt, SUBSTEPS, &def),
                        I2D_ERR_INVALID_ARGUMENT, "time_step");
    CHECK_BATCH_REFUSED("no substeps", i2d_worlds_step(batch, 2, k_dt, 0, &def), I2D_ERR_INVALID_ARGUMENT,
                        "substep_count");
    CHECK_BATCH_REFUSED("NULL def", i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, NULL), I2D_ERR_INVALID_ARGUMENT,
                        "batch def is NULL");
    i2d_batch_def raw;
    memset(&raw, 0, sizeof raw);
    raw.worker_count = 1;
    CHECK_BATCH_REFUSED("uninitialised def", i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &raw),
                        I2D_ERR_INVALID_ARGUMENT, "batch_def");
    const int32_t bad_workers[] = {0, -3, I2D_MAX_WORKERS + 1};
    for (size_t k = 0; k < sizeof bad_workers / sizeof bad_workers[0]; ++k) {
        i2d_batch_def d = i2d_default_batch_def();
        d.worker_count = bad_workers[k];
        CHECK_BATCH_REFUSED("worker_count out of range", i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &d),
                            I2D_ERR_INVALID_ARGUMENT, "worker_count");
    }
    /* The world beside it was not stepped either: it matches a world never stepped. */
    I2D_CHECK(i2d_world_get_counters(other).body_count == 0);
    i2d_world_destroy(other);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_batch_bad_input_refused_whole_nothing_stepped) { run_on_twins(run_bad_batches); }

/* Half a job system is refused; a whole one is used. */
static void* run_inline(i2d_task_fn* task, int32_t item_count, int32_t min_range, void* task_context,
                        void* user_context) {
    (void)min_range;
    ++*(int*)user_context;
    task(0, item_count, 1, task_context);
    return NULL;
}

static void finish_nothing(void* user_task, void* user_context) { (void)user_task, (void)user_context; }

static void run_batch_job_system(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    i2d_world_id batch[1] = {a->world};
    int tasks = 0;
    i2d_batch_def def = i2d_default_batch_def();
    def.worker_count = 3;
    def.enqueue_task = run_inline;
    def.user_task_context = &tasks;
    CHECK_BATCH_REFUSED("enqueue without finish", i2d_worlds_step(batch, 1, k_dt, SUBSTEPS, &def),
                        I2D_ERR_INVALID_ARGUMENT, "finish_task is NULL");
    def.finish_task = finish_nothing;
    for (int s = 0; s < BATCH_STEPS; ++s) {
        I2D_CHECK_STATUS(i2d_worlds_step(batch, 1, k_dt, SUBSTEPS, &def), I2D_OK);
        I2D_CHECK(step_ok(b->world));
    }
    I2D_CHECK(tasks == 2 * BATCH_STEPS); /* one task per worker beyond the caller */
    I2D_CHECK(i2d_world_get_state_hash(a->world) == i2d_world_get_state_hash(b->world));
}

I2D_TEST(api_batch_uses_the_callers_job_system) { run_on_twins(run_batch_job_system); }

/* From inside a query callback on a world, a batch holding that world is refused. */
typedef struct batch_in_query {
    i2d_world_id batch[1];
    i2d_status status;
} batch_in_query;

static bool step_batch_from_query(i2d_shape_id shape, void* context) {
    (void)shape;
    batch_in_query* q = (batch_in_query*)context;
    i2d_batch_def def = i2d_default_batch_def();
    q->status = i2d_worlds_step(q->batch, 1, k_dt, SUBSTEPS, &def);
    return false;
}

static void run_batch_locked_in_query(const fixture* a, const fixture* b) {
    (void)b;
    static snapshot before;
    snapshot_take(a, &before);
    batch_in_query q = {{a->world}, I2D_OK};
    i2d_world_overlap_aabb(a->world, box(-100, -100, 100, 100), i2d_default_query_filter(), step_batch_from_query, &q);
    I2D_CHECK_STATUS(q.status, I2D_ERR_WORLD_LOCKED);
    CHECK_UNCHANGED("batch from a query callback", a, &before);
}

I2D_TEST(api_batch_refused_inside_a_query_callback) { run_on_twins(run_batch_locked_in_query); }

/* A contact hook of one world in a batch reaches another world of the batch: refused,
 * even once that world's own step is over, since another worker may be stepping it. */
typedef struct cross_world {
    i2d_world_id target;
    i2d_body_id target_body;
    int calls, refused;
} cross_world;

static bool touch_the_other_world(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* m, void* context) {
    (void)a, (void)b, (void)m;
    cross_world* c = (cross_world*)context;
    ++c->calls;
    if (i2d_body_set_linear_velocity(c->target_body, v2(7.0f, 0.0f)) == I2D_ERR_WORLD_LOCKED &&
        !i2d_world_is_valid(c->target)) {
        ++c->refused;
    }
    return true;
}

static void run_cross_world_hook(const fixture* a, const fixture* b) {
    (void)b;
    i2d_world_id hooked = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(hooked));
    i2d_body_id ground = make_body(hooked, I2D_BODY_STATIC, 0.0f, -1.0f);
    i2d_shape_def shape_def = i2d_default_shape_def();
    shape_def.enable_pre_solve_events = true;
    i2d_shape_create_box(ground, &shape_def, 5.0f, 1.0f);
    i2d_body_id crate = make_body(hooked, I2D_BODY_DYNAMIC, 0.0f, 0.49f);
    i2d_shape_create_box(crate, &shape_def, 0.5f, 0.5f);
    cross_world c = {a->world, a->body[FIX_BALL], 0, 0};
    I2D_CHECK_STATUS(i2d_world_set_pre_solve_callback(hooked, touch_the_other_world, &c), I2D_OK);
    i2d_world_id batch[2] = {a->world, hooked};
    i2d_batch_def def = i2d_default_batch_def();
    def.worker_count = 2;
    for (int s = 0; s < 5; ++s) {
        I2D_CHECK_STATUS(i2d_worlds_step(batch, 2, k_dt, SUBSTEPS, &def), I2D_OK);
    }
    I2D_CHECK(c.calls > 0);
    I2D_CHECK(c.refused == c.calls);
    I2D_CHECK(i2d_body_get_linear_velocity(a->body[FIX_BALL]).x < 1.5f);
    /* After the batch, the worlds are open again. */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(a->body[FIX_BALL], v2(7.0f, 0.0f)), I2D_OK);
    i2d_world_destroy(hooked);
}

I2D_TEST(api_batch_worlds_locked_to_each_others_hooks) { run_on_twins(run_cross_world_hook); }
