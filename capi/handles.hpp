// SPDX-License-Identifier: MIT
// Id encoding: what the 64 bits of a public id hold, and how to build and read them.
//
// Layout, low to high: 24 bits slot index + 1, 16 bits slot generation, 12 bits world
// slot, 8 bits world generation, 3 bits kind; the top bit is always 0, so that an id
// reads the same as a signed or an unsigned 64-bit integer (a JavaScript BigInt from a
// function's return and from an event's array, a Java long). The kind tag makes a shape id passed as a
// body id (easy over FFI, where ids are plain integers) detectably wrong; the world
// generation makes ids of a destroyed world stale even after its slot is reused.
#pragma once

#include <cstdint>

#include <impulse2d/id.h>

namespace i2d::capi {

enum class IdKind : uint8_t { none = 0, world = 1, body = 2, shape = 3, joint = 4, chain = 5 };

struct IdFields {
    IdKind kind = IdKind::none;
    int32_t world_slot = 0;
    uint16_t world_generation = 0;
    int32_t index = -1;  // -1 for world ids
    uint16_t generation = 0;
};

inline uint64_t encode_id(const IdFields& f) {
    return (uint64_t(f.kind) << 60) | (uint64_t(f.world_generation & 0xFF) << 52) |
           (uint64_t(f.world_slot & 0xFFF) << 40) | (uint64_t(f.generation) << 24) |
           uint64_t((f.index + 1) & 0xFFFFFF);
}

inline IdFields decode_id(uint64_t bits) {
    IdFields f;
    f.kind = static_cast<IdKind>(bits >> 60);
    f.world_generation = static_cast<uint16_t>((bits >> 52) & 0xFF);
    f.world_slot = static_cast<int32_t>((bits >> 40) & 0xFFF);
    f.generation = static_cast<uint16_t>((bits >> 24) & 0xFFFF);
    f.index = static_cast<int32_t>(bits & 0xFFFFFF) - 1;
    return f;
}

}  // namespace i2d::capi
