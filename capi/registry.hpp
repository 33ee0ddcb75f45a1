// SPDX-License-Identifier: MIT
// The process-wide table of worlds: slot plus generation, so that ids of a destroyed
// world stay stale even after its slot is reused.
#pragma once

#include <cstdint>

namespace i2d {
class World;
}

namespace i2d::capi {

constexpr int32_t max_worlds = 256;
constexpr uint16_t max_world_generation = 0xFFF;  // 12 bits in an id

struct WorldSlotRef {
    int32_t slot = -1;
    uint16_t generation = 0;
};

/// Places a world in a free slot; slot -1 when all are taken.
WorldSlotRef register_world(World* world);
/// Frees the slot. Its generation already moved on at registration of the next world.
void release_world(int32_t slot);
/// The live world of that slot and generation, or null.
World* find_world(int32_t slot, uint16_t generation);

}  // namespace i2d::capi
