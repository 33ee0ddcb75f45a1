// SPDX-License-Identifier: MIT
// radix_sort: the result equals std::stable_sort's for keys spread over all four bytes,
// for keys that share their high bytes (the passes it skips), for one key repeated, and
// for no items at all.
#include <algorithm>
#include <vector>

#include "check.h"
#include "core/radix_sort.hpp"
#include "test_rng.hpp"

namespace {

struct Item {
    uint32_t key;
    int32_t arrival;  // tells equal keys apart: stability keeps arrivals increasing
};

bool same_as_stable_sort(std::vector<Item> items) {
    std::vector<Item> expected = items;
    std::stable_sort(expected.begin(), expected.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
    std::vector<Item> scratch;
    i2d::radix_sort(items, scratch, [](const Item& item) { return item.key; });
    if (items.size() != expected.size()) {
        return false;
    }
    for (size_t i = 0; i < items.size(); ++i) {
        if (items[i].key != expected[i].key || items[i].arrival != expected[i].arrival) {
            return false;
        }
    }
    return true;
}

std::vector<Item> random_items(TestRng& rng, int32_t count, uint32_t key_mask) {
    std::vector<Item> items;
    for (int32_t i = 0; i < count; ++i) {
        items.push_back({rng.next() & key_mask, i});
    }
    return items;
}

}  // namespace

I2D_TEST(unit_radix_sort_equals_stable_sort) {
    TestRng rng(11u);
    I2D_CHECK(same_as_stable_sort(random_items(rng, 5000, 0xFFFFFFFFu)));
    // Few distinct keys: many ties, whose order must survive every pass.
    I2D_CHECK(same_as_stable_sort(random_items(rng, 5000, 0x8000000Fu)));
    // Keys below 2^16 and keys whose low bytes agree: passes are skipped.
    I2D_CHECK(same_as_stable_sort(random_items(rng, 5000, 0x0000FFFFu)));
    I2D_CHECK(same_as_stable_sort(random_items(rng, 5000, 0xFF000000u)));
}

I2D_TEST(unit_radix_sort_short_lists_sort_stably) {
    // Below the radix passes' threshold the sort is by insertion: every length up to
    // past it, with ties.
    TestRng rng(5u);
    for (int32_t count = 2; count <= 80; ++count) {
        I2D_CHECK(same_as_stable_sort(random_items(rng, count, 0x0F00000Fu)));
    }
}

I2D_TEST(unit_radix_sort_degenerate_inputs) {
    I2D_CHECK(same_as_stable_sort({}));
    I2D_CHECK(same_as_stable_sort({{42u, 0}}));
    std::vector<Item> repeated;
    for (int32_t i = 0; i < 300; ++i) {
        repeated.push_back({0xABCDEF01u, i});
    }
    I2D_CHECK(same_as_stable_sort(repeated));
    std::vector<Item> descending;
    for (int32_t i = 0; i < 300; ++i) {
        descending.push_back({uint32_t(300 - i) << 20, i});
    }
    I2D_CHECK(same_as_stable_sort(descending));
}
