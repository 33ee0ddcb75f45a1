/* SPDX-License-Identifier: MIT */
/* Command-line arguments shared by the benchmark apps. */
#ifndef IMPULSE2D_BENCH_ARGUMENTS_H
#define IMPULSE2D_BENCH_ARGUMENTS_H

#include <stdbool.h>
#include <stdint.h>

/* Parses a whole decimal argument in [lo, hi] into out; false (out untouched) for NULL,
 * trailing characters or a value out of range. */
bool bench_parse_int(const char* text, int32_t lo, int32_t hi, int32_t* out);

#endif
