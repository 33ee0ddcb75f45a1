// SPDX-License-Identifier: MIT
// A small deterministic random generator for the unit tests (xorshift32).
#pragma once

#include <cstdint>

struct TestRng {
    uint32_t state;
    explicit TestRng(uint32_t seed) : state(seed ? seed : 1u) {}
    uint32_t next() {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    }
    /// Uniform in [lo, hi].
    float uniform(float lo, float hi) { return lo + (hi - lo) * float(next() >> 8) * (1.0f / 16777215.0f); }
    int32_t below(int32_t n) { return int32_t(next() % uint32_t(n)); }
};
