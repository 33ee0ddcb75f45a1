/* SPDX-License-Identifier: MIT */
/* Calls that take an enum by value, made from C with any int: legal in C (an enum holds
 * any value of its integer type), while a C++ caller could not even load such a value. */
#include <impulse2d/impulse2d.h>

#include "raw_enum_calls.h"

bool fuzz_simd_path_supported(int32_t path) { return i2d_simd_path_supported((i2d_simd_path)path); }

const char* fuzz_status_string(int32_t status) { return i2d_status_string((i2d_status)status); }
int32_t fuzz_body_set_type(uint64_t body_bits, int32_t type) {
    i2d_body_id body;
    body.bits = body_bits;
    return (int32_t)i2d_body_set_type(body, (i2d_body_type)type);
}
