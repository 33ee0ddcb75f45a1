// SPDX-License-Identifier: MIT
// I2D_FORCE_INLINE: for the small helpers of the SIMD kernels, which must be inlined to
// keep their vector arguments in registers; compilers give up on inlining them once the
// kernels grow, and a call passes eight-lane structs through memory.
#pragma once

#if defined(_MSC_VER)
#define I2D_FORCE_INLINE __forceinline
#elif defined(__GNUC__) || defined(__clang__)
#define I2D_FORCE_INLINE inline __attribute__((always_inline))
#else
#define I2D_FORCE_INLINE inline
#endif
