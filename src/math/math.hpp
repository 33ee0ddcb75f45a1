// SPDX-License-Identifier: MIT
// Scalar helpers and the finiteness checks that guard every value entering the core.
#pragma once

#include <cmath>

#include "math/vec2.hpp"

namespace i2d {

constexpr float pi = 3.14159265358979323846f;

inline bool is_finite(float a) { return std::isfinite(a); }
inline bool is_finite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }
inline bool is_finite(Rot q) { return std::isfinite(q.c) && std::isfinite(q.s); }

inline float clamp(float a, float lo, float hi) { return a < lo ? lo : (a > hi ? hi : a); }

/// min and max for values known not to be NaN: one instruction each, where std::fmin
/// and std::fmax are library calls (they must handle NaN).
inline float min_of(float a, float b) { return a < b ? a : b; }
inline float max_of(float a, float b) { return a > b ? a : b; }

}  // namespace i2d
