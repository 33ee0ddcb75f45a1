// SPDX-License-Identifier: MIT
// Prefetch helpers: ask for memory a loop will read soon, so that cache misses overlap
// instead of stalling one after the other.
//
// They are forced inline: GCC counts a prefetch as no side effect, finds a helper that
// only prefetches pure, and drops the call.
#pragma once

#include <cstddef>

#include "core/force_inline.hpp"

namespace i2d {

I2D_FORCE_INLINE void prefetch_line(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

/// The first `lines` cache lines from an address: the part of a large object a loop reads.
I2D_FORCE_INLINE void prefetch_lines(const void* address, std::size_t lines) {
    for (std::size_t line = 0; line < lines; ++line) {
        prefetch_line(static_cast<const char*>(address) + 64 * line);
    }
}

/// Every cache line of an object.
template <class T>
I2D_FORCE_INLINE void prefetch_object(const T& object) {
    const char* bytes = reinterpret_cast<const char*>(&object);
    constexpr std::size_t line = 64;
    for (std::size_t offset = 0; offset < sizeof(T); offset += line) {
        prefetch_line(bytes + offset);
    }
    prefetch_line(bytes + sizeof(T) - 1);
}

}  // namespace i2d
