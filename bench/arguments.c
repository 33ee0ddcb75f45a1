/* SPDX-License-Identifier: MIT */
#include "arguments.h"

#include <stdlib.h>

bool bench_parse_int(const char* text, int32_t lo, int32_t hi, int32_t* out) {
    char* end;
    long value;
    if (!text) {
        return false;
    }
    value = strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < lo || value > hi) {
        return false;
    }
    *out = (int32_t)value;
    return true;
}
