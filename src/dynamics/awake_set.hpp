// SPDX-License-Identifier: MIT
// Awake sets: dense lists of pool indices whose items know their place in the list
// (their awake_index), so that adding, removing and iterating are all cheap.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"

namespace i2d {

/// Appends the item; the list must have room (reserved) if this may not allocate.
template <class T>
void add_to_awake_set(std::vector<int32_t>& set, Pool<T>& pool, int32_t item) {
    pool[item].awake_index = int32_t(set.size());
    set.push_back(item);
}

/// Removes the item in O(1): the last entry moves into its place.
template <class T>
void remove_from_awake_set(std::vector<int32_t>& set, Pool<T>& pool, int32_t item) {
    const int32_t slot = pool[item].awake_index;
    const int32_t last = set.back();
    set[slot] = last;
    pool[last].awake_index = slot;
    set.pop_back();
    pool[item].awake_index = null_index;
}

}  // namespace i2d
