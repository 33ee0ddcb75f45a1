// SPDX-License-Identifier: MIT
// i2d_world_start_recording, i2d_world_stop_recording and i2d_replay_*.
//
// Replays live in a small process-wide table of their own: slot plus generation, as
// worlds do, so that the id of a closed replay stays stale.
#include <cstdio>
#include <memory>
#include <mutex>

#include "boundary.hpp"
#include "replay.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

/// Replays open at once.
constexpr int32_t max_replays = 64;

struct ReplaySlot {
    std::unique_ptr<Replay> replay;
    uint32_t generation = 0;
};

std::mutex& table_mutex() {
    static std::mutex m;
    return m;
}

ReplaySlot* table() {
    static ReplaySlot slots[max_replays];
    return slots;
}

// An id: generation in the high 32 bits, slot + 1 in the low (never 0: the null id).
i2d_replay_id make_replay_id(int32_t slot, uint32_t generation) {
    return i2d_replay_id{(uint64_t(generation) << 32) | uint64_t(slot + 1)};
}

// The open replay an id names, or null with I2D_ERR_INVALID_HANDLE. A replay is used by
// one thread at a time, as a world is.
Replay* find_replay(Call& call, i2d_replay_id id) {
    const int64_t slot = int64_t(id.bits & 0xFFFFFFFFu) - 1;
    const uint32_t generation = uint32_t(id.bits >> 32);
    const std::lock_guard<std::mutex> lock(table_mutex());
    if (slot < 0 || slot >= max_replays || table()[slot].replay == nullptr || table()[slot].generation != generation) {
        call.fail(I2D_ERR_INVALID_HANDLE, "replay id 0x%016llx is not an open replay",
                  static_cast<unsigned long long>(id.bits));
        return nullptr;
    }
    return table()[slot].replay.get();
}

}  // namespace

I2D_API i2d_status i2d_world_start_recording(i2d_world_id world, i2d_write_fn* write, void* context) {
    return guarded("i2d_world_start_recording", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.unlocked(*w.world)) {
            return last_status();
        }
        if (write == nullptr) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "write is NULL"), last_status();
        }
        w.world->start_recording(write, context);
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_stop_recording(i2d_world_id world) {
    return guarded("i2d_world_stop_recording", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.unlocked(*w.world)) {
            return last_status();
        }
        w.world->stop_recording();
        return I2D_OK;
    });
}

I2D_API i2d_replay_id i2d_replay_open(const void* recording, size_t size, const i2d_world_def* runtime) {
    return guarded("i2d_replay_open", i2d_replay_id{0}, [&](Call& call) -> i2d_replay_id {
        std::unique_ptr<Replay> replay = Replay::open(call, recording, size, runtime);
        if (replay == nullptr) {
            return i2d_replay_id{0};
        }
        const std::lock_guard<std::mutex> lock(table_mutex());
        for (int32_t slot = 0; slot < max_replays; ++slot) {
            ReplaySlot& s = table()[slot];
            if (s.replay == nullptr) {
                s.replay = std::move(replay);
                s.generation = s.generation == UINT32_MAX ? 1 : s.generation + 1;
                return make_replay_id(slot, s.generation);
            }
        }
        call.fail(I2D_ERR_CAPACITY, "%d replays are open, the most there can be", int(max_replays));
        return i2d_replay_id{0};
    });
}

I2D_API i2d_world_id i2d_replay_get_world(i2d_replay_id id) {
    return guarded("i2d_replay_get_world", I2D_NULL_WORLD_ID, [&](Call& call) {
        const Replay* replay = find_replay(call, id);
        return replay != nullptr ? replay->world() : I2D_NULL_WORLD_ID;
    });
}

I2D_API int32_t i2d_replay_step(i2d_replay_id id, int32_t step_count) {
    return guarded("i2d_replay_step", int32_t(0), [&](Call& call) -> int32_t {
        Replay* replay = find_replay(call, id);
        if (replay == nullptr) {
            return 0;
        }
        if (step_count < 0) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "step_count is %d; it must be >= 0", int(step_count));
            return 0;
        }
        return replay->run(call, step_count, true);
    });
}

I2D_API int32_t i2d_replay_get_step(i2d_replay_id id) {
    return guarded("i2d_replay_get_step", int32_t(0), [&](Call& call) {
        const Replay* replay = find_replay(call, id);
        return replay != nullptr ? replay->step() : 0;
    });
}

I2D_API int32_t i2d_replay_get_step_count(i2d_replay_id id) {
    return guarded("i2d_replay_get_step_count", int32_t(0), [&](Call& call) {
        const Replay* replay = find_replay(call, id);
        return replay != nullptr ? replay->step_count() : 0;
    });
}

I2D_API int32_t i2d_replay_get_divergent_step(i2d_replay_id id) {
    return guarded("i2d_replay_get_divergent_step", int32_t(-1), [&](Call& call) {
        const Replay* replay = find_replay(call, id);
        return replay != nullptr ? replay->divergent_step() : -1;
    });
}

I2D_API i2d_status i2d_replay_seek(i2d_replay_id id, int32_t step) {
    return guarded("i2d_replay_seek", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        Replay* replay = find_replay(call, id);
        if (replay == nullptr || !replay->seek(call, step)) {
            return last_status();
        }
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_replay_close(i2d_replay_id id) {
    return guarded("i2d_replay_close", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        if (find_replay(call, id) == nullptr) {
            return last_status();
        }
        std::unique_ptr<Replay> closing;
        {
            const std::lock_guard<std::mutex> lock(table_mutex());
            closing = std::move(table()[int32_t(id.bits & 0xFFFFFFFFu) - 1].replay);
        }
        return I2D_OK;  // closing goes out of scope: the replay and its world are gone
    });
}
