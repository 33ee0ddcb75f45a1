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
            if (stage.item_count > 0) {
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
    const int32_t count = int32_t(active_.size());
    if (count > progress_capacity_) {
        progress_capacity_ = count + count / 2;
        progress_ = std::make_unique<Progress[]>(std::size_t(progress_capacity_));
    }
    for (int32_t s = 0; s < count; ++s) {
        progress_[s].next_block.store(0, std::memory_order_relaxed);
        progress_[s].done_blocks.store(0, std::memory_order_relaxed);
    }
    current_.store(0, std::memory_order_release);
    tasks.run_on_workers(&work_on, this);
}

void StageRunner::work_on(int32_t worker, void* runner) { static_cast<StageRunner*>(runner)->work(worker); }

void StageRunner::work(int32_t worker) {
    const int32_t count = int32_t(active_.size());
    int32_t s = current_.load(std::memory_order_acquire);
    while (s < count) {
        const Stage& stage = active_[std::size_t(s)];
        Progress& progress = progress_[s];
        const int32_t blocks = stage.block_count();
        for (;;) {
            const int32_t block = progress.next_block.fetch_add(1, std::memory_order_relaxed);
            if (block >= blocks) {
                break;
            }
            const int32_t begin = block * stage.items_per_block;
            const int32_t end = begin + stage.items_per_block < stage.item_count ? begin + stage.items_per_block
                                                                                  : stage.item_count;
            stage.fn(stage.owner, stage, begin, end, worker);
            // The release half publishes this block's writes; the stage's last block
            // acquires them all before it opens the next stage.
            if (progress.done_blocks.fetch_add(1, std::memory_order_acq_rel) + 1 == blocks) {
                current_.store(s + 1, std::memory_order_release);
            }
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

}  // namespace i2d
