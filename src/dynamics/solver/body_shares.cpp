// SPDX-License-Identifier: MIT
// BodyShares: cutting the awake bodies by work; ShareBalance: fractions from speeds.
#include "dynamics/solver/body_shares.hpp"

#include <algorithm>
#include <cmath>

#include "core/assert.hpp"

namespace i2d {

void BodyShares::cut(int32_t count, const int32_t* contacts_before, int32_t body_count, const double* fractions) {
    I2D_ASSERT(count >= 1 && body_count >= 0);
    // The work of the states below b, which rises with b.
    const auto work_below = [&](int32_t b) { return int64_t(b) + contact_weight * contacts_before[b]; };
    const int64_t total = work_below(body_count);
    starts_.resize(std::size_t(count) + 1);
    starts_[0] = 0;
    int32_t low = 0;
    double fraction_below = 0.0;
    for (int32_t r = 1; r < count; ++r) {
        // The first body at or past the work of the shares before r.
        fraction_below += fractions != nullptr ? fractions[r - 1] : 0.0;
        const int64_t target = fractions != nullptr ? int64_t(double(total) * fraction_below) : total * r / count;
        int32_t high = body_count;
        while (low < high) {
            const int32_t mid = low + (high - low) / 2;
            if (work_below(mid) < target) {
                low = mid + 1;
            } else {
                high = mid;
            }
        }
        starts_[std::size_t(r)] = low;
    }
    starts_[std::size_t(count)] = body_count;
}

void ShareBalance::note_run(const StageRunner::WorkerTime* times, int32_t workers) {
    if (int32_t(rates_.size()) != workers) {
        rates_.assign(std::size_t(workers), 0.0);
        fractions_.assign(std::size_t(workers), 1.0 / double(workers));
        cut_fractions_ = fractions_;
        runs_since_cut_ = 0;
    }
    ++runs_since_cut_;
    for (int32_t w = 0; w < workers; ++w) {
        const StageRunner::WorkerTime& time = times[w];
        if (time.blocks == 0 || time.busy == 0) {
            continue;
        }
        const double rate = double(time.blocks) / double(time.busy);
        double& smoothed = rates_[std::size_t(w)];
        smoothed = smoothed == 0.0 ? rate : smoothed + smoothing * (rate - smoothed);
    }
    double total = 0.0;
    for (const double rate : rates_) {
        if (rate == 0.0) {
            return;  // a worker has not run yet: nothing to compare
        }
        total += rate;
    }
    const double even = 1.0 / double(workers);
    double sum = 0.0;
    for (int32_t w = 0; w < workers; ++w) {
        const double fraction = rates_[std::size_t(w)] / total;
        fractions_[std::size_t(w)] = std::clamp(fraction, (1.0 - max_tilt) * even, (1.0 + max_tilt) * even);
        sum += fractions_[std::size_t(w)];
    }
    for (double& fraction : fractions_) {
        fraction /= sum;
    }
}

bool ShareBalance::wants_cut() const {
    if (runs_since_cut_ < runs_between_cuts) {
        return false;
    }
    for (std::size_t w = 0; w < fractions_.size(); ++w) {
        if (std::fabs(fractions_[w] - cut_fractions_[w]) > cut_threshold) {
            return true;
        }
    }
    return false;
}

void ShareBalance::cut_made() {
    cut_fractions_ = fractions_;
    runs_since_cut_ = 0;
}

}  // namespace i2d
