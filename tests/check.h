/* SPDX-License-Identifier: MIT */
/* Tiny test macros, C99 and C++: checks record file, line and expression and keep going.
 *
 * Write a test as
 *     I2D_TEST(circle_overlap) { I2D_CHECK(1 + 1 == 2); }
 * Test names are global C symbols: make them unique across a suite. CMake scans the
 * suite's sources for I2D_TEST(name) and generates the table the runner walks, and
 * registers each name as its own CTest test. */
#ifndef I2D_TESTS_CHECK_H
#define I2D_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>

#ifdef __cplusplus
#define I2D_TEST_LINKAGE extern "C"
#else
#define I2D_TEST_LINKAGE
#endif

#define I2D_TEST(name) I2D_TEST_LINKAGE void name(void)

/* One row of the table CMake generates for each suite. */
typedef struct i2d_test_case {
    const char* name;
    void (*fn)(void);
} i2d_test_case;

#ifdef __cplusplus
extern "C" {
#endif
/** Failed checks in the running test; the runner resets it per test. */
extern int i2d_check_failures;
#ifdef __cplusplus
}
#endif

#define I2D_CHECK(cond)                                                                    \
    do {                                                                                   \
        if (!(cond)) {                                                                     \
            ++i2d_check_failures;                                                          \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);       \
        }                                                                                  \
    } while (0)

/* |actual - expected| <= tol, printing both values and the tolerance on failure. NaN fails. */
#define I2D_CHECK_NEAR(actual, expected, tol)                                              \
    do {                                                                                   \
        double i2d_a_ = (double)(actual), i2d_e_ = (double)(expected), i2d_t_ = (double)(tol); \
        if (!(fabs(i2d_a_ - i2d_e_) <= i2d_t_)) {                                          \
            ++i2d_check_failures;                                                          \
            fprintf(stderr, "%s:%d: check failed: %s = %.9g, expected %s = %.9g within %.3g\n", \
                    __FILE__, __LINE__, #actual, i2d_a_, #expected, i2d_e_, i2d_t_);       \
        }                                                                                  \
    } while (0)

/* Stops the current test when cond fails (for checks later ones depend on). */
#define I2D_REQUIRE(cond)                                                                  \
    do {                                                                                   \
        if (!(cond)) {                                                                     \
            ++i2d_check_failures;                                                          \
            fprintf(stderr, "%s:%d: requirement failed: %s\n", __FILE__, __LINE__, #cond); \
            return;                                                                        \
        }                                                                                  \
    } while (0)

/* Only where impulse2d.h is visible: a status check that prints the library's message. */
#ifdef IMPULSE2D_BASE_H
#define I2D_CHECK_STATUS(expr, expected)                                                   \
    do {                                                                                   \
        i2d_status i2d_s_ = (expr);                                                        \
        if (i2d_s_ != (expected)) {                                                        \
            ++i2d_check_failures;                                                          \
            fprintf(stderr, "%s:%d: %s returned %s, expected %s (message: \"%s\")\n",       \
                    __FILE__, __LINE__, #expr, i2d_status_string(i2d_s_),                  \
                    i2d_status_string(expected), i2d_last_error_message());                \
        }                                                                                  \
    } while (0)
#endif

#endif
