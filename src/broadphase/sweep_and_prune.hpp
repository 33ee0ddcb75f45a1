// SPDX-License-Identifier: MIT
// SweepAndPrune: overlapping pairs of boxes by sorting along one axis and sweeping.
//
// Design note: this is the first broadphase, O(n log n) per update plus the pairs that
// overlap on the sweep axis. The axis with the larger spread of box centres is swept so
// that a tall stack or a long floor does not overlap everything on it. It is replaced by
// dynamic AABB trees with the broadphase issue; a uniform grid was the alternative, but
// it needs a cell size that suits every scene.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "math/vec2.hpp"

namespace i2d {

struct BroadphasePair {
    int32_t a, b;  // proxy indices, a < b
};

class SweepAndPrune {
public:
    /// Appends to `out` every pair of `boxes` that overlap (touching included) and that
    /// `accept(a, b)` keeps. The order depends only on the input.
    template <class Accept>
    void find_pairs(const std::vector<AABB>& boxes, Accept&& accept, std::vector<BroadphasePair>& out) {
        const bool sweep_x = spread_is_wider_in_x(boxes);
        entries_.resize(boxes.size());
        for (size_t i = 0; i < boxes.size(); ++i) {
            const AABB& b = boxes[i];
            entries_[i] = sweep_x ? Entry{b.lower.x, b.upper.x, b.lower.y, b.upper.y, static_cast<int32_t>(i)}
                                  : Entry{b.lower.y, b.upper.y, b.lower.x, b.upper.x, static_cast<int32_t>(i)};
        }
        std::sort(entries_.begin(), entries_.end(), [](const Entry& l, const Entry& r) {
            return l.lower != r.lower ? l.lower < r.lower : l.index < r.index;
        });
        const size_t n = entries_.size();
        for (size_t i = 0; i < n; ++i) {
            const Entry& e = entries_[i];
            for (size_t j = i + 1; j < n && entries_[j].lower <= e.upper; ++j) {
                const Entry& f = entries_[j];
                if (f.cross_lower > e.cross_upper || e.cross_lower > f.cross_upper) {
                    continue;
                }
                const int32_t a = std::min(e.index, f.index), b = std::max(e.index, f.index);
                if (accept(a, b)) {
                    out.push_back({a, b});
                }
            }
        }
    }

private:
    struct Entry {
        float lower, upper;              // along the sweep axis
        float cross_lower, cross_upper;  // along the other axis
        int32_t index;
    };

    static bool spread_is_wider_in_x(const std::vector<AABB>& boxes) {
        // Variance of the centres, accumulated in double so that many boxes far from the
        // origin do not lose it to cancellation.
        double sx = 0, sy = 0, sxx = 0, syy = 0;
        for (const AABB& b : boxes) {
            const double cx = 0.5 * (double(b.lower.x) + b.upper.x), cy = 0.5 * (double(b.lower.y) + b.upper.y);
            sx += cx, sy += cy, sxx += cx * cx, syy += cy * cy;
        }
        const double n = boxes.empty() ? 1.0 : double(boxes.size());
        return sxx / n - (sx / n) * (sx / n) >= syy / n - (sy / n) * (sy / n);
    }

    std::vector<Entry> entries_;
};

}  // namespace i2d
