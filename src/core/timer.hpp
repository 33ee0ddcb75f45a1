// SPDX-License-Identifier: MIT
// Timer: wall-clock milliseconds for the step profile (never used to make decisions, so
// results stay deterministic). A timer that is off reads no clock at all: a step's
// profile would otherwise cost a tenth of an empty world's step.
#pragma once

#include <chrono>

namespace i2d {

class Timer {
public:
    explicit Timer(bool on = true) : on_(on) {
        if (on_) {
            start_ = std::chrono::steady_clock::now();
        }
    }
    /// Milliseconds since construction or the last lap, and restarts; 0 when off.
    float lap_ms() {
        if (!on_) {
            return 0.0f;
        }
        const auto now = std::chrono::steady_clock::now();
        const float ms = std::chrono::duration<float, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

private:
    std::chrono::steady_clock::time_point start_;
    bool on_;
};

}  // namespace i2d
