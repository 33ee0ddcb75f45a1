// SPDX-License-Identifier: MIT
// i2d_worlds_step: the batch's checks, all before any world moves, and the pools of
// workers kept between batches.
#include <bitset>
#include <cstdio>
#include <memory>
#include <mutex>
#include <vector>

#include "boundary.hpp"
#include "core/task_system.hpp"
#include "dynamics/world/world_batch.hpp"
#include "registry.hpp"
#include "world_def.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// Workers kept between batches: starting a thread costs tens of microseconds, about as
// long as a batch of small worlds takes to step, and a training loop steps its batch
// every few milliseconds. A pool serves one batch at a time; a thread that starts a
// batch while the pool is busy gets one of its own, kept afterwards too, up to a few.
class BatchPools {
public:
    static constexpr std::size_t max_idle_pools = 4;

    std::unique_ptr<TaskSystem> take(int32_t worker_count) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            for (std::size_t i = 0; i < idle_.size(); ++i) {
                if (idle_[i]->worker_count() == worker_count) {
                    std::unique_ptr<TaskSystem> pool = std::move(idle_[i]);
                    idle_.erase(idle_.begin() + std::ptrdiff_t(i));
                    return pool;
                }
            }
        }
        return std::make_unique<TaskSystem>(worker_count, TaskCallbacks{});
    }

    void give_back(std::unique_ptr<TaskSystem> pool) {
        std::unique_ptr<TaskSystem> surplus;  // stopped outside the lock: joining threads takes a while
        std::lock_guard<std::mutex> lock(mutex_);
        if (idle_.size() < max_idle_pools) {
            idle_.push_back(std::move(pool));
        } else {
            surplus = std::move(idle_.front());
            idle_.erase(idle_.begin());
            idle_.push_back(std::move(pool));
        }
    }

private:
    std::mutex mutex_;
    std::vector<std::unique_ptr<TaskSystem>> idle_;
};

BatchPools& batch_pools() {
    static BatchPools pools;
    return pools;
}

bool valid_batch_def(Call& call, const i2d_batch_def* def) {
    return call.not_null(def, "batch def") && call.cookie(def->internal_cookie, "batch_def") &&
           valid_job_system(call, "batch def", def->worker_count, def->enqueue_task != nullptr,
                            def->finish_task != nullptr);
}

// Every id a live, unlocked world, each listed once; out gets the worlds.
bool gather_worlds(Call& call, const i2d_world_id* ids, int32_t count, std::vector<World*>& out) {
    std::bitset<max_worlds> listed;
    char field[32];
    out.reserve(std::size_t(count));
    for (int32_t i = 0; i < count; ++i) {
        WorldRef w;
        std::snprintf(field, sizeof field, "worlds[%d]", int(i));
        if (!call.world(ids[i], w) || !call.unlocked(*w.world)) {
            return call.fail_in(field);
        }
        if (listed.test(std::size_t(w.id.world_slot))) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s: the world is listed twice; list each world once",
                             field);
        }
        listed.set(std::size_t(w.id.world_slot));
        out.push_back(w.world);
    }
    return true;
}

i2d_status step_batch(Call& call, std::vector<World*>& worlds, float time_step, int32_t substep_count,
                      const i2d_batch_def& def) {
    BatchOutcome outcome = BatchOutcome::stepped;
    if (def.enqueue_task != nullptr) {
        TaskSystem tasks(def.worker_count, TaskCallbacks{def.enqueue_task, def.finish_task, def.user_task_context});
        outcome = step_worlds(worlds.data(), int32_t(worlds.size()), time_step, substep_count, tasks);
    } else {
        std::unique_ptr<TaskSystem> pool = batch_pools().take(def.worker_count);
        outcome = step_worlds(worlds.data(), int32_t(worlds.size()), time_step, substep_count, *pool);
        batch_pools().give_back(std::move(pool));
    }
    switch (outcome) {
        case BatchOutcome::stepped:
            return I2D_OK;
        case BatchOutcome::out_of_memory:
            call.fail(I2D_ERR_OUT_OF_MEMORY, "out of memory in a world's step; the other worlds were stepped");
            return last_status();
        case BatchOutcome::internal_error:
            break;
    }
    call.fail(I2D_ERR_INTERNAL, "internal error (an unexpected exception) in a world's step; please report it");
    return last_status();
}

}  // namespace

I2D_API i2d_batch_def i2d_default_batch_def(void) {
    set_ok();
    i2d_batch_def def{};
    def.worker_count = 1;
    def.internal_cookie = def_cookie;
    return def;
}

I2D_API i2d_status i2d_worlds_step(const i2d_world_id* worlds, int32_t count, float time_step,
                                   int32_t substep_count, const i2d_batch_def* def) {
    return guarded("i2d_worlds_step", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        if (!valid_batch_def(call, def) || !valid_step(call, time_step, substep_count)) {
            return last_status();
        }
        if (count < 0 || count > max_worlds) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "count is %d; it must be in [0, %d]", int(count), int(max_worlds));
            return last_status();
        }
        if (count > 0 && !call.not_null(worlds, "worlds")) {
            return last_status();
        }
        std::vector<World*> stepped;
        if (!gather_worlds(call, worlds, count, stepped)) {
            return last_status();
        }
        return step_batch(call, stepped, time_step, substep_count, *def);
    });
}
