// SPDX-License-Identifier: MIT
// radix_sort: a stable sort of records by a 32-bit unsigned key, linear in the count.
//
// Design note: least significant byte first, four counting passes at most; a pass whose
// byte is the same in every key is skipped, so keys below 65,536 (node indices of a tree
// of 32k leaves) cost two passes. The records move through a caller's scratch array
// that keeps its capacity from call to call: no allocation in a steady state. A pass
// costs 256 buckets whatever the count, so a short list (a world where little moved)
// takes an insertion sort instead: a few items must not cost microseconds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace i2d {

/// Sorts `items` by `key(item)` (uint32_t), keeping the order of equal keys.
template <class T, class Key>
void radix_sort(std::vector<T>& items, std::vector<T>& scratch, Key&& key) {
    const std::size_t n = items.size();
    constexpr std::size_t insertion_sort_below = 64;
    if (n < insertion_sort_below) {
        for (std::size_t i = 1; i < n; ++i) {
            const T item = items[i];
            std::size_t j = i;
            for (; j > 0 && key(items[j - 1]) > key(item); --j) {
                items[j] = items[j - 1];
            }
            items[j] = item;
        }
        return;
    }
    scratch.resize(n);
    for (int32_t shift = 0; shift < 32; shift += 8) {
        std::size_t starts[257] = {};
        for (const T& item : items) {
            ++starts[((key(item) >> shift) & 0xFFu) + 1];
        }
        bool one_bucket = false;
        for (int32_t digit = 0; digit < 256; ++digit) {
            one_bucket = one_bucket || starts[digit + 1] == n;
            starts[digit + 1] += starts[digit];
        }
        if (one_bucket) {
            continue;  // every key has this byte: the pass would keep the order as it is
        }
        for (const T& item : items) {
            scratch[starts[(key(item) >> shift) & 0xFFu]++] = item;
        }
        items.swap(scratch);
    }
}

}  // namespace i2d
