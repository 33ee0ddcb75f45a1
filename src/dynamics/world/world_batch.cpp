// SPDX-License-Identifier: MIT
// step_worlds: the worlds shared out to the workers one at a time.
#include "dynamics/world/world_batch.hpp"

#include <atomic>
#include <new>

#include "core/task_system.hpp"
#include "dynamics/world/world.hpp"

namespace i2d {

namespace {

struct BatchWork {
    World* const* worlds;
    int32_t count;
    float time_step;
    int32_t substep_count;
    std::atomic<int32_t> next_world{0};
    std::atomic<int32_t> worst_outcome{int32_t(BatchOutcome::stepped)};

    void record(BatchOutcome outcome) {
        int32_t seen = worst_outcome.load(std::memory_order_relaxed);
        while (seen < int32_t(outcome) &&
               !worst_outcome.compare_exchange_weak(seen, int32_t(outcome), std::memory_order_relaxed)) {
        }
    }
};

void step_claimed_worlds(int32_t, void* context) {
    BatchWork& work = *static_cast<BatchWork*>(context);
    for (int32_t i = work.next_world.fetch_add(1, std::memory_order_relaxed); i < work.count;
         i = work.next_world.fetch_add(1, std::memory_order_relaxed)) {
        try {
            work.worlds[i]->step(work.time_step, work.substep_count);
        } catch (const std::bad_alloc&) {
            work.record(BatchOutcome::out_of_memory);
        } catch (...) {
            work.record(BatchOutcome::internal_error);
        }
    }
}

// Marks the worlds as in the batch from before the first worker starts until after the
// last has returned, also when a worker's start throws.
class BatchMark {
public:
    BatchMark(World* const* worlds, int32_t count) : worlds_(worlds), count_(count) { set(true); }
    ~BatchMark() { set(false); }
    BatchMark(const BatchMark&) = delete;
    BatchMark& operator=(const BatchMark&) = delete;

private:
    void set(bool in_batch) {
        for (int32_t i = 0; i < count_; ++i) {
            worlds_[i]->set_in_batch(in_batch);
        }
    }
    World* const* worlds_;
    int32_t count_;
};

}  // namespace

BatchOutcome step_worlds(World* const* worlds, int32_t count, float time_step, int32_t substep_count,
                         TaskSystem& tasks) {
    BatchWork work{worlds, count, time_step, substep_count};
    const BatchMark mark(worlds, count);
    tasks.run_on_workers(&step_claimed_worlds, &work);
    return BatchOutcome(work.worst_outcome.load(std::memory_order_relaxed));
}

}  // namespace i2d
