/* SPDX-License-Identifier: MIT */
/* Shared helpers of the random-scene API tests: a fixed-seed generator and capped
 * mismatch reports. Each test file that includes it gets its own copies (static). */
#ifndef I2D_TESTS_API_TEST_SUPPORT_H
#define I2D_TESTS_API_TEST_SUPPORT_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>

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
