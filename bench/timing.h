/* SPDX-License-Identifier: MIT */
/* The benchmark apps' clock and medians. */
#ifndef IMPULSE2D_BENCH_TIMING_H
#define IMPULSE2D_BENCH_TIMING_H

#include <stdint.h>

/* Seconds on the monotonic clock. */
double bench_seconds_now(void);
/* Nanoseconds on the monotonic clock. */
double bench_nanoseconds_now(void);
/* qsort's comparison of doubles, ascending. */
int bench_compare_doubles(const void* a, const void* b);
/* Sorts values and returns their median; values[0] is then the minimum. n >= 1. */
double bench_sort_median(double* values, int32_t n);

#endif
