// SPDX-License-Identifier: MIT
// checksum64: four multiply-rotate lanes over little-endian words.
#include "core/checksum.hpp"

#include <cstring>

namespace i2d {

namespace {

// Odd constants with well-spread bits (the first 64 bits of the fractional parts of
// sqrt(2), sqrt(3), sqrt(5) and sqrt(7)), so that each multiplication is a bijection.
constexpr uint64_t k1 = 0x6a09e667f3bcc909ull;
constexpr uint64_t k2 = 0xbb67ae8584caa73bull;
constexpr uint64_t k3 = 0x3c6ef372fe94f82bull;
constexpr uint64_t k4 = 0xa54ff53a5f1d36f1ull;

uint64_t rotl(uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }

// A word as little-endian bytes, whatever the host: one load where the host is
// little-endian (every platform built today), a byte swap elsewhere.
uint64_t load_word(const unsigned char* p) {
    uint64_t v = 0;
    std::memcpy(&v, p, sizeof v);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    v = __builtin_bswap64(v);
#endif
    return v;
}

uint64_t lane_step(uint64_t lane, uint64_t word) { return rotl(lane + word * k1, 31) * k2; }

// A bijective final mix, so that nearby inputs give unrelated checksums.
uint64_t avalanche(uint64_t h) {
    h ^= h >> 33;
    h *= k3;
    h ^= h >> 29;
    h *= k4;
    h ^= h >> 32;
    return h;
}

}  // namespace

uint64_t checksum64(const void* data, std::size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    uint64_t lanes[4] = {k1, k2, k3, k4};
    std::size_t offset = 0;
    for (; offset + 32 <= size; offset += 32) {
        for (int l = 0; l < 4; ++l) {
            lanes[l] = lane_step(lanes[l], load_word(p + offset + 8 * std::size_t(l)));
        }
    }
    // The last whole words, then the last bytes padded with zeros, go to the lanes in turn.
    int lane = 0;
    for (; offset + 8 <= size; offset += 8, ++lane) {
        lanes[lane] = lane_step(lanes[lane], load_word(p + offset));
    }
    if (offset < size) {
        unsigned char tail[8] = {};
        std::memcpy(tail, p + offset, size - offset);
        lanes[lane] = lane_step(lanes[lane], load_word(tail));
    }
    uint64_t h = rotl(lanes[0], 1) + rotl(lanes[1], 7) + rotl(lanes[2], 12) + rotl(lanes[3], 18);
    h = (h ^ uint64_t(size)) * k2;
    return avalanche(h);
}

}  // namespace i2d
