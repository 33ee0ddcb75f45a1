// SPDX-License-Identifier: MIT
// reserve_room: makes room in a vector ahead of time, growing it geometrically.
//
// std::vector::reserve(n) allocates exactly n, so reserving "one more than now" before
// every insertion copies the whole vector each time: quadratic in the number of objects
// a scene creates. Growing by at least half keeps the amortised cost constant.
#pragma once

#include <cstddef>
#include <vector>

namespace i2d {

template <class T>
void reserve_room(std::vector<T>& v, std::size_t needed) {
    if (v.capacity() < needed) {
        const std::size_t grown = v.capacity() + v.capacity() / 2;
        v.reserve(needed > grown ? needed : grown);
    }
}

}  // namespace i2d
