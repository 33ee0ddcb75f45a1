// SPDX-License-Identifier: MIT
// The lowest and the highest set bit of a 32-bit word, one instruction on every target
// the library builds for (C++17 has no <bit>).
#pragma once

#include <cstdint>

#if defined(_MSC_VER)
#include <intrin.h>
#endif

namespace i2d {

/// Index of the lowest set bit; `bits` must not be 0.
inline int32_t lowest_set_bit(uint32_t bits) {
#if defined(_MSC_VER)
    unsigned long index;
    _BitScanForward(&index, bits);
    return int32_t(index);
#else
    return __builtin_ctz(bits);
#endif
}

/// Index of the highest set bit; `bits` must not be 0.
inline int32_t highest_set_bit(uint32_t bits) {
#if defined(_MSC_VER)
    unsigned long index;
    _BitScanReverse(&index, bits);
    return int32_t(index);
#else
    return 31 - __builtin_clz(bits);
#endif
}

}  // namespace i2d
