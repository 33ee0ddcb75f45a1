// SPDX-License-Identifier: MIT
// BitSet: insert and remove say whether anything changed, the count follows, values far
// beyond the current size are absent rather than out of bounds, and membership agrees
// with a plain reference set under random use.
#include <set>
#include <vector>

#include "check.h"
#include "core/bit_set.hpp"
#include "test_rng.hpp"

using i2d::BitSet;

I2D_TEST(unit_bit_set_insert_remove_contains) {
    BitSet set;
    I2D_CHECK(!set.contains(0) && !set.contains(-1) && !set.contains(1000000));
    I2D_CHECK(set.insert(5));
    I2D_CHECK(!set.insert(5));
    I2D_CHECK(set.insert(64) && set.insert(63) && set.insert(0));
    I2D_CHECK(set.count() == 4);
    I2D_CHECK(set.contains(5) && set.contains(63) && set.contains(64) && set.contains(0));
    I2D_CHECK(!set.contains(6) && !set.contains(65) && !set.contains(128));
    I2D_CHECK(set.remove(63));
    I2D_CHECK(!set.remove(63));
    I2D_CHECK(!set.remove(100000));  // never grown that far
    I2D_CHECK(!set.contains(63) && set.contains(64));
    I2D_CHECK(set.count() == 3);
}

I2D_TEST(unit_bit_set_matches_a_reference_set) {
    TestRng rng(7u);
    BitSet set;
    std::set<int32_t> reference;
    for (int32_t i = 0; i < 20000; ++i) {
        const int32_t value = rng.below(5000);
        if (rng.below(3) == 0) {
            I2D_CHECK(set.remove(value) == (reference.erase(value) == 1));
        } else {
            I2D_CHECK(set.insert(value) == reference.insert(value).second);
        }
        const int32_t probe = rng.below(6000);
        I2D_CHECK(set.contains(probe) == (reference.count(probe) == 1));
    }
    I2D_CHECK(set.count() == int32_t(reference.size()));
    std::vector<int32_t> visited;
    set.visit([&](int32_t value) { visited.push_back(value); });
    I2D_CHECK(visited == std::vector<int32_t>(reference.begin(), reference.end()));  // every one, in order
}
