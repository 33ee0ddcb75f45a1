// SPDX-License-Identifier: MIT
// JobSystem: a stand-in for a game's own job system, handed to worlds through the world
// def's enqueue_task and finish_task, that runs the engine's tasks in an order of its
// choosing: first in first out, last in first out (the reverse of the engine's order),
// shuffled, or inline on the calling thread. A world must give the same bits with each.
#pragma once

#include <impulse2d/impulse2d.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace det {

class JobSystem {
public:
    enum class Order { fifo, lifo, shuffled, inline_now };

    JobSystem(int threads, Order order) : order_(order) {
        for (int t = 0; order != Order::inline_now && t < threads; ++t) {
            threads_.emplace_back([this, t] { serve(t); });
        }
    }
    ~JobSystem() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        work_.notify_all();
        for (std::thread& thread : threads_) {
            thread.join();
        }
    }
    JobSystem(const JobSystem&) = delete;
    JobSystem& operator=(const JobSystem&) = delete;

    /// Fills the job system fields of a world def or a batch def.
    template <class Def>
    void install(Def& def) {
        def.enqueue_task = &enqueue;
        def.finish_task = &finish;
        def.user_task_context = this;
    }
    int tasks_run() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return tasks_run_;
    }

private:
    struct Job {
        i2d_task_fn* task;
        int32_t item_count, min_range;
        void* context;
        bool done;
    };

    static void* enqueue(i2d_task_fn* task, int32_t item_count, int32_t min_range, void* task_context, void* self) {
        JobSystem& jobs = *static_cast<JobSystem*>(self);
        if (jobs.order_ == Order::inline_now) {
            run_in_ranges(Job{task, item_count, min_range, task_context, false}, 0);
            std::lock_guard<std::mutex> lock(jobs.mutex_);
            ++jobs.tasks_run_;
            return nullptr;
        }
        Job* job = new Job{task, item_count, min_range, task_context, false};
        {
            std::lock_guard<std::mutex> lock(jobs.mutex_);
            jobs.queue_.push_back(job);
        }
        jobs.work_.notify_one();
        return job;
    }

    static void finish(void* handle, void* self) {
        JobSystem& jobs = *static_cast<JobSystem*>(self);
        Job* job = static_cast<Job*>(handle);
        {
            std::unique_lock<std::mutex> lock(jobs.mutex_);
            jobs.finished_.wait(lock, [job] { return job->done; });
        }
        delete job;
    }

    // The task's items in ranges of min_range, as a job system that splits work would.
    static void run_in_ranges(const Job& job, int worker) {
        const int32_t range = job.min_range > 0 ? job.min_range : 1;
        for (int32_t start = 0; start < job.item_count; start += range) {
            const int32_t end = start + range < job.item_count ? start + range : job.item_count;
            job.task(start, end, worker, job.context);
        }
    }

    void serve(int thread) {
        uint32_t random = 0x9e3779b9u * uint32_t(thread + 1);
        for (;;) {
            Job* job = nullptr;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                work_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
                if (queue_.empty()) {
                    return;
                }
                std::size_t pick = 0;
                if (order_ == Order::lifo) {
                    pick = queue_.size() - 1;
                } else if (order_ == Order::shuffled) {
                    random = random * 1664525u + 1013904223u;
                    pick = (random >> 8) % queue_.size();
                }
                job = queue_[pick];
                queue_.erase(queue_.begin() + std::ptrdiff_t(pick));
            }
            run_in_ranges(*job, thread);
            {
                std::lock_guard<std::mutex> lock(mutex_);
                job->done = true;
                ++tasks_run_;
            }
            finished_.notify_all();
        }
    }

    Order order_;
    mutable std::mutex mutex_;
    std::condition_variable work_, finished_;
    std::deque<Job*> queue_;
    std::vector<std::thread> threads_;
    bool stopping_ = false;
    int tasks_run_ = 0;
};

}  // namespace det
