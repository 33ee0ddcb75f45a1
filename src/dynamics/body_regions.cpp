// SPDX-License-Identifier: MIT
#include "dynamics/body_regions.hpp"

#include <algorithm>

#include "core/assert.hpp"

namespace i2d {

void BodyRegions::cut(int32_t regions, const int32_t* contacts_before, int32_t body_count) {
    I2D_ASSERT(regions >= 1 && body_count >= 0);
    // The work of the states below b, which rises with b.
    const auto work_below = [&](int32_t b) { return int64_t(b) + contact_weight * contacts_before[b]; };
    const int64_t total = work_below(body_count);
    starts_.resize(std::size_t(regions) + 1);
    starts_[0] = 0;
    int32_t low = 0;
    for (int32_t r = 1; r < regions; ++r) {
        // The first body at or past r / regions of the work.
        const int64_t target = total * r / regions;
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

int32_t BodyRegions::region_of(int32_t body) const {
    const auto after = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, body);
    return int32_t(after - (starts_.begin() + 1));
}

}  // namespace i2d
