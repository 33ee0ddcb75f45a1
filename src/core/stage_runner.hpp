// SPDX-License-Identifier: MIT
// StageRunner: a list of stages run one after the other, each stage's items split into
// blocks that the workers claim.
//
// Design note (after Box2D v3's solver stages): one run hands each worker a single task
// that lasts through every stage, so a step with a hundred stages pays for waking its
// workers once, and the stages are separated by a counter, not by a task round trip.
//
// Each worker owns a contiguous share of every stage's blocks and claims them from the
// front, through a counter in memory of its own. The same items go to the same worker in
// every stage and substep, so a body's state stays in one core's cache rather than
// crossing to the other core each colour. A worker done with its share takes blocks from
// the back of the others' shares: when one core runs slower for a while (a shared machine,
// an interrupt), the other takes over its last blocks and the owners keep the rest. A
// stage ends when the blocks the workers have done reach the sum of the blocks of the
// stages so far; each worker counts what it did (once, or again for blocks it took over)
// and waits for the others' counts. On a machine whose cores trade a cache line in
// hundreds of nanoseconds, that wait, not the work, is what a small stage costs, so it is
// kept to one write of a worker's own line and reads of the others'.
//
// A worker never blocks inside a stage, and any subset of the workers, even one, finishes
// the run: a job system that starts some tasks late, out of order, or runs them one
// after another cannot deadlock it.
//
// The split into blocks never changes a result: a stage's items must be independent of
// one another (each writes only what is its own), which is what makes a world's results
// the same bits for every worker count.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/task_system.hpp"

namespace i2d {

struct Stage {
    /// Does items [begin, end) of the stage on worker `worker`; `context` is what the run
    /// was given (the step's context). Made by make_stage from a typed function.
    using Fn = void (*)(const void* context, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    Fn fn = nullptr;
    void* owner = nullptr;
    int32_t item_count = 0;
    int32_t items_per_block = 1;  // a stage that must run as a whole: item_count
    /// When set, the stage runs only if this is true once the stages before it are done
    /// (an earlier stage decides it): skipping costs no wait between workers.
    const bool* run_if = nullptr;
    /// When set, the item where each worker's share begins: worker_count + 1 entries,
    /// rising from 0 to item_count (the owner's memory, read as the run starts). A worker's
    /// blocks then start at its share's first item, not at multiples of items_per_block.
    /// An owner that splits every stage at the same items (the same bodies) keeps each
    /// worker on the same data from stage to stage. When null, the blocks split evenly.
    const int32_t* share_starts = nullptr;

    bool runs() const { return item_count > 0 && (run_if == nullptr || *run_if); }

    int32_t block_count() const { return blocks_of(item_count); }
    int32_t blocks_of(int32_t items) const { return (items + items_per_block - 1) / items_per_block; }

    /// The stage's own argument (which colours, which pass), of the type its function
    /// takes: a few bytes of plain data, copied in and out.
    template <class Arg>
    void set_arg(const Arg& arg) {
        static_assert(sizeof(Arg) <= arg_capacity && std::is_trivially_copyable<Arg>::value,
                      "a stage argument is a few bytes of plain data");
        std::memcpy(arg_bytes, &arg, sizeof arg);
    }
    template <class Arg>
    Arg arg() const {
        Arg arg;
        std::memcpy(&arg, arg_bytes, sizeof arg);
        return arg;
    }

    static constexpr std::size_t arg_capacity = 16;
    alignas(8) unsigned char arg_bytes[arg_capacity] = {};
};

/// No argument: for stages whose items say everything.
struct NoStageArg {};

/// Items per block for `items` spread over `workers`: a few blocks per worker, so that
/// one slow worker does not hold a stage up, but no block smaller than min_items.
int32_t items_per_block(int32_t items, int32_t workers, int32_t min_items);

/// The untyped function that calls a typed stage function F:
///   void F(const Context& context, Owner& owner, const Arg& arg, int32_t begin, int32_t end, int32_t worker)
template <auto F>
struct StageFn;
template <class Context, class Owner, class Arg,
          void (*F)(const Context&, Owner&, const Arg&, int32_t, int32_t, int32_t)>
struct StageFn<F> {
    using OwnerType = Owner;
    using ArgType = Arg;
    static void call(const void* context, const Stage& stage, int32_t begin, int32_t end, int32_t worker) {
        F(*static_cast<const Context*>(context), *static_cast<Owner*>(stage.owner), stage.arg<Arg>(), begin, end,
          worker);
    }
};

/// A stage of the typed function F over item_count items of `owner`, with argument
/// `arg`: in blocks for `workers` when parallel, else one block.
template <auto F>
Stage make_stage(typename StageFn<F>::OwnerType& owner, const typename StageFn<F>::ArgType& arg, int32_t item_count,
                 int32_t workers, bool parallel, int32_t min_items_per_block) {
    Stage stage;
    stage.fn = &StageFn<F>::call;
    stage.owner = &owner;
    stage.set_arg(arg);
    stage.item_count = item_count;
    stage.items_per_block = parallel ? items_per_block(item_count, workers, min_items_per_block)
                                     : (item_count > 0 ? item_count : 1);
    return stage;
}

class StageRunner {
public:
    /// Runs the stages in order on the task system's workers, or inline on the calling
    /// thread (each stage as one block) when `parallel` is false or there is one worker;
    /// each stage's function gets `context`.
    void run(TaskSystem& tasks, const std::vector<Stage>& stages, bool parallel, const void* context);

    /// What each worker did in the last run: the blocks it ran (its own and those it
    /// took over) and the time it spent on them, in cycle_now() ticks (waits left out).
    /// A worker that found nothing to do ran 0 blocks; a run inline or without stages
    /// leaves the list empty.
    struct WorkerTime {
        int32_t blocks = 0;
        uint64_t busy = 0;
    };
    const std::vector<WorkerTime>& worker_times() const { return times_; }

private:
    // A worker's share of one stage's blocks, numbered from its share's first item:
    // [front, end) are still unclaimed, front in the low half, end in the high half. The
    // owner claims from the front; a worker done with its own share takes from the back,
    // so the owner keeps all but the last blocks.
    struct Share {
        std::atomic<uint64_t> range{0};
    };
    static constexpr int32_t shares_per_line = 8;
    // Pauses a worker waits for a stage's end before it takes over another's blocks:
    // about a microsecond.
    static constexpr int32_t spins_before_taking_over = 32;
    // ... and before it takes a worker's last block too: tens of microseconds.
    static constexpr int32_t spins_before_taking_all = 1024;
    struct alignas(64) ShareLine {
        Share shares[shares_per_line];
    };
    static void work_on(int32_t worker, void* runner);
    void work(int32_t worker);
    int32_t claim_own(const Stage& stage, int32_t s, int32_t worker);
    int32_t take_over(const Stage& stage, int32_t s, int32_t worker, int32_t leave);
    int32_t count_done(int32_t worker, int32_t& done_here, int32_t blocks);
    static int32_t claim_front(Share& share);
    static int32_t claim_back(Share& share, int32_t leave);
    void lay_out_shares();
    void run_block(const Stage& stage, int32_t s, int32_t owner, int32_t block, int32_t worker) const;
    Share& share(int32_t worker, int32_t s) {
        const std::size_t k = std::size_t(worker) * std::size_t(capacity_) + std::size_t(s);
        return share_lines_[k / shares_per_line].shares[k % shares_per_line];
    }
    void reserve(int32_t stage_count);

    std::vector<Stage> active_;  // the run's stages that have items
    const void* context_ = nullptr;
    // Per active stage: the first item of each worker's share and the stage's end
    // (workers_ + 1 entries), then the stage's blocks in all.
    std::vector<int32_t> share_bounds_;
    std::vector<int32_t> stage_blocks_;
    int32_t workers_ = 1;
    // Per worker, its shares of every stage, one after the other (capacity_ of them, a
    // whole number of cache lines): a worker claiming its own writes only its own lines.
    std::unique_ptr<ShareLine[]> share_lines_;
    int32_t capacity_ = 0;  // stages per worker the shares hold
    int32_t capacity_workers_ = 0;
    // Per worker, on a line of its own: the blocks it did in the run so far, and its time
    // when the run ends.
    struct alignas(64) DoneCount {
        std::atomic<int32_t> blocks{0};
        WorkerTime time;
    };
    std::unique_ptr<DoneCount[]> done_;
    std::vector<WorkerTime> times_;  // the last run's, gathered from done_
};

}  // namespace i2d
