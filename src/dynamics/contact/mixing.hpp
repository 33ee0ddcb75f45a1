// SPDX-License-Identifier: MIT
// MixingRule: how a contact combines its two shapes' friction or restitution.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>

#include "math/math.hpp"

namespace i2d {

enum class MixingRule : uint8_t { geometric_mean, minimum, maximum, average, multiply, count };

/// Finite for finite non-negative inputs: infinite friction times a zero normal impulse
/// would be NaN in the solver.
inline float mix(MixingRule rule, float a, float b) {
    float mixed = 0.0f;
    switch (rule) {
        // sqrt(a) sqrt(b) rather than sqrt(a b): the product of two huge values overflows.
        case MixingRule::geometric_mean: mixed = std::sqrt(a) * std::sqrt(b); break;
        case MixingRule::minimum: mixed = min_of(a, b); break;
        case MixingRule::maximum: mixed = max_of(a, b); break;
        case MixingRule::average: mixed = 0.5f * a + 0.5f * b; break;
        case MixingRule::multiply: mixed = a * b; break;
        case MixingRule::count: break;
    }
    return min_of(mixed, FLT_MAX);
}

}  // namespace i2d
