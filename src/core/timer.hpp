// SPDX-License-Identifier: MIT
// Timer: wall-clock milliseconds for the step profile (never used to make decisions, so
// results stay deterministic).
#pragma once

#include <chrono>

namespace i2d {

class Timer {
public:
    Timer() : start_(std::chrono::steady_clock::now()) {}
    /// Milliseconds since construction or the last lap, and restarts.
    float lap_ms() {
        const auto now = std::chrono::steady_clock::now();
        const float ms = std::chrono::duration<float, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace i2d
