// SPDX-License-Identifier: MIT
// SpinWait: waiting a short time without giving up the core, then politely.
//
// Threads that wait for each other between stages of a step wait microseconds: a
// sleep would cost more than the wait. Spinning forever would starve other threads on a
// machine with more threads than cores, so after a while each round yields the core.
#pragma once

#include <cstdint>
#include <thread>

#if defined(__x86_64__) || defined(_M_X64) || defined(__i386__)
#include <immintrin.h>
#endif

namespace i2d {

class SpinWait {
public:
    void once() {
        if (spins_ < spins_before_yield) {
            ++spins_;
            pause();
        } else {
            std::this_thread::yield();
        }
    }
    /// Whether the wait has gone on long enough that sleeping would cost less.
    bool long_wait() const { return spins_ >= spins_before_yield; }

private:
    // About 20 to 50 microseconds of pause instructions on current x86 cores.
    static constexpr int32_t spins_before_yield = 2000;

    static void pause() {
#if defined(__x86_64__) || defined(_M_X64) || defined(__i386__)
        _mm_pause();
#elif defined(__aarch64__)
        __asm__ __volatile__("yield");
#endif
    }

    int32_t spins_ = 0;
};

}  // namespace i2d
