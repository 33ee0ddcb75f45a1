// SPDX-License-Identifier: MIT
// TaskSystem: where a world's parallel work runs, on the caller's job system (enqueue and
// finish callbacks, as Box2D v3 takes them) or on a pool of threads the world owns.
//
// Design note: the engine asks for one thing only, "run this function once on each of
// the world's workers and wait": worker 0 is the calling thread, the others are tasks
// handed to the job system. What the workers then do is shared out by the stage runner
// (stage_runner.hpp), which lets any subset of them finish the work, so a job system that
// runs tasks late, out of order or one after another on the calling thread still works.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace i2d {

class ThreadPool;

/// The C API's task function: items [start, end) of a task, on worker `worker`.
using TaskFn = void (*)(int32_t start, int32_t end, int32_t worker, void* task_context);
/// Runs `task` over [0, item_count) in ranges of at least min_range; returns a handle
/// for FinishTaskFn, or null after running it inline.
using EnqueueTaskFn = void* (*)(TaskFn task, int32_t item_count, int32_t min_range, void* task_context,
                                void* user_context);
using FinishTaskFn = void (*)(void* user_task, void* user_context);

struct TaskCallbacks {
    EnqueueTaskFn enqueue = nullptr;
    FinishTaskFn finish = nullptr;
    void* user_context = nullptr;
};

/// Most workers a world may have; each costs a little memory per stage and, with the
/// built-in pool, a thread.
constexpr int32_t max_worker_count = 64;

class TaskSystem {
public:
    /// worker_count in [1, max_worker_count]; without callbacks, worker_count > 1 starts
    /// a pool of worker_count - 1 threads at the first parallel run.
    TaskSystem(int32_t worker_count, const TaskCallbacks& callbacks);
    ~TaskSystem();
    TaskSystem(const TaskSystem&) = delete;
    TaskSystem& operator=(const TaskSystem&) = delete;

    int32_t worker_count() const { return worker_count_; }

    /// Calls work(worker, context) once for each worker in [0, worker_count): worker 0
    /// on the calling thread, the others as tasks. Returns when every call has returned.
    void run_on_workers(void (*work)(int32_t worker, void* context), void* context);

private:
    struct WorkerTask {
        void (*work)(int32_t, void*);
        void* context;
        int32_t worker;
    };
    static void run_worker_task(int32_t start, int32_t end, int32_t worker, void* task);
    bool start_pool();

    int32_t worker_count_;
    TaskCallbacks callbacks_;
    std::unique_ptr<ThreadPool> pool_;  // made at the first run without callbacks
    bool pool_failed_ = false;          // no threads could be started: worker 0 works alone
    std::vector<WorkerTask> tasks_;
    std::vector<void*> handles_;
};

}  // namespace i2d
