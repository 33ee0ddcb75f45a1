// SPDX-License-Identifier: MIT
// HashSet against std::set: the same answers for every insert, remove and contains, at every
// load the table goes through (so that backward-shift deletion runs inside long probe chains),
// across growth and clear; pair_key symmetric, injective and never 0.
#include <cmath>
#include <cstdint>
#include <iterator>
#include <cstdio>
#include <set>
#include <utility>
#include <vector>

#include "check.h"
#include "core/hash_set.hpp"
#include "test_rng.hpp"

using namespace i2d;

namespace {

uint64_t next_u64(TestRng& rng) {
    const uint64_t hi = rng.next();
    return (hi << 32) | rng.next();
}

// Families of keys the engine produces or that tend to collide under weak hashes: a small
// dense range (so inserts often find the key present and removes often find it absent),
// pair keys of small shape indices, multiples of a large power of two (only high bits set),
// and full 64-bit values. Never 0.
enum class KeyFamily { dense, pair_keys, high_bits, spread, count };

const char* family_name(KeyFamily f) {
    switch (f) {
        case KeyFamily::dense: return "dense";
        case KeyFamily::pair_keys: return "pair_keys";
        case KeyFamily::high_bits: return "high_bits";
        default: return "spread";
    }
}

uint64_t random_key(TestRng& rng, KeyFamily family, int32_t range) {
    switch (family) {
        case KeyFamily::dense: return uint64_t(rng.below(range)) + 1;
        case KeyFamily::pair_keys: return pair_key(rng.below(range), rng.below(range));
        case KeyFamily::high_bits: return uint64_t(rng.below(range) + 1) << 40;
        default: {
            const uint64_t k = next_u64(rng);
            return k == 0 ? 1 : k;
        }
    }
}

// Every key of the reference must be found: a backward shift that breaks a probe chain makes
// a key further along unreachable. Returns the number of keys that were not found.
int32_t missing_keys(const HashSet& set, const std::set<uint64_t>& ref) {
    int32_t missing = 0;
    for (uint64_t k : ref) {
        if (!set.contains(k)) {
            if (missing < 5) {
                std::fprintf(stderr, "  key %llu is in the reference but not found\n", (unsigned long long)k);
            }
            ++missing;
        }
    }
    return missing;
}

template <class T>
void shuffle(std::vector<T>& v, TestRng& rng) {
    for (size_t i = v.size(); i > 1; --i) {
        std::swap(v[i - 1], v[size_t(rng.below(int32_t(i)))]);
    }
}

}  // namespace

// Many random operations per key family; every return value and the count compared with
// std::set, and every stored key looked up again every 1000 operations.
I2D_TEST(unit_hash_set_random_operations_match_std_set) {
    for (int32_t f = 0; f < int32_t(KeyFamily::count); ++f) {
        const KeyFamily family = KeyFamily(f);
        TestRng rng(0x1234u + uint32_t(f) * 7919u);
        HashSet set;
        std::set<uint64_t> ref;
        // Ranges a little larger than the set grows to, so that about half of the inserts
        // and of the plain removes hit.
        const int32_t range = family == KeyFamily::pair_keys ? 90 : 4000;
        int32_t mismatches = 0;
        for (int32_t op = 0; op < 60000; ++op) {
            const uint64_t key = random_key(rng, family, range);
            const int32_t what = rng.below(10);
            if (what < 5) {
                const bool expected = ref.insert(key).second;
                if (set.insert(key) != expected) {
                    ++mismatches;
                }
            } else if (what < 8) {
                // Mostly remove a present key, so that chains are cut often.
                uint64_t victim = key;
                if (what < 7 && !ref.empty()) {
                    auto it = ref.lower_bound(key);
                    victim = it == ref.end() ? *ref.begin() : *it;
                }
                const bool expected = ref.erase(victim) == 1;
                if (set.remove(victim) != expected || set.contains(victim)) {
                    ++mismatches;
                }
            } else if (set.contains(key) != (ref.count(key) == 1)) {
                ++mismatches;
            }
            if (set.count() != int32_t(ref.size())) {
                ++mismatches;
            }
            if (op % 1000 == 999 && missing_keys(set, ref) != 0) {
                ++mismatches;
            }
        }
        if (mismatches != 0) {
            std::fprintf(stderr, "family %s: %d mismatches\n", family_name(family), mismatches);
        }
        I2D_CHECK(mismatches == 0);

        // Empty it in random order, checking the remaining keys as it shrinks.
        std::vector<uint64_t> keys(ref.begin(), ref.end());
        shuffle(keys, rng);
        int32_t failed_removes = 0;
        for (size_t i = 0; i < keys.size(); ++i) {
            ref.erase(keys[i]);
            failed_removes += set.remove(keys[i]) ? 0 : 1;
            if (i % 64 == 0 && missing_keys(set, ref) != 0) {
                ++failed_removes;
            }
        }
        I2D_CHECK(failed_removes == 0);
        I2D_CHECK(set.count() == 0);
        int32_t still_found = 0;
        for (uint64_t k : keys) {
            still_found += set.contains(k) ? 1 : 0;
        }
        I2D_CHECK(still_found == 0);
    }
}

// Backward-shift deletion at the highest loads: for every size from 1 to 80 (and a few larger
// ones), the set is held at that size while keys are removed and inserted, so each growth
// threshold is visited at its fullest and removals happen inside long clusters. After every
// removal all remaining keys must still be found (a wrong shift makes a later key of the same
// cluster unreachable) and the removed one must be gone.
I2D_TEST(unit_hash_set_backward_shift_keeps_every_key_reachable) {
    TestRng rng(77);
    std::vector<int32_t> sizes;
    for (int32_t s = 1; s <= 80; ++s) {
        sizes.push_back(s);
    }
    for (int32_t s : {96, 127, 128, 129, 255, 256, 257, 511, 512, 513}) {
        sizes.push_back(s);
    }
    int32_t failures = 0, cycles = 0;
    for (int32_t size : sizes) {
        for (int32_t family = 0; family < int32_t(KeyFamily::count); ++family) {
            HashSet set;
            std::set<uint64_t> ref;
            // Key ranges about 3x the size, so that reinserted keys are often recently removed ones.
            // (pair keys of indices below r number r (r + 1) / 2.)
            const int32_t range = family == int32_t(KeyFamily::pair_keys) ? int32_t(std::sqrt(6.0 * size)) + 3
                                                                          : 3 * size + 3;
            while (int32_t(ref.size()) < size) {
                const uint64_t k = random_key(rng, KeyFamily(family), range);
                if (ref.insert(k).second != set.insert(k)) {
                    ++failures;
                }
            }
            const int32_t churn = size <= 80 ? 8 * size : 2 * size;
            for (int32_t op = 0; op < churn; ++op) {
                // Remove a random present key...
                auto it = ref.begin();
                std::advance(it, rng.below(int32_t(ref.size())));
                const uint64_t victim = *it;
                ref.erase(it);
                if (!set.remove(victim) || set.contains(victim) || set.remove(victim)) {
                    ++failures;
                }
                if ((size <= 80 || op % 8 == 0) && missing_keys(set, ref) != 0) {
                    ++failures;
                }
                // ...and insert an absent one, keeping the size.
                for (;;) {
                    const uint64_t k = random_key(rng, KeyFamily(family), range);
                    if (ref.insert(k).second) {
                        if (!set.insert(k) || set.insert(k)) {
                            ++failures;
                        }
                        break;
                    }
                }
                if (set.count() != size) {
                    ++failures;
                }
                ++cycles;
            }
            if (missing_keys(set, ref) != 0) {
                ++failures;
            }
        }
    }
    if (failures != 0) {
        std::fprintf(stderr, "%d failures in %d remove/insert cycles\n", failures, cycles);
    }
    I2D_CHECK(failures == 0);
}

// Growth from empty to 200k keys keeps every key and finds none of a disjoint set; then half
// are removed and the other half are still there.
I2D_TEST(unit_hash_set_growth_keeps_all_keys) {
    HashSet set;
    const int32_t n = 200000;
    int32_t failures = 0;
    for (int32_t i = 0; i < n; ++i) {
        // Even pair keys of a long run of shape pairs, as a big world would make.
        const uint64_t k = pair_key(i, i + 1 + (i % 7)) * 2;
        if (!set.insert(k)) {
            ++failures;
        }
        if (set.count() != i + 1) {
            ++failures;
        }
    }
    I2D_CHECK(failures == 0);
    int32_t missing = 0, phantom = 0;
    for (int32_t i = 0; i < n; ++i) {
        const uint64_t k = pair_key(i, i + 1 + (i % 7)) * 2;
        missing += set.contains(k) ? 0 : 1;
        phantom += set.contains(k + 1) ? 1 : 0;  // odd: never inserted
        failures += set.insert(k) ? 1 : 0;       // already there
    }
    I2D_CHECK(missing == 0);
    I2D_CHECK(phantom == 0);
    I2D_CHECK(failures == 0);
    I2D_CHECK(set.count() == n);
    for (int32_t i = 0; i < n; i += 2) {
        failures += set.remove(pair_key(i, i + 1 + (i % 7)) * 2) ? 0 : 1;
    }
    I2D_CHECK(failures == 0);
    I2D_CHECK(set.count() == n / 2);
    for (int32_t i = 0; i < n; ++i) {
        const bool expected = i % 2 == 1;
        missing += set.contains(pair_key(i, i + 1 + (i % 7)) * 2) != expected ? 1 : 0;
    }
    I2D_CHECK(missing == 0);
}

// Extreme keys: 1, all ones, only the top bit, values differing only in high bits.
I2D_TEST(unit_hash_set_extreme_keys) {
    HashSet set;
    const uint64_t keys[] = {1, ~uint64_t(0), uint64_t(1) << 63, uint64_t(1) << 32, (uint64_t(1) << 32) + 1,
                             uint64_t(0xFFFFFFFF), uint64_t(0xFFFFFFFF) << 32, 2, 3};
    for (uint64_t k : keys) {
        I2D_CHECK(!set.contains(k));
        I2D_CHECK(set.insert(k));
        I2D_CHECK(set.contains(k));
        I2D_CHECK(!set.insert(k));
    }
    I2D_CHECK(set.count() == int32_t(sizeof keys / sizeof keys[0]));
    for (uint64_t k : keys) {
        I2D_CHECK(set.remove(k));
        I2D_CHECK(!set.contains(k));
        I2D_CHECK(!set.remove(k));
    }
    I2D_CHECK(set.count() == 0);
}

// clear() empties the set whatever its size and leaves it usable; an empty set answers no.
I2D_TEST(unit_hash_set_clear_empties_and_stays_usable) {
    HashSet set;
    I2D_CHECK(set.count() == 0);
    I2D_CHECK(!set.contains(1));
    I2D_CHECK(!set.remove(1));
    set.clear();
    I2D_CHECK(set.count() == 0);
    for (int32_t round = 0; round < 3; ++round) {
        const int32_t n = 10 + 5000 * round;
        for (int32_t i = 1; i <= n; ++i) {
            I2D_CHECK(set.insert(uint64_t(i) * 31));
        }
        I2D_CHECK(set.count() == n);
        set.clear();
        I2D_CHECK(set.count() == 0);
        int32_t found = 0;
        for (int32_t i = 1; i <= n; ++i) {
            found += set.contains(uint64_t(i) * 31) ? 1 : 0;
        }
        I2D_CHECK(found == 0);
        // Usable again: the same keys are new.
        int32_t reinserted = 0;
        for (int32_t i = 1; i <= n; i += 3) {
            reinserted += set.insert(uint64_t(i) * 31) ? 1 : 0;
        }
        I2D_CHECK(reinserted == (n + 2) / 3);
        I2D_CHECK(set.count() == (n + 2) / 3);
        set.clear();
    }
}

// pair_key(a, b) == pair_key(b, a), never 0, and different unordered pairs get different keys.
I2D_TEST(unit_hash_set_pair_key_symmetric_nonzero_injective) {
    const int32_t big = 0x7fffffff;
    const int32_t edge[] = {0, 1, 2, 0xffff, 0x10000, big - 1, big};
    for (int32_t a : edge) {
        for (int32_t b : edge) {
            I2D_CHECK(pair_key(a, b) == pair_key(b, a));
            I2D_CHECK(pair_key(a, b) != 0);
        }
    }
    I2D_CHECK(pair_key(0, 0) != 0);
    I2D_CHECK(pair_key(big, big) != 0);

    // Every unordered pair of 0..199 (diagonal included) has its own key.
    std::set<uint64_t> keys;
    int32_t asymmetric = 0, zero = 0, pairs = 0;
    for (int32_t a = 0; a < 200; ++a) {
        for (int32_t b = a; b < 200; ++b) {
            const uint64_t k = pair_key(a, b);
            asymmetric += k != pair_key(b, a) ? 1 : 0;
            zero += k == 0 ? 1 : 0;
            keys.insert(k);
            ++pairs;
        }
    }
    I2D_CHECK(asymmetric == 0);
    I2D_CHECK(zero == 0);
    I2D_CHECK(int32_t(keys.size()) == pairs);

    // Random large indices, where a collision of (a, b) with another pair would need the
    // high and low halves to swap or mix.
    TestRng rng(99);
    std::set<std::pair<int32_t, int32_t>> seen;
    std::set<uint64_t> random_keys;
    for (int32_t i = 0; i < 20000; ++i) {
        const int32_t a = int32_t(rng.next() & 0x7fffffffu), b = int32_t(rng.next() & 0x7fffffffu);
        const uint64_t k = pair_key(a, b);
        I2D_CHECK(k != 0);
        I2D_CHECK(k == pair_key(b, a));
        seen.insert({a < b ? a : b, a < b ? b : a});
        random_keys.insert(k);
    }
    I2D_CHECK(random_keys.size() == seen.size());
}
