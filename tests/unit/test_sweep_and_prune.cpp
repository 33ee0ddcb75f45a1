// SPDX-License-Identifier: MIT
// SweepAndPrune against brute force: the same pairs, each once, in a repeatable order.
#include <algorithm>
#include <vector>

#include "broadphase/sweep_and_prune.hpp"
#include "check.h"
#include "test_rng.hpp"

using namespace i2d;

namespace {

std::vector<AABB> random_boxes(TestRng& rng, int32_t count, float world, float max_size) {
    std::vector<AABB> boxes;
    for (int32_t i = 0; i < count; ++i) {
        const Vec2 lower{rng.uniform(-world, world), rng.uniform(-world, world)};
        const Vec2 size{rng.uniform(0.0f, max_size), rng.uniform(0.0f, max_size)};
        boxes.push_back({lower, lower + size});
    }
    return boxes;
}

std::vector<std::pair<int32_t, int32_t>> brute_force_pairs(const std::vector<AABB>& boxes) {
    std::vector<std::pair<int32_t, int32_t>> pairs;
    for (size_t i = 0; i < boxes.size(); ++i) {
        for (size_t j = i + 1; j < boxes.size(); ++j) {
            if (overlaps(boxes[i], boxes[j])) {
                pairs.emplace_back(int32_t(i), int32_t(j));
            }
        }
    }
    return pairs;
}

std::vector<std::pair<int32_t, int32_t>> sorted(const std::vector<BroadphasePair>& found) {
    std::vector<std::pair<int32_t, int32_t>> pairs;
    for (const BroadphasePair& p : found) {
        pairs.emplace_back(p.a, p.b);
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace

I2D_TEST(unit_sap_matches_brute_force_on_random_scenes) {
    TestRng rng(1234);
    SweepAndPrune sap;
    for (int32_t scene = 0; scene < 20; ++scene) {
        // Vary density so that both sparse and crowded scenes are covered.
        const std::vector<AABB> boxes = random_boxes(rng, 300, 20.0f, 0.5f + 0.5f * float(scene));
        std::vector<BroadphasePair> found;
        sap.find_pairs(boxes, [](int32_t, int32_t) { return true; }, found);
        for (const BroadphasePair& p : found) {
            I2D_CHECK(p.a < p.b);
        }
        I2D_CHECK(sorted(found) == brute_force_pairs(boxes));
    }
}

I2D_TEST(unit_sap_counts_touching_boxes_and_respects_accept) {
    // A row of unit boxes touching edge to edge along x: n - 1 pairs.
    std::vector<AABB> boxes;
    for (int32_t i = 0; i < 10; ++i) {
        boxes.push_back({{float(i), 0.0f}, {float(i + 1), 1.0f}});
    }
    SweepAndPrune sap;
    std::vector<BroadphasePair> found;
    sap.find_pairs(boxes, [](int32_t, int32_t) { return true; }, found);
    I2D_CHECK(found.size() == 9);
    found.clear();
    sap.find_pairs(boxes, [](int32_t a, int32_t) { return a % 2 == 0; }, found);
    I2D_CHECK(found.size() == 5);
}

I2D_TEST(unit_sap_vertical_column_is_swept_along_its_length) {
    // A tall column overlaps everything in x; sweeping y must still find only neighbours.
    std::vector<AABB> boxes;
    for (int32_t i = 0; i < 200; ++i) {
        boxes.push_back({{0.0f, float(i)}, {1.0f, float(i) + 0.999f}});
    }
    SweepAndPrune sap;
    std::vector<BroadphasePair> found;
    sap.find_pairs(boxes, [](int32_t, int32_t) { return true; }, found);
    I2D_CHECK(found.empty());
}

I2D_TEST(unit_sap_order_is_repeatable) {
    TestRng rng(99);
    const std::vector<AABB> boxes = random_boxes(rng, 500, 10.0f, 1.0f);
    SweepAndPrune first, second;
    std::vector<BroadphasePair> a, b;
    first.find_pairs(boxes, [](int32_t, int32_t) { return true; }, a);
    second.find_pairs(boxes, [](int32_t, int32_t) { return true; }, b);
    I2D_REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        I2D_CHECK(a[i].a == b[i].a && a[i].b == b[i].b);
    }
}
