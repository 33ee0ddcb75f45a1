// SPDX-License-Identifier: MIT
// World slots. Create and destroy take a lock; lookups read atomics, so that worlds
// used on different threads never wait for each other.
#include "registry.hpp"

#include <atomic>
#include <mutex>

namespace i2d::capi {

namespace {

struct WorldSlot {
    std::atomic<World*> world{nullptr};
    std::atomic<uint16_t> generation{0};
};

WorldSlot g_slots[max_worlds];
std::mutex g_mutex;
int32_t g_next_slot = 0;  // round robin: a freed slot is reused as late as possible

}  // namespace

// A slot's generation counts 1..255 and then starts again at 1 (0 is never used), so a
// process may create worlds forever. The price of finite id bits: an id of a destroyed
// world is refused until its slot has been reused 254 times; the 255th reuse gives the
// same bits again. Slots are taken round robin, so with few worlds alive that takes
// about 4096 x 255 (a million) further worlds; with all but one slot in use, 255.
WorldSlotRef register_world(World* world) {
    std::lock_guard<std::mutex> lock(g_mutex);
    for (int32_t k = 0; k < max_worlds; ++k) {
        const int32_t i = (g_next_slot + k) % max_worlds;
        WorldSlot& s = g_slots[i];
        if (s.world.load(std::memory_order_relaxed) != nullptr) {
            continue;
        }
        const uint16_t generation = next_world_generation(s.generation.load(std::memory_order_relaxed));
        s.generation.store(generation, std::memory_order_relaxed);
        s.world.store(world, std::memory_order_release);
        g_next_slot = (i + 1) % max_worlds;
        return {i, generation};
    }
    return {};
}

void release_world(int32_t slot) {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_slots[slot].world.store(nullptr, std::memory_order_release);
}

World* find_world(int32_t slot, uint16_t generation) {
    if (slot < 0 || slot >= max_worlds) {
        return nullptr;
    }
    const WorldSlot& s = g_slots[slot];
    World* world = s.world.load(std::memory_order_acquire);
    if (world == nullptr || s.generation.load(std::memory_order_relaxed) != generation) {
        return nullptr;
    }
    return world;
}

}  // namespace i2d::capi
