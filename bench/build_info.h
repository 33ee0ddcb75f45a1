/* SPDX-License-Identifier: MIT */
/* What the numbers were measured on: compiler, flags, SIMD level, library options, commit and
 * date, printed first by every benchmark app (as Jolt's PerformanceTest does). */
#ifndef IMPULSE2D_BENCH_BUILD_INFO_H
#define IMPULSE2D_BENCH_BUILD_INFO_H

#include <stdbool.h>
#include <stdio.h>

/* One line starting with "# ": "# impulse2d 0.1.0 <app> | compiler | ... | commit | date". */
void bench_print_build_line(FILE* out, const char* app);

/* The same as the members of a JSON object, without braces: "\"library\": \"0.1.0\", ...". */
void bench_print_build_json(FILE* out);

/* s as the body of a JSON string (quotes and backslashes escaped, control characters as \u). */
void bench_json_string(FILE* out, const char* s);

/* False (with a message on stderr naming app) when the loaded library is not the version built against. */
bool bench_check_library_version(const char* app);

#endif
