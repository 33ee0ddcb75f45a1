/* SPDX-License-Identifier: MIT */
/* raw_enum_calls.c: enum-taking calls with any int, as C callers may make them. */
#ifndef I2D_FUZZ_RAW_ENUM_CALLS_H
#define I2D_FUZZ_RAW_ENUM_CALLS_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif
bool fuzz_simd_path_supported(int32_t path);
const char* fuzz_status_string(int32_t status);
int32_t fuzz_body_set_type(uint64_t body_bits, int32_t type);
#ifdef __cplusplus
}
#endif

#endif
