/* SPDX-License-Identifier: MIT */
/* The ABI binding authors rely on: size, alignment and field offsets of every public
 * struct, fixed in abi_layout.def. The build fails on a changed row (compile-time
 * checks); the test prints every value and checks them again at run time, so a log shows
 * the whole layout. Recorded for x86-64 (System V, LP64); elsewhere the contract fixes
 * only the ids' size. */
#include <impulse2d/impulse2d.h>

#include <stddef.h>
#include <stdio.h>

#include "check.h"

#if defined(__x86_64__) || defined(_M_X64)

/* Alignment without C11's _Alignof: the offset of a member placed after one char. */
#define ALIGN_PROBE_NAME(line) align_probe_##line
#define ALIGN_PROBE(line) ALIGN_PROBE_NAME(line)
#define STATIC_ROW_NAME(line) abi_layout_row_##line
#define STATIC_ROW(line) STATIC_ROW_NAME(line)

/* Compile time: each row is a typedef whose array size is -1 when the row is wrong. */
#define LAYOUT(expr, expected) typedef char STATIC_ROW(__LINE__)[((expr) == (expected)) ? 1 : -1];
#define ALIGN(type, expected)                                                                          \
    typedef struct {                                                                                   \
        char c;                                                                                        \
        type t;                                                                                        \
    } ALIGN_PROBE(__LINE__);                                                                           \
    typedef char STATIC_ROW(__LINE__)[(offsetof(ALIGN_PROBE(__LINE__), t) == (expected)) ? 1 : -1];
#include "abi_layout.def"
#undef LAYOUT
#undef ALIGN

static void check_row(const char* what, size_t actual, size_t expected) {
    printf("%-60s %3zu\n", what, actual);
    if (actual != expected) {
        ++i2d_check_failures;
        fprintf(stderr, "%s: %s = %zu, recorded %zu\n", __FILE__, what, actual, expected);
    }
}

#endif

I2D_TEST(api_abi_struct_layout) {
#if defined(__x86_64__) || defined(_M_X64)
#define LAYOUT(expr, expected) check_row(#expr, (expr), (expected));
#define ALIGN(type, expected) check_row("alignment of " #type, offsetof(ALIGN_PROBE(__LINE__), t), (expected));
#include "abi_layout.def"
#undef LAYOUT
#undef ALIGN
#else
    /* Elsewhere only the ids' size is fixed by the contract. */
    I2D_CHECK(sizeof(i2d_world_id) == 8 && sizeof(i2d_body_id) == 8 && sizeof(i2d_shape_id) == 8);
#endif
}
