// SPDX-License-Identifier: MIT
// Open addressing with linear probing and backward-shift deletion.
#include "core/hash_set.hpp"

#include <algorithm>

#include "core/prefetch.hpp"

namespace i2d {

// A 64-bit finaliser (splitmix64's): pair keys differ in few bits, so mix them all.
uint64_t HashSet::hash(uint64_t key) {
    key ^= key >> 30;
    key *= 0xbf58476d1ce4e5b9ull;
    key ^= key >> 27;
    key *= 0x94d049bb133111ebull;
    key ^= key >> 31;
    return key;
}

bool HashSet::contains(uint64_t key) const {
    if (slots_.empty()) {
        return false;
    }
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash(key) & mask;; i = (i + 1) & mask) {
        if (slots_[i] == key) {
            return true;
        }
        if (slots_[i] == 0) {
            return false;
        }
    }
}

void HashSet::prefetch(uint64_t key) const {
    if (!slots_.empty()) {
        prefetch_line(&slots_[hash(key) & (slots_.size() - 1)]);
    }
}

bool HashSet::insert(uint64_t key) {
    // Keep the load under one half so that probes stay short.
    if (2 * (size_t(count_) + 1) > slots_.size()) {
        grow();
    }
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash(key) & mask;; i = (i + 1) & mask) {
        if (slots_[i] == key) {
            return false;
        }
        if (slots_[i] == 0) {
            slots_[i] = key;
            ++count_;
            return true;
        }
    }
}

bool HashSet::remove(uint64_t key) {
    if (slots_.empty()) {
        return false;
    }
    const size_t mask = slots_.size() - 1;
    size_t i = hash(key) & mask;
    while (slots_[i] != key) {
        if (slots_[i] == 0) {
            return false;
        }
        i = (i + 1) & mask;
    }
    // Backward shift: move later members of the probe run into the hole when their home
    // slot lies at or before it, so that no lookup ever stops early at the hole.
    size_t hole = i;
    for (size_t j = (hole + 1) & mask; slots_[j] != 0; j = (j + 1) & mask) {
        const size_t home = hash(slots_[j]) & mask;
        // Distance from home to j versus from hole to j, both around the ring.
        if (((j - home) & mask) >= ((j - hole) & mask)) {
            slots_[hole] = slots_[j];
            hole = j;
        }
    }
    slots_[hole] = 0;
    --count_;
    return true;
}

void HashSet::clear() {
    std::fill(slots_.begin(), slots_.end(), 0);
    count_ = 0;
}

void HashSet::grow() {
    // Allocate first: if that throws, the set is unchanged.
    std::vector<uint64_t> old(slots_.empty() ? 32 : slots_.size() * 2, 0);
    old.swap(slots_);
    count_ = 0;
    for (uint64_t key : old) {
        if (key != 0) {
            insert(key);
        }
    }
}

}  // namespace i2d
