// SPDX-License-Identifier: MIT
// BitSet: membership of small non-negative integers (ids, keys), one bit each.
//
// Design note: where keys are dense indices, a bit array answers "is it in?" with one
// load and no hashing, from one bit per possible key (32 KB for the 256k proxy keys of
// 64k shapes), which stays in cache where a hash table of 12k moved keys (256 KB) did
// not. The broadphase asks it for every candidate pair.
#pragma once

#include <cstdint>
#include <vector>

namespace i2d {

class BitSet {
public:
    /// Returns true if the value was added, false if it was there already. value >= 0.
    bool insert(int32_t value) {
        const std::size_t word = std::size_t(value) >> 6;
        if (word >= words_.size()) {
            words_.resize(word + 1 + words_.size() / 2, 0u);
        }
        const uint64_t bit = uint64_t(1) << (value & 63);
        if ((words_[word] & bit) != 0) {
            return false;
        }
        words_[word] |= bit;
        ++count_;
        return true;
    }
    /// Returns true if the value was there.
    bool remove(int32_t value) {
        if (!contains(value)) {
            return false;
        }
        words_[std::size_t(value) >> 6] &= ~(uint64_t(1) << (value & 63));
        --count_;
        return true;
    }
    bool contains(int32_t value) const {
        const std::size_t word = std::size_t(value) >> 6;
        return value >= 0 && word < words_.size() && (words_[word] >> (value & 63) & 1u) != 0;
    }
    int32_t count() const { return count_; }
    /// Calls visit(value) for every value in it, in increasing order.
    template <class Visit>
    void visit(Visit&& visit) const {
        for (std::size_t w = 0; w < words_.size(); ++w) {
            for (uint64_t word = words_[w]; word != 0; word &= word - 1) {
                visit(int32_t(w << 6) + lowest_bit(word));
            }
        }
    }

private:
    static int32_t lowest_bit(uint64_t word) {
#if defined(__GNUC__)
        return __builtin_ctzll(word);
#else
        int32_t n = 0;
        for (; (word & 1u) == 0; word >>= 1) {
            ++n;
        }
        return n;
#endif
    }

    std::vector<uint64_t> words_;
    int32_t count_ = 0;
};

}  // namespace i2d
