// SPDX-License-Identifier: MIT
#include "dynamics/solver/body_regions.hpp"

#include <algorithm>
#include <cmath>

#include "core/assert.hpp"

namespace i2d {

void BodyRegions::cut(int32_t regions, const int32_t* contacts_before, int32_t body_count, const double* shares) {
    I2D_ASSERT(regions >= 1 && body_count >= 0);
    // The work of the states below b, which rises with b.
    const auto work_below = [&](int32_t b) { return int64_t(b) + contact_weight * contacts_before[b]; };
    const int64_t total = work_below(body_count);
    starts_.resize(std::size_t(regions) + 1);
    starts_[0] = 0;
    int32_t low = 0;
    double share_below = 0.0;
    for (int32_t r = 1; r < regions; ++r) {
        // The first body at or past the work of the regions before r.
        share_below += shares != nullptr ? shares[r - 1] : 0.0;
        const int64_t target = shares != nullptr ? int64_t(double(total) * share_below) : total * r / regions;
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
    starts_[std::size_t(regions)] = body_count;
}

void RegionBalance::note_run(const StageRunner::WorkerTime* times, int32_t workers) {
    if (int32_t(rates_.size()) != workers) {
        rates_.assign(std::size_t(workers), 0.0);
        shares_.assign(std::size_t(workers), 1.0 / double(workers));
        cut_shares_ = shares_;
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
        const double share = rates_[std::size_t(w)] / total;
        shares_[std::size_t(w)] = std::clamp(share, (1.0 - max_tilt) * even, (1.0 + max_tilt) * even);
        sum += shares_[std::size_t(w)];
    }
    for (double& share : shares_) {
        share /= sum;
    }
}

bool RegionBalance::wants_cut() const {
    if (runs_since_cut_ < runs_between_cuts) {
        return false;
    }
    for (std::size_t w = 0; w < shares_.size(); ++w) {
        if (std::fabs(shares_[w] - cut_shares_[w]) > cut_threshold) {
            return true;
        }
    }
    return false;
}

void RegionBalance::cut_made() {
    cut_shares_ = shares_;
    runs_since_cut_ = 0;
}

int32_t BodyRegions::region_of(int32_t body) const {
    const auto after = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, body);
    return int32_t(after - (starts_.begin() + 1));
}

}  // namespace i2d
