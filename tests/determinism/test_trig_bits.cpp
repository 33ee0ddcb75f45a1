// SPDX-License-Identifier: MIT
// The engine's trigonometry gives the same bits in every build: i2d_make_rot and
// i2d_rot_get_angle over a sweep of angles, hashed and compared with a recorded value.
// Accuracy against long double is tested in unit/test_trig.cpp; this test only pins the
// bits, so that a compiler, flag or platform that changes them fails here.
#include <impulse2d/impulse2d.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "check.h"

namespace {

uint64_t mix(uint64_t hash, float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return (hash ^ bits) * 0x100000001B3ull;  // FNV-1a, a word at a time
}

}  // namespace

I2D_TEST(det_trigonometry_bits_are_recorded) {
    uint64_t hash = 0xCBF29CE484222325ull;
    for (int i = -20000; i <= 20000; ++i) {
        const float angle = float(i) * 0.0123f;  // about -246 to 246 rad
        const i2d_rot q = i2d_make_rot(angle);
        hash = mix(mix(hash, q.c), q.s);
        hash = mix(hash, i2d_rot_get_angle(q));
    }
    const float large[] = {1e5f, -3.3e4f, 123456.7f, 1e9f};
    for (float angle : large) {
        const i2d_rot q = i2d_make_rot(angle);
        hash = mix(mix(hash, q.c), q.s);
    }
    constexpr uint64_t recorded = 0x79846e80775a27dfull;
    std::fprintf(stderr, "    trigonometry hash %016" PRIx64 ", recorded %016" PRIx64 "\n", hash, recorded);
    I2D_CHECK(hash == recorded);
}
