// SPDX-License-Identifier: MIT
// TaskSystem: worker 0 on the caller, the rest on the job system or the pool.
#include "core/task_system.hpp"

#include <exception>

#include "core/thread_pool.hpp"

namespace i2d {

TaskSystem::TaskSystem(int32_t worker_count, const TaskCallbacks& callbacks)
    : worker_count_(worker_count), callbacks_(callbacks) {
    tasks_.resize(std::size_t(worker_count));
    handles_.resize(std::size_t(worker_count));
}

TaskSystem::~TaskSystem() = default;

void TaskSystem::run_worker_task(int32_t start, int32_t end, int32_t, void* task) {
    // A job system may split even a one-item task; only the range holding item 0 works.
    if (start == 0 && end > 0) {
        const WorkerTask& t = *static_cast<const WorkerTask*>(task);
        t.work(t.worker, t.context);
    }
}

// Where no threads can be started (a platform without them, such as WebAssembly built
// without thread support, or a process at its limit) the calling thread does all the
// work: any subset of workers finishes a run, so the results are the same.
bool TaskSystem::start_pool() {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    // WebAssembly built without threads (and without exceptions): trying would abort.
    pool_failed_ = true;
#endif
    if (!pool_ && !pool_failed_) {
        try {
            pool_ = std::make_unique<ThreadPool>(worker_count_ - 1);
        } catch (const std::exception&) {
            pool_failed_ = true;
        }
    }
    return pool_ != nullptr;
}

void TaskSystem::run_on_workers(void (*work)(int32_t worker, void* context), void* context) {
    const bool use_pool = callbacks_.enqueue == nullptr;
    if (use_pool && worker_count_ > 1 && !start_pool()) {
        work(0, context);
        return;
    }
    for (int32_t w = 1; w < worker_count_; ++w) {
        WorkerTask& task = tasks_[std::size_t(w)];
        task = {work, context, w};
        if (use_pool) {
            pool_->start(w - 1, &run_worker_task, 1, &task);
        } else {
            handles_[std::size_t(w)] = callbacks_.enqueue(&run_worker_task, 1, 1, &task, callbacks_.user_context);
        }
    }
    work(0, context);
    for (int32_t w = 1; w < worker_count_; ++w) {
        if (use_pool) {
            pool_->wait(w - 1);
        } else if (handles_[std::size_t(w)] != nullptr) {
            callbacks_.finish(handles_[std::size_t(w)], callbacks_.user_context);
        }
    }
}

}  // namespace i2d
