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
// Each worker owns a contiguous share of every stage's blocks and claims its own first,
// through a counter on a cache line of its own; only then does it take what is left of
// the others' shares. Two reasons. The same items go to the same worker in every stage
// and substep, so a body's state stays in one core's cache instead of crossing to the
// other core each colour. And a worker that only claims its own share touches no line
// another core writes, except once per stage to count its blocks done: on a machine
// whose cores trade a cache line in hundreds of nanoseconds, a shared claim counter
// cost more per stage than the work of a small stage.
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
    /// When set, the stage runs only if this is true once the stages before it are done
    /// (an earlier stage decides it): skipping costs no wait between workers.
    const bool* run_if = nullptr;

    bool runs() const { return item_count > 0 && (run_if == nullptr || *run_if); }

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
    // A worker's share of one stage's blocks: [next, end) are still unclaimed.
    struct alignas(64) Share {
        std::atomic<int32_t> next{0};
        int32_t end = 0;
    };
    struct alignas(64) Done {
        std::atomic<int32_t> blocks{0};
    };
    static void work_on(int32_t worker, void* runner);
    void work(int32_t worker);
    int32_t claim_blocks(const Stage& stage, Share* shares, int32_t worker);
    void reserve(int32_t stage_count);
    int32_t next_to_run(int32_t after) const;

    std::vector<Stage> active_;  // the run's stages that have items
    int32_t workers_ = 1;
    std::unique_ptr<Share[]> shares_;  // workers_ per active stage
    std::unique_ptr<Done[]> done_;     // one per active stage
    int32_t capacity_ = 0;             // stages the arrays hold, for capacity_workers_ workers
    int32_t capacity_workers_ = 0;
    alignas(64) std::atomic<int32_t> current_{0};  // the open stage; the stage count when done
};

}  // namespace i2d
