// SPDX-License-Identifier: MIT
// StageRunner: claim blocks, and open the next stage on completing the last one.
#include "core/stage_runner.hpp"

#include "core/spin_wait.hpp"

namespace i2d {

int32_t items_per_block(int32_t items, int32_t workers, int32_t min_items) {
    constexpr int32_t blocks_per_worker = 4;
    const int32_t blocks = workers * blocks_per_worker;
    const int32_t size = (items + blocks - 1) / blocks;
    return size > min_items ? size : (min_items > 0 ? min_items : 1);
}

Stage make_stage(Stage::Fn fn, void* owner, int32_t item_count, int32_t workers, bool parallel,
                 int32_t min_items_per_block) {
    Stage stage;
    stage.fn = fn;
    stage.owner = owner;
    stage.item_count = item_count;
    stage.items_per_block = parallel ? items_per_block(item_count, workers, min_items_per_block)
                                     : (item_count > 0 ? item_count : 1);
    return stage;
}

void StageRunner::run(TaskSystem& tasks, const std::vector<Stage>& stages, bool parallel) {
    if (!parallel || tasks.worker_count() == 1) {
        for (const Stage& stage : stages) {
            if (stage.runs()) {
                stage.fn(stage.owner, stage, 0, stage.item_count, 0);
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
    const int32_t count = int32_t(active_.size());
    reserve(count);
    for (int32_t s = 0; s < count; ++s) {
        const int32_t blocks = active_[std::size_t(s)].block_count();
        Share* shares = &shares_[std::size_t(s) * std::size_t(workers_)];
        for (int32_t w = 0; w < workers_; ++w) {
            shares[w].next.store(int32_t(int64_t(blocks) * w / workers_), std::memory_order_relaxed);
            shares[w].end = int32_t(int64_t(blocks) * (w + 1) / workers_);
        }
        done_[s].blocks.store(0, std::memory_order_relaxed);
    }
    current_.store(next_to_run(-1), std::memory_order_release);
    tasks.run_on_workers(&work_on, this);
}

void StageRunner::reserve(int32_t stage_count) {
    if (stage_count <= capacity_ && workers_ == capacity_workers_) {
        return;
    }
    capacity_ = stage_count + stage_count / 2;
    capacity_workers_ = workers_;
    shares_ = std::make_unique<Share[]>(std::size_t(capacity_) * std::size_t(workers_));
    done_ = std::make_unique<Done[]>(std::size_t(capacity_));
}

// Called by whoever opens a stage, after every stage before it is done: a stage's run_if
// is final by then.
int32_t StageRunner::next_to_run(int32_t after) const {
    int32_t s = after + 1;
    while (s < int32_t(active_.size()) && !active_[std::size_t(s)].runs()) {
        ++s;
    }
    return s;
}

void StageRunner::work_on(int32_t worker, void* runner) { static_cast<StageRunner*>(runner)->work(worker); }

void StageRunner::work(int32_t worker) {
    const int32_t count = int32_t(active_.size());
    int32_t s = current_.load(std::memory_order_acquire);
    while (s < count) {
        const Stage& stage = active_[std::size_t(s)];
        const int32_t done_here = claim_blocks(stage, &shares_[std::size_t(s) * std::size_t(workers_)], worker);
        // The release half publishes this worker's blocks; the count's last addition
        // acquires them all before it opens the next stage.
        if (done_here > 0 &&
            done_[s].blocks.fetch_add(done_here, std::memory_order_acq_rel) + done_here == stage.block_count()) {
            current_.store(next_to_run(s), std::memory_order_release);
        }
        SpinWait spin;
        int32_t next = current_.load(std::memory_order_acquire);
        while (next == s) {
            spin.once();
            next = current_.load(std::memory_order_acquire);
        }
        s = next;
    }
}

// The worker's own share first, then the others' in turn; returns how many blocks it did.
int32_t StageRunner::claim_blocks(const Stage& stage, Share* shares, int32_t worker) {
    int32_t done_here = 0;
    for (int32_t i = 0; i < workers_; ++i) {
        const int32_t owner = worker + i < workers_ ? worker + i : worker + i - workers_;
        Share& share = shares[owner];
        // A plain read first: a finished share is not written to again.
        if (share.next.load(std::memory_order_relaxed) >= share.end) {
            continue;
        }
        for (;;) {
            const int32_t block = share.next.fetch_add(1, std::memory_order_relaxed);
            if (block >= share.end) {
                break;
            }
            const int32_t begin = block * stage.items_per_block;
            const int32_t end = begin + stage.items_per_block < stage.item_count ? begin + stage.items_per_block
                                                                                  : stage.item_count;
            stage.fn(stage.owner, stage, begin, end, worker);
            ++done_here;
        }
    }
    return done_here;
}

}  // namespace i2d
