// SPDX-License-Identifier: MIT
// The process-wide table of worlds: slot plus generation, so that ids of a destroyed
// world stay stale even after its slot is reused.
#pragma once

#include <cstdint>

#include <impulse2d/types.h>

namespace i2d {
class World;
}

namespace i2d::capi {

/// Worlds alive at once (12 bits of an id). Creating and destroying is unlimited.
constexpr int32_t max_worlds = I2D_MAX_WORLDS;
constexpr uint16_t max_world_generation = 0xFF;  // 8 bits in an id

/// The generation after g: 1..max_world_generation, round and round; 0 never (it would
/// make the id of slot 0's first world all but null).
constexpr uint16_t next_world_generation(uint16_t g) {
    return g >= max_world_generation ? uint16_t(1) : static_cast<uint16_t>(g + 1);
}

struct WorldSlotRef {
    int32_t slot = -1;
    uint16_t generation = 0;
};

/// Places a world in a free slot; slot -1 when max_worlds are alive.
WorldSlotRef register_world(World* world);
/// Frees the slot. Its generation already moved on at registration of the next world.
void release_world(int32_t slot);
/// The live world of that slot and generation, or null.
World* find_world(int32_t slot, uint16_t generation);

}  // namespace i2d::capi
