// SPDX-License-Identifier: MIT
// cycle_now: a clock cheap enough to read at every stage a worker waits at (the time
// stamp counter where the core has one). For sharing work out between workers, never for
// anything a result depends on.
#pragma once

#include <chrono>
#include <cstdint>

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <intrin.h>
#elif defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace i2d {

/// Ticks of a clock that runs at one rate on every core; the unit varies by machine.
inline uint64_t cycle_now() {
#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
    return __rdtsc();
#elif defined(__x86_64__) || defined(__i386__)
    return __rdtsc();
#elif defined(__aarch64__)
    uint64_t ticks;
    __asm__ __volatile__("mrs %0, cntvct_el0" : "=r"(ticks));
    return ticks;
#else
    return uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                        std::chrono::steady_clock::now().time_since_epoch())
                        .count());
#endif
}

}  // namespace i2d
