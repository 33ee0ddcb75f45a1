// SPDX-License-Identifier: MIT
// HashSet: a set of 64-bit keys by open addressing with linear probing.
//
// Design note: used for shape-pair keys (dense keys such as the move set's proxy keys
// use a BitSet). Deletion uses backward-shift (no tombstones), so lookups stay short
// however many pairs come and go. Key 0 marks an empty slot, so callers store key + 1
// or keys that are never 0. Iteration order is never used by the step (it depends on
// the table size): the set answers membership only.
#pragma once

#include <cstdint>
#include <vector>

namespace i2d {

class HashSet {
public:
    /// Returns true if the key was added, false if it was there already. key != 0.
    bool insert(uint64_t key);
    /// Returns true if the key was there.
    bool remove(uint64_t key);
    bool contains(uint64_t key) const;
    /// Asks for the slot where a lookup of `key` starts, for a lookup soon after.
    void prefetch(uint64_t key) const;
    void clear();
    int32_t count() const { return count_; }

private:
    static uint64_t hash(uint64_t key);
    void grow();

    std::vector<uint64_t> slots_;
    int32_t count_ = 0;
};

/// The key of an unordered pair of non-negative indices, never 0.
inline uint64_t pair_key(int32_t a, int32_t b) {
    const uint64_t lo = uint64_t(a < b ? a : b), hi = uint64_t(a < b ? b : a);
    return ((hi << 32) | lo) + 1;
}

}  // namespace i2d
