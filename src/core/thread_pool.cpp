// SPDX-License-Identifier: MIT
// ThreadPool: one slot per thread, spin then sleep.
#include "core/thread_pool.hpp"

#include <chrono>

#include "core/spin_wait.hpp"

namespace i2d {

ThreadPool::ThreadPool(int32_t thread_count) {
    slots_.reserve(std::size_t(thread_count));
    threads_.reserve(std::size_t(thread_count));
    for (int32_t t = 0; t < thread_count; ++t) {
        slots_.push_back(std::make_unique<Slot>());
    }
    try {
        for (int32_t t = 0; t < thread_count; ++t) {
            threads_.emplace_back([this, t] { serve(t); });
        }
    } catch (...) {
        stop();  // the threads that did start, before the error reaches the caller
        throw;
    }
}

ThreadPool::~ThreadPool() { stop(); }

void ThreadPool::stop() {
    for (const std::unique_ptr<Slot>& slot : slots_) {
        {
            std::lock_guard<std::mutex> lock(slot->mutex);
            slot->state.store(stopping, std::memory_order_release);
        }
        slot->wake.notify_one();
    }
    for (std::thread& thread : threads_) {
        thread.join();
    }
}

void ThreadPool::start(int32_t thread, Task task, int32_t item_count, void* context) {
    Slot& slot = *slots_[std::size_t(thread)];
    slot.task = task;
    slot.item_count = item_count;
    slot.context = context;
    {
        std::lock_guard<std::mutex> lock(slot.mutex);
        slot.state.store(ready, std::memory_order_release);
    }
    slot.wake.notify_one();
}

void ThreadPool::wait(int32_t thread) {
    Slot& slot = *slots_[std::size_t(thread)];
    SpinWait spin;
    while (slot.state.load(std::memory_order_acquire) != done) {
        if (spin.long_wait()) {
            std::unique_lock<std::mutex> lock(slot.mutex);
            slot.finished.wait(lock, [&] { return slot.state.load(std::memory_order_acquire) == done; });
            break;
        }
        spin.once();
    }
    slot.state.store(idle, std::memory_order_relaxed);
}

void ThreadPool::serve(int32_t thread) {
    Slot& slot = *slots_[std::size_t(thread)];
    for (;;) {
        SpinWait spin;
        const auto sleep_at = std::chrono::steady_clock::now() + std::chrono::microseconds(idle_spin_microseconds);
        int32_t state = slot.state.load(std::memory_order_acquire);
        for (int32_t spins = 1; state != ready && state != stopping; ++spins) {
            // The clock is read now and then: a read costs as much as tens of pauses.
            constexpr int32_t spins_per_clock_read = 64;
            if (spins % spins_per_clock_read == 0 && std::chrono::steady_clock::now() >= sleep_at) {
                std::unique_lock<std::mutex> lock(slot.mutex);
                slot.wake.wait(lock, [&] {
                    state = slot.state.load(std::memory_order_acquire);
                    return state == ready || state == stopping;
                });
                break;
            }
            spin.once();
            state = slot.state.load(std::memory_order_acquire);
        }
        if (state == stopping) {
            return;
        }
        slot.state.store(running, std::memory_order_relaxed);
        slot.task(0, slot.item_count, thread + 1, slot.context);
        {
            std::lock_guard<std::mutex> lock(slot.mutex);
            slot.state.store(done, std::memory_order_release);
        }
        slot.finished.notify_one();
    }
}

}  // namespace i2d
