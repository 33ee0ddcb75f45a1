/* SPDX-License-Identifier: MIT */
/* The API suite's fixture header, the one place for what its test files share: value
 * builders for the public structs, the step the tests take, a fresh world to run a test
 * body in, a fixed-seed generator and capped mismatch reports. Everything is static, so
 * each test file that includes it gets its own copies (inline: no warning for the ones a
 * file does not use). Topic headers build on it: ref_shape.h (the query tests' reference
 * model) and test_api_errors.h (the bad-input tests' fixture). */
#ifndef I2D_TESTS_API_TEST_SUPPORT_H
#define I2D_TESTS_API_TEST_SUPPORT_H

#include <impulse2d/impulse2d.h>

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "check.h"

/* ---- Values of the public structs, each built in one expression ---------------------- */

static inline i2d_vec2 v2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static inline i2d_rot rot(float c, float s) {
    i2d_rot q;
    q.c = c;
    q.s = s;
    return q;
}

static inline i2d_rot identity_rot(void) { return rot(1.0f, 0.0f); }

static inline i2d_aabb box(float min_x, float min_y, float max_x, float max_y) {
    i2d_aabb b;
    b.min = v2(min_x, min_y);
    b.max = v2(max_x, max_y);
    return b;
}

static inline i2d_query_filter query_filter(uint64_t category_bits, uint64_t mask_bits) {
    i2d_query_filter f;
    f.category_bits = category_bits;
    f.mask_bits = mask_bits;
    return f;
}

/* ---- Worlds and bodies ----------------------------------------------------------------- */

/* The step of the tests that step: 60 Hz with 4 substeps. */
static const float k_dt = 1.0f / 60.0f;
enum { SUBSTEPS = 4 };

static inline bool step_ok(i2d_world_id world) { return i2d_world_step(world, k_dt, SUBSTEPS) == I2D_OK; }

/* A default world but for its gravity, (0, gravity_y). */
static inline i2d_world_id make_world(float gravity_y) {
    i2d_world_def def = i2d_default_world_def();
    def.gravity = v2(0.0f, gravity_y);
    return i2d_world_create(&def);
}

/* A default body but for its type and position, without shapes. */
static inline i2d_body_id make_body(i2d_world_id world, i2d_body_type type, float x, float y) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = v2(x, y);
    return i2d_body_create(world, &def);
}

/* Whether the unordered pair {a, b} is {x, y}. */
static inline bool same_pair(i2d_shape_id a, i2d_shape_id b, i2d_shape_id x, i2d_shape_id y) {
    return (I2D_ID_EQUALS(a, x) && I2D_ID_EQUALS(b, y)) || (I2D_ID_EQUALS(a, y) && I2D_ID_EQUALS(b, x));
}

/* A test body: the checks of one test, on a world it is given. Bodies take their world
 * rather than make it so that the world is destroyed even when a body stops early at an
 * I2D_REQUIRE. */
typedef void (*world_test_body)(i2d_world_id world);

static inline void run_then_destroy(i2d_world_id world, world_test_body test_body) {
    I2D_REQUIRE(!I2D_IS_NULL(world));
    test_body(world);
    i2d_world_destroy(world);
}

static inline void run_in_default_world(world_test_body test_body) {
    const i2d_world_def def = i2d_default_world_def();
    run_then_destroy(i2d_world_create(&def), test_body);
}

/* In a default world but for its gravity, (0, gravity_y). */
static inline void run_in_world(float gravity_y, world_test_body test_body) {
    run_then_destroy(make_world(gravity_y), test_body);
}

/* ---- Refusals ------------------------------------------------------------------------- */

/* A copy of an error message ("(null)" for none) for a failure report: any i2d_ call
 * may overwrite the library's. */
static inline void copy_message(char* out, size_t size, const char* message) {
    snprintf(out, size, "%s", message != NULL ? message : "(null)");
}

/* The call just made answered `expected` through both its return value and
 * i2d_last_status(), with a non-empty message. Reads the status and the message before
 * calling anything else. */
static inline void check_refused_at(const char* file, int line, const char* what, i2d_status returned,
                                    i2d_status expected) {
    i2d_status last = i2d_last_status();
    const char* message = i2d_last_error_message();
    char copy[256];
    copy_message(copy, sizeof copy, message);
    if (returned != expected || last != expected || message == NULL || message[0] == '\0') {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: returned %s, last status %s, message \"%s\"; expected %s with a message\n", file,
                line, what, i2d_status_string(returned), i2d_status_string(last), copy, i2d_status_string(expected));
    }
}

/* ---- Random scenes and capped reports ---------------------------------------------------- */

/* splitmix64: a fixed-seed generator, the same on every platform (rand() is not). */
typedef struct rng {
    uint64_t state;
} rng;

static inline uint64_t rng_next(rng* r) {
    uint64_t z = (r->state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi). */
static inline float rng_float(rng* r, float lo, float hi) {
    double unit = (double)(rng_next(r) >> 11) / 9007199254740992.0; /* 2^53 */
    return (float)(lo + (hi - lo) * unit);
}

/* Uniform in [0, n). */
static inline int rng_int(rng* r, int n) { return (int)(rng_next(r) % (uint64_t)n); }

/* Mismatch reports are capped so that a broken feature does not flood the log; a test
 * sets g_reports_left before it starts. */
static int g_reports_left;

static inline void report_at(const char* file, const char* format, ...) {
    if (g_reports_left <= 0) {
        return;
    }
    --g_reports_left;
    va_list args;
    va_start(args, format);
    fprintf(stderr, "%s: ", file);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
}

/* Names the test file, not this header, in the message. */
#define report(...) report_at(__FILE__, __VA_ARGS__)

#endif
