// SPDX-License-Identifier: MIT
// StageRunner: a list of stages run one after the other, each stage's items split into
// blocks that the workers claim.
//
// Design note (after Box2D v3's solver stages): one run hands each worker a single task
// that lasts through every stage, so a step with a hundred stages pays for waking its
// workers once, and the stages are separated by a counter, not by a task round trip.
// No worker leads: a worker claims blocks of the current stage until none are left, and
// whoever completes a stage's last block opens the next stage. So any subset of the
// workers, even one, finishes the run: a job system that starts some tasks late, out of
// order, or runs them one after another cannot deadlock it.
//
// The split into blocks never changes a result: a stage's items must be independent of
// one another (each writes only what is its own), which is what makes a world's results
// the same bits for every worker count.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/task_system.hpp"

namespace i2d {

struct Stage {
    /// Does items [begin, end) of the stage on worker `worker`.
    using Fn = void (*)(void* owner, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    Fn fn = nullptr;
    void* owner = nullptr;
    int32_t item_count = 0;
    int32_t items_per_block = 1;  // a stage that must run as a whole: item_count
    int32_t arg0 = 0, arg1 = 0;   // the owner's own (which colour, which substep)

    int32_t block_count() const { return (item_count + items_per_block - 1) / items_per_block; }
};

/// Items per block for `items` spread over `workers`: a few blocks per worker, so that
/// one slow worker does not hold a stage up, but no block smaller than min_items.
int32_t items_per_block(int32_t items, int32_t workers, int32_t min_items);

/// A stage over item_count items: in blocks for `workers` when parallel, else one block.
Stage make_stage(Stage::Fn fn, void* owner, int32_t item_count, int32_t workers, bool parallel,
                 int32_t min_items_per_block);

class StageRunner {
public:
    /// Runs the stages in order on the task system's workers, or inline on the calling
    /// thread (each stage as one block) when `parallel` is false or there is one worker.
    void run(TaskSystem& tasks, const std::vector<Stage>& stages, bool parallel);

private:
    struct alignas(64) Progress {
        std::atomic<int32_t> next_block{0};
        std::atomic<int32_t> done_blocks{0};
    };
    static void work_on(int32_t worker, void* runner);
    void work(int32_t worker);

    std::vector<Stage> active_;  // the run's stages that have items
    std::unique_ptr<Progress[]> progress_;
    int32_t progress_capacity_ = 0;
    alignas(64) std::atomic<int32_t> current_{0};  // the open stage; the stage count when done
};

}  // namespace i2d
