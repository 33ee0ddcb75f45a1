// SPDX-License-Identifier: MIT
// StageRunner: every item of every stage is done once, after every item of the stages
// before it, with the run's context and the stage's own argument, for any worker count
// and block size; a stage whose run_if an earlier stage cleared is skipped by every worker; a stage split at the owner's share starts gets
// blocks that never cross them; and a run finishes however a job system schedules the
// workers' tasks: inline inside enqueue, or only when the engine waits for them.
#include <atomic>
#include <vector>

#include "check.h"
#include "core/stage_runner.hpp"
#include "core/task_system.hpp"

namespace {

using i2d::Stage;

// Stage k writes k + 1 into each of its items, having checked that the stage before left
// k there: an item done twice, out of order, or not at all shows in the counts.
struct Ledger {
    std::vector<std::atomic<int32_t>> items;
    std::atomic<int32_t> out_of_order{0};
    std::atomic<int32_t> bad_worker{0};
    std::atomic<int32_t> blocks_across_shares{0};
    int32_t workers = 1;
    const int32_t* share_starts = nullptr;  // the owner's split, when the stages have one
    bool skip_flag_stage_runs = true;  // cleared by the stage that decides it

    explicit Ledger(int32_t item_count) : items(std::size_t(item_count)) {}
};

// The run's context: every block must see the one the run was given.
struct RunContext {
    const Ledger* ledger = nullptr;
};

// Which stage of the ledger's a stage is: its items advance from `stage` to stage + 1.
struct StageNumber {
    int32_t stage = 0;
};

void advance(const RunContext& context, Ledger& ledger, const StageNumber& arg, int32_t begin, int32_t end,
             int32_t worker) {
    if (worker < 0 || worker >= ledger.workers || context.ledger != &ledger) {
        ledger.bad_worker.fetch_add(1);
    }
    if (ledger.share_starts != nullptr) {
        for (int32_t w = 1; w < ledger.workers; ++w) {
            const int32_t start = ledger.share_starts[w];
            ledger.blocks_across_shares.fetch_add(begin < start && start < end ? 1 : 0);
        }
    }
    for (int32_t i = begin; i < end; ++i) {
        int32_t expected = arg.stage;
        if (!ledger.items[std::size_t(i)].compare_exchange_strong(expected, arg.stage + 1)) {
            ledger.out_of_order.fetch_add(1);
        }
    }
}

void clear_skip_flag(const RunContext&, Ledger& ledger, const i2d::NoStageArg&, int32_t, int32_t, int32_t) {
    ledger.skip_flag_stage_runs = false;
}

std::vector<Stage> advancing_stages(Ledger& ledger, int32_t stage_count, int32_t item_count, int32_t workers,
                                    int32_t min_items_per_block) {
    std::vector<Stage> stages;
    for (int32_t k = 0; k < stage_count; ++k) {
        stages.push_back(i2d::make_stage<&advance>(ledger, StageNumber{k}, item_count, workers, true, min_items_per_block));
    }
    return stages;
}

int32_t items_left_behind(const Ledger& ledger, int32_t final_value) {
    int32_t count = 0;
    for (const std::atomic<int32_t>& item : ledger.items) {
        count += item.load() != final_value ? 1 : 0;
    }
    return count;
}

// A job system that runs each task only when the engine waits for it: worker 0 does its
// part (and, finding the others absent, theirs) before any other task starts.
struct DeferredJobs {
    struct Job {
        i2d::TaskFn task;
        int32_t item_count;
        void* context;
    };
    std::vector<Job> jobs;
    int32_t next = 0;

    static void* enqueue(i2d::TaskFn task, int32_t item_count, int32_t, void* task_context, void* self) {
        DeferredJobs& deferred = *static_cast<DeferredJobs*>(self);
        deferred.jobs.push_back(Job{task, item_count, task_context});
        return self;  // any non-null handle: finish runs whatever is queued
    }
    static void finish(void*, void* self) {
        DeferredJobs& deferred = *static_cast<DeferredJobs*>(self);
        while (deferred.next < int32_t(deferred.jobs.size())) {
            const Job job = deferred.jobs[std::size_t(deferred.next++)];
            job.task(0, job.item_count, 0, job.context);
        }
    }
};

// Runs tasks at once, inside enqueue: the other workers finish the run before worker 0
// has started.
void* run_inline(i2d::TaskFn task, int32_t item_count, int32_t, void* task_context, void*) {
    task(0, item_count, 0, task_context);
    return nullptr;
}
void finish_nothing(void*, void*) {}

}  // namespace

I2D_TEST(unit_stage_runner_does_every_item_once_in_stage_order) {
    const int32_t worker_counts[] = {1, 2, 3, 4, 8};
    const int32_t item_counts[] = {1, 3, 17, 1000};
    const int32_t min_items[] = {1, 4, 64};
    constexpr int32_t stage_count = 12;
    constexpr int32_t runs = 3;
    for (const int32_t workers : worker_counts) {
        i2d::TaskSystem tasks(workers, i2d::TaskCallbacks{});
        i2d::StageRunner runner;
        for (const int32_t item_count : item_counts) {
            for (const int32_t min_per_block : min_items) {
                for (int32_t run = 0; run < runs; ++run) {
                    Ledger ledger(item_count);
                    ledger.workers = workers;
                    const RunContext context{&ledger};
                    runner.run(tasks, advancing_stages(ledger, stage_count, item_count, workers, min_per_block), true,
                               &context);
                    I2D_CHECK(ledger.out_of_order.load() == 0);
                    I2D_CHECK(ledger.bad_worker.load() == 0);
                    I2D_CHECK(items_left_behind(ledger, stage_count) == 0);
                }
            }
        }
    }
}

// Shares of any size, empty ones too, starting anywhere: each item still done once in
// stage order, and no block reaches past its share into the next.
I2D_TEST(unit_stage_runner_splits_at_the_owners_share_starts) {
    constexpr int32_t item_count = 1000, stage_count = 8;
    const std::vector<std::vector<int32_t>> splits = {
        {0, 1000}, {0, 333, 1000}, {0, 0, 1000}, {0, 1000, 1000}, {0, 7, 7, 700, 1000}, {0, 1, 2, 3, 1000}};
    for (const std::vector<int32_t>& starts : splits) {
        const int32_t workers = int32_t(starts.size()) - 1;
        i2d::TaskSystem tasks(workers, i2d::TaskCallbacks{});
        i2d::StageRunner runner;
        for (const int32_t min_per_block : {1, 16, 64}) {
            Ledger ledger(item_count);
            ledger.workers = workers;
            const RunContext context{&ledger};
            ledger.share_starts = starts.data();
            std::vector<Stage> stages = advancing_stages(ledger, stage_count, item_count, workers, min_per_block);
            for (Stage& stage : stages) {
                stage.share_starts = starts.data();
            }
            runner.run(tasks, stages, true, &context);
            I2D_CHECK(ledger.out_of_order.load() == 0);
            I2D_CHECK(ledger.bad_worker.load() == 0);
            I2D_CHECK(ledger.blocks_across_shares.load() == 0);
            I2D_CHECK(items_left_behind(ledger, stage_count) == 0);
        }
    }
}

// What each worker reports it did adds up to every block of the run, once; a worker that
// ran blocks was busy for some time.
I2D_TEST(unit_stage_runner_reports_the_blocks_each_worker_ran) {
    constexpr int32_t item_count = 1000, stage_count = 10;
    for (const int32_t workers : {2, 3, 4}) {
        i2d::TaskSystem tasks(workers, i2d::TaskCallbacks{});
        i2d::StageRunner runner;
        Ledger ledger(item_count);
        ledger.workers = workers;
        const RunContext context{&ledger};
        const std::vector<Stage> stages = advancing_stages(ledger, stage_count, item_count, workers, 16);
        runner.run(tasks, stages, true, &context);
        int32_t blocks = 0;
        for (const Stage& stage : stages) {
            blocks += stage.block_count();
        }
        I2D_REQUIRE(runner.worker_times().size() == std::size_t(workers));
        int32_t reported = 0;
        for (int32_t w = 0; w < workers; ++w) {
            const i2d::StageRunner::WorkerTime time = runner.worker_times()[std::size_t(w)];
            I2D_CHECK(time.blocks >= 0);
            I2D_CHECK(time.blocks == 0 || time.busy > 0);
            reported += time.blocks;
        }
        I2D_CHECK(reported == blocks);
        I2D_CHECK(items_left_behind(ledger, stage_count) == 0);
        // A run on the calling thread reports no worker's time.
        runner.run(tasks, stages, false, &context);
        I2D_CHECK(runner.worker_times().empty());
    }
}

I2D_TEST(unit_stage_runner_skips_a_stage_an_earlier_stage_turned_off) {
    for (const int32_t workers : {1, 2, 4}) {
        i2d::TaskSystem tasks(workers, i2d::TaskCallbacks{});
        i2d::StageRunner runner;
        constexpr int32_t item_count = 200;
        Ledger ledger(item_count);
        ledger.workers = workers;
        const RunContext context{&ledger};
        // Stage 0 advances every item to 1; the decider clears the flag; the guarded stage
        // would advance to 2 and the last stage expects 1, so it finds every item out of
        // order if the guarded stage ran, for any worker.
        std::vector<Stage> stages = advancing_stages(ledger, 1, item_count, workers, 8);
        stages.push_back(i2d::make_stage<&clear_skip_flag>(ledger, i2d::NoStageArg{}, 1, workers, true, 1));
        Stage guarded = i2d::make_stage<&advance>(ledger, StageNumber{1}, item_count, workers, true, 8);
        guarded.run_if = &ledger.skip_flag_stage_runs;
        stages.push_back(guarded);
        Stage last = guarded;
        last.run_if = nullptr;
        stages.push_back(last);
        runner.run(tasks, stages, true, &context);
        I2D_CHECK(!ledger.skip_flag_stage_runs);
        I2D_CHECK(ledger.out_of_order.load() == 0);
        I2D_CHECK(items_left_behind(ledger, 2) == 0);
    }
}

I2D_TEST(unit_stage_runner_finishes_with_tasks_deferred_or_inline) {
    constexpr int32_t workers = 4, item_count = 500, stage_count = 20;
    {
        DeferredJobs deferred;
        deferred.jobs.reserve(workers);
        i2d::TaskSystem tasks(workers, i2d::TaskCallbacks{&DeferredJobs::enqueue, &DeferredJobs::finish, &deferred});
        i2d::StageRunner runner;
        Ledger ledger(item_count);
        ledger.workers = workers;
        const RunContext context{&ledger};
        runner.run(tasks, advancing_stages(ledger, stage_count, item_count, workers, 16), true, &context);
        I2D_CHECK(deferred.next == workers - 1);  // every task ran, after worker 0
        I2D_CHECK(ledger.out_of_order.load() == 0);
        I2D_CHECK(items_left_behind(ledger, stage_count) == 0);
    }
    {
        i2d::TaskSystem tasks(workers, i2d::TaskCallbacks{&run_inline, &finish_nothing, nullptr});
        i2d::StageRunner runner;
        Ledger ledger(item_count);
        ledger.workers = workers;
        const RunContext context{&ledger};
        runner.run(tasks, advancing_stages(ledger, stage_count, item_count, workers, 16), true, &context);
        I2D_CHECK(ledger.out_of_order.load() == 0);
        I2D_CHECK(items_left_behind(ledger, stage_count) == 0);
    }
}
