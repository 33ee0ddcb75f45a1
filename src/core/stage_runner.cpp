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
    for (int32_t w = 0; w < workers_; ++w) {
        for (int32_t s = 0; s < count; ++s) {
            const int64_t blocks = active_[std::size_t(s)].block_count();
            Share& mine = share(w, s);
            mine.next.store(int32_t(blocks * w / workers_), std::memory_order_relaxed);
            mine.end = int32_t(blocks * (w + 1) / workers_);
        }
        arrivals_[w].arrived.store(false, std::memory_order_relaxed);
    }
    blocks_done_.store(0, std::memory_order_release);
    tasks.run_on_workers(&work_on, this);
}

void StageRunner::reserve(int32_t stage_count) {
    if (stage_count <= capacity_ && workers_ == capacity_workers_) {
        return;
    }
    const int32_t wanted = stage_count + stage_count / 2;
    capacity_ = (wanted + shares_per_line - 1) / shares_per_line * shares_per_line;
    capacity_workers_ = workers_;
    share_lines_ = std::make_unique<ShareLine[]>(std::size_t(capacity_ / shares_per_line) * std::size_t(workers_));
    arrivals_ = std::make_unique<Arrival[]>(std::size_t(workers_));
}

void StageRunner::work_on(int32_t worker, void* runner) { static_cast<StageRunner*>(runner)->work(worker); }

// Every worker walks every stage; whether a stage runs (its run_if) is read only after
// the stages before it are done, so all workers skip the same ones.
void StageRunner::work(int32_t worker) {
    arrivals_[worker].arrived.store(true, std::memory_order_relaxed);
    int32_t blocks_before_next = 0;
    for (int32_t s = 0; s < int32_t(active_.size()); ++s) {
        const Stage& stage = active_[std::size_t(s)];
        if (!stage.runs()) {
            continue;
        }
        blocks_before_next += stage.block_count();
        const int32_t done_here = claim_blocks(stage, s, worker);
        // The release half publishes this worker's blocks; whoever reads the total that
        // ends the stage acquires them all.
        int32_t done = done_here > 0 ? blocks_done_.fetch_add(done_here, std::memory_order_acq_rel) + done_here
                                     : blocks_done_.load(std::memory_order_acquire);
        SpinWait spin;
        while (done < blocks_before_next) {
            spin.once();
            done = blocks_done_.load(std::memory_order_acquire);
        }
    }
}

// The worker's own share, then the shares of workers that have not arrived; returns how
// many blocks it did.
int32_t StageRunner::claim_blocks(const Stage& stage, int32_t s, int32_t worker) {
    int32_t done_here = claim_share(stage, share(worker, s), worker);
    for (int32_t other = 0; other < workers_; ++other) {
        if (other != worker && !arrivals_[other].arrived.load(std::memory_order_relaxed)) {
            done_here += claim_share(stage, share(other, s), worker);
        }
    }
    return done_here;
}

int32_t StageRunner::claim_share(const Stage& stage, Share& share, int32_t worker) {
    int32_t done_here = 0;
    // A plain read first: a share used up is not written to again.
    if (share.next.load(std::memory_order_relaxed) >= share.end) {
        return 0;
    }
    for (;;) {
        const int32_t block = share.next.fetch_add(1, std::memory_order_relaxed);
        if (block >= share.end) {
            return done_here;
        }
        const int32_t begin = block * stage.items_per_block;
        const int32_t end = begin + stage.items_per_block < stage.item_count ? begin + stage.items_per_block
                                                                              : stage.item_count;
        stage.fn(stage.owner, stage, begin, end, worker);
        ++done_here;
    }
}

}  // namespace i2d
