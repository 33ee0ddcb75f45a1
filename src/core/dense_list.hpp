// SPDX-License-Identifier: MIT
// Dense lists of indices whose items know their place in the list, so that adding,
// removing and walking are all cheap (the awake bodies, islands and contacts).
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"

namespace i2d {

/// Appends the item; place(item) is the int32_t where the item keeps its place.
template <class Place>
void dense_list_add(std::vector<int32_t>& list, int32_t item, Place&& place) {
    place(item) = int32_t(list.size());
    list.push_back(item);
}

/// Removes the item in O(1): the last item moves into its place.
template <class Place>
void dense_list_remove(std::vector<int32_t>& list, int32_t item, Place&& place) {
    const int32_t slot = place(item);
    const int32_t last = list.back();
    list[std::size_t(slot)] = last;
    place(last) = slot;
    list.pop_back();
    place(item) = null_index;
}

}  // namespace i2d
