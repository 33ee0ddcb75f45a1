// SPDX-License-Identifier: MIT
// StageRunner: claim blocks from the front of one's share and the back of the others',
// count them done, wait for the stage's total.
#include "core/stage_runner.hpp"

#include "core/assert.hpp"
#include "core/cycle_clock.hpp"
#include "core/spin_wait.hpp"

namespace i2d {

namespace {
int32_t front_of(uint64_t range) { return int32_t(range & 0xffffffffu); }
int32_t end_of(uint64_t range) { return int32_t(range >> 32); }
uint64_t range_of(int32_t front, int32_t end) { return uint64_t(uint32_t(front)) | uint64_t(uint32_t(end)) << 32; }
}  // namespace

int32_t items_per_block(int32_t items, int32_t workers, int32_t min_items) {
    // A stage's blocks are its shortest wait: the last one started is what the others
    // wait for. With 4 a worker, large_pyramid with 2 workers stepped 6 % slower
    // (paired runs: 0.94 with 8; 16 gave 0.99, the claims costing what the waits saved).
    constexpr int32_t blocks_per_worker = 8;
    const int32_t blocks = workers * blocks_per_worker;
    const int32_t size = (items + blocks - 1) / blocks;
    return size > min_items ? size : (min_items > 0 ? min_items : 1);
}

void StageRunner::run(TaskSystem& tasks, const std::vector<Stage>& stages, bool parallel, const void* context) {
    times_.clear();
    if (!parallel || tasks.worker_count() == 1) {
        for (const Stage& stage : stages) {
            if (stage.runs()) {
                stage.fn(context, stage, 0, stage.item_count, 0);
            }
        }
        return;
    }
    active_.clear();
    for (const Stage& stage : stages) {
        if (stage.item_count > 0) {
            active_.push_back(stage);
        }
    }
    if (active_.empty()) {
        return;
    }
    workers_ = tasks.worker_count();
    context_ = context;
    reserve(int32_t(active_.size()));
    lay_out_shares();
    for (int32_t w = 0; w < workers_; ++w) {
        done_[std::size_t(w)].blocks.store(0, std::memory_order_relaxed);
        done_[std::size_t(w)].time = WorkerTime{};
    }
    tasks.run_on_workers(&work_on, this);
    for (int32_t w = 0; w < workers_; ++w) {
        times_.push_back(done_[std::size_t(w)].time);
    }
}

// Each worker's share of every stage: the owner's split, or the blocks split evenly.
void StageRunner::lay_out_shares() {
    const std::size_t bounds = std::size_t(workers_) + 1;
    share_bounds_.resize(active_.size() * bounds);
    stage_blocks_.resize(active_.size());
    for (std::size_t s = 0; s < active_.size(); ++s) {
        const Stage& stage = active_[s];
        int32_t* first = share_bounds_.data() + s * bounds;
        const int64_t blocks = stage.block_count();
        for (int32_t w = 0; w <= workers_; ++w) {
            const int64_t even = int64_t(stage.items_per_block) * (blocks * w / workers_);
            first[w] = stage.share_starts != nullptr ? stage.share_starts[w]
                                                     : int32_t(even < stage.item_count ? even : stage.item_count);
        }
        I2D_ASSERT(first[0] == 0 && first[workers_] == stage.item_count);
        int32_t total = 0;
        for (int32_t w = 0; w < workers_; ++w) {
            I2D_ASSERT(first[w] <= first[w + 1]);
            const int32_t own = stage.blocks_of(first[w + 1] - first[w]);
            share(w, int32_t(s)).range.store(range_of(0, own), std::memory_order_relaxed);
            total += own;
        }
        stage_blocks_[s] = total;
    }
}

void StageRunner::reserve(int32_t stage_count) {
    if (stage_count <= capacity_ && workers_ == capacity_workers_) {
        return;
    }
    const int32_t wanted = stage_count + stage_count / 2;
    capacity_ = (wanted + shares_per_line - 1) / shares_per_line * shares_per_line;
    capacity_workers_ = workers_;
    share_lines_ = std::make_unique<ShareLine[]>(std::size_t(capacity_ / shares_per_line) * std::size_t(workers_));
    done_ = std::make_unique<DoneCount[]>(std::size_t(workers_));
}

void StageRunner::work_on(int32_t worker, void* runner) { static_cast<StageRunner*>(runner)->work(worker); }

// Every worker walks every stage; whether a stage runs (its run_if) is read only after
// the stages before it are done, so all workers skip the same ones.
void StageRunner::work(int32_t worker) {
    const uint64_t start = cycle_now();
    uint64_t waited = 0;
    int32_t blocks_before_next = 0;
    int32_t done_here = 0;  // blocks this worker did in the run
    for (int32_t s = 0; s < int32_t(active_.size()); ++s) {
        const Stage& stage = active_[std::size_t(s)];
        if (!stage.runs()) {
            continue;
        }
        blocks_before_next += stage_blocks_[std::size_t(s)];
        int32_t done = count_done(worker, done_here, claim_own(stage, s, worker));
        if (done >= blocks_before_next) {
            continue;
        }
        const uint64_t wait_start = cycle_now();
        SpinWait spin;
        for (int64_t spins = 1; done < blocks_before_next; ++spins) {
            // Late blocks are taken over only after a short wait: most stages end within
            // it, and looking at another worker's share costs a cache line from its core.
            // A worker's last block is left to it (it is likely working on the one before)
            // unless the wait goes on long: the worker may not have started at all.
            if (spins % spins_before_taking_over == 0) {
                const uint64_t taking_start = cycle_now();
                const int32_t taken = take_over(stage, s, worker, spins < spins_before_taking_all ? 1 : 0);
                if (taken > 0) {
                    waited -= cycle_now() - taking_start;  // work, not waiting
                    done = count_done(worker, done_here, taken);
                    continue;
                }
            }
            spin.once();
            done = count_done(worker, done_here, 0);
        }
        waited += cycle_now() - wait_start;
    }
    done_[std::size_t(worker)].time = WorkerTime{done_here, cycle_now() - start - waited};
}

// Adds `blocks` to this worker's count and returns the run's. Each count has one writer,
// so a plain store publishes it: the worker goes on at once, where an atomic add to a
// count the waiting core is reading would stall it for a round trip between the cores at
// every stage's end. The release store publishes this worker's blocks; whoever reads the
// counts that end the stage acquires them all.
int32_t StageRunner::count_done(int32_t worker, int32_t& done_here, int32_t blocks) {
    if (blocks > 0) {
        done_here += blocks;
        done_[std::size_t(worker)].blocks.store(done_here, std::memory_order_release);
    }
    int32_t total = 0;
    for (int32_t w = 0; w < workers_; ++w) {
        total += w == worker ? done_here : done_[std::size_t(w)].blocks.load(std::memory_order_acquire);
    }
    return total;
}

int32_t StageRunner::claim_own(const Stage& stage, int32_t s, int32_t worker) {
    int32_t done_here = 0;
    Share& mine = share(worker, s);
    for (int32_t block = claim_front(mine); block >= 0; block = claim_front(mine)) {
        run_block(stage, s, worker, block, worker);
        ++done_here;
    }
    return done_here;
}

// Blocks from the back of the other workers' shares, while more than `leave` are left.
int32_t StageRunner::take_over(const Stage& stage, int32_t s, int32_t worker, int32_t leave) {
    int32_t done_here = 0;
    for (int32_t other = 0; other < workers_; ++other) {
        if (other == worker) {
            continue;
        }
        Share& theirs = share(other, s);
        for (int32_t block = claim_back(theirs, leave); block >= 0; block = claim_back(theirs, leave)) {
            run_block(stage, s, other, block, worker);
            ++done_here;
        }
    }
    return done_here;
}

int32_t StageRunner::claim_front(Share& share) {
    uint64_t range = share.range.load(std::memory_order_relaxed);
    while (front_of(range) < end_of(range)) {
        if (share.range.compare_exchange_weak(range, range_of(front_of(range) + 1, end_of(range)),
                                              std::memory_order_relaxed)) {
            return front_of(range);
        }
    }
    return -1;
}

int32_t StageRunner::claim_back(Share& share, int32_t leave) {
    uint64_t range = share.range.load(std::memory_order_relaxed);
    while (front_of(range) + leave < end_of(range)) {
        if (share.range.compare_exchange_weak(range, range_of(front_of(range), end_of(range) - 1),
                                              std::memory_order_relaxed)) {
            return end_of(range) - 1;
        }
    }
    return -1;
}

// Block `block` of `owner`'s share of stage s, done by `worker`.
void StageRunner::run_block(const Stage& stage, int32_t s, int32_t owner, int32_t block, int32_t worker) const {
    const int32_t* first = share_bounds_.data() + std::size_t(s) * std::size_t(workers_ + 1);
    const int32_t begin = first[owner] + block * stage.items_per_block;
    const int32_t share_end = first[owner + 1];
    const int32_t end = begin + stage.items_per_block < share_end ? begin + stage.items_per_block : share_end;
    stage.fn(context_, stage, begin, end, worker);
}

}  // namespace i2d
