// SPDX-License-Identifier: MIT
// The fuzzer's input read as operands: bytes, integers of any sign, and floats drawn
// from hostile values (NaN, infinities, denormals, huge and negative) or raw bits. An
// exhausted input reads as zeros, so every program ends.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include <impulse2d/impulse2d.h>

class FuzzInput {
public:
    FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {}

    bool empty() const { return pos_ >= size_; }

    uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) {
            v = (v << 8) | byte();
        }
        return v;
    }

    uint64_t u64() { return (uint64_t(u32()) << 32) | u32(); }

    bool flag() { return (byte() & 1) != 0; }

    /// 0..limit, sometimes just outside it (negative or too many).
    int32_t count(int32_t limit) {
        const uint8_t b = byte();
        if (b > 250) {
            return b == 255 ? -1 : limit + 1;
        }
        return static_cast<int32_t>(b % (limit + 1));
    }

    /// Any float a caller could pass.
    float real() {
        const uint8_t kind = byte();
        if (kind < 96) {
            return small_value(kind);
        }
        if (kind < 160) {
            return special(kind - 96);
        }
        const uint32_t bits = u32();
        float v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }

    /// Mostly sensible sizes and coordinates (what a scene is built from), sometimes hostile.
    float small_real() {
        const uint8_t kind = byte();
        return kind < 224 ? small_value(kind) : special(kind);
    }

    i2d_vec2 vec2() { return i2d_vec2{real(), real()}; }
    i2d_vec2 small_vec2() { return i2d_vec2{small_real(), small_real()}; }

    /// Any 32-bit value in an enum field, as a C caller may store.
    template <class Enum>
    void raw_enum(Enum* out) {
        static_assert(sizeof(Enum) == sizeof(int32_t), "enums are 32-bit");
        const uint8_t b = byte();
        const int32_t v = b < 200 ? static_cast<int32_t>(b % 8) : static_cast<int32_t>(u32());
        std::memcpy(out, &v, sizeof v);
    }

private:
    // -4..4 in steps of 1/16 plus a fraction of a byte: dense near scene sizes.
    float small_value(uint8_t kind) { return (static_cast<float>(kind % 129) - 64.0f) / 16.0f + byte() / 4096.0f; }

    static float special(int which) {
        static const float values[] = {
            std::numeric_limits<float>::quiet_NaN(),
            std::numeric_limits<float>::infinity(),
            -std::numeric_limits<float>::infinity(),
            std::numeric_limits<float>::denorm_min(),
            -std::numeric_limits<float>::denorm_min(),
            FLT_MIN,
            FLT_MAX,
            -FLT_MAX,
            0.0f,
            -0.0f,
            1e-30f,
            1e20f,
            -1e20f,
            1e30f,
            1e9f,
            -1e9f,
            1.0000001e9f,
            1e5f,
            100000.01f,
            1e-4f,
            9.9e-5f,
            -1.0f,
            0.005f,
            1e38f,
        };
        return values[static_cast<size_t>(which) % (sizeof values / sizeof values[0])];
    }

    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;
};
