// SPDX-License-Identifier: MIT
// StateHash: a 64-bit FNV-1a hash over the exact bits of values, for telling whether two
// simulations are in bitwise the same state (determinism tests, replays, lockstep).
#pragma once

#include <cstdint>
#include <cstring>

namespace i2d {

class StateHash {
public:
    void add_bytes(const void* data, std::size_t size) {
        const unsigned char* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value_ = (value_ ^ bytes[i]) * prime;
        }
    }
    void add(float value) { add_bytes(&value, sizeof value); }
    void add(int32_t value) { add_bytes(&value, sizeof value); }
    uint64_t value() const { return value_; }

private:
    static constexpr uint64_t prime = 0x100000001b3ull;
    uint64_t value_ = 0xcbf29ce484222325ull;  // FNV offset basis
};

}  // namespace i2d
