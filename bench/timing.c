/* SPDX-License-Identifier: MIT */
/* clock_gettime and CLOCK_MONOTONIC are POSIX, not C99. */
#define _POSIX_C_SOURCE 199309L

#include "timing.h"

#include <stdlib.h>
#include <time.h>

double bench_seconds_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_nanoseconds_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

int bench_compare_doubles(const void* a, const void* b) {
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

double bench_sort_median(double* values, int32_t n) {
    qsort(values, (size_t)n, sizeof values[0], bench_compare_doubles);
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}
