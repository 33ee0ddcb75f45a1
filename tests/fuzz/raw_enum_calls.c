/* SPDX-License-Identifier: MIT */
/* Calls that take an enum by value, made from C with any int: legal in C (an enum holds
 * any value of its integer type), while a C++ caller could not even load such a value. */
#include <impulse2d/impulse2d.h>

#include "raw_enum_calls.h"

bool fuzz_simd_path_supported(int32_t path) { return i2d_simd_path_supported((i2d_simd_path)path); }

const char* fuzz_status_string(int32_t status) { return i2d_status_string((i2d_status)status); }
