// SPDX-License-Identifier: MIT
// ThreadPool: the threads a world owns when its caller gives it no job system.
//
// Design note: the engine hands the pool at most one task per thread at a time and waits
// for all of them before it hands out more (TaskSystem::run_on_workers), so each thread
// has one slot, with no queue. A thread that finished a task spins for a while before it
// sleeps: a step hands out work several times, with serial parts of up to a few hundred
// microseconds between, and waking a sleeping thread costs tens of microseconds. The
// while is a time, not a count of pause instructions, whose length differs tenfold
// between processors: on this project's AMD VM, 2000 pauses ended before the step's next
// parallel part and the thread slept through most of them (tumbler, 2 workers: 2.84 ms
// a step against 2.62 when it spins through).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace i2d {

class ThreadPool {
public:
    /// How long a thread that finished a task waits, spinning, for the next, microseconds.
    static constexpr int64_t idle_spin_microseconds = 500;

    using Task = void (*)(int32_t start, int32_t end, int32_t worker, void* context);

    /// Starts thread_count threads, which wait for tasks; throws (having stopped those it
    /// started) when the system cannot start one.
    explicit ThreadPool(int32_t thread_count);
    /// Stops and joins the threads; no task may be running.
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int32_t thread_count() const { return int32_t(slots_.size()); }
    /// Runs task(0, item_count, thread + 1, context) on the given thread, which must be idle.
    void start(int32_t thread, Task task, int32_t item_count, void* context);
    /// Waits until the thread's task has returned.
    void wait(int32_t thread);

private:
    enum State : int32_t { idle, ready, running, done, stopping };
    struct alignas(64) Slot {
        std::atomic<int32_t> state{idle};
        Task task = nullptr;
        int32_t item_count = 0;
        void* context = nullptr;
        std::mutex mutex;
        std::condition_variable wake;      // the thread waits here for a task
        std::condition_variable finished;  // the caller waits here for its end
    };
    void serve(int32_t thread);
    void stop();

    std::vector<std::unique_ptr<Slot>> slots_;
    std::vector<std::thread> threads_;
};

}  // namespace i2d
