// SPDX-License-Identifier: MIT
// How long one cache line takes to go from one CPU to another and back: two threads,
// pinned to the first two CPUs this process may use, hand a counter to each other.
//
// Every stage boundary of a shared step, and every body two workers both move, costs
// such trips. On a virtual machine the figure depends on where the host put the two
// vCPUs (one shared cache, or two dies apart), it can change within minutes, and a
// 2-worker speed-up measured without it means little: large_pyramid's was 1.4 to 1.8
// with a 120 ns trip on this EPYC VM and 1.05 to 1.1 with a 480 ns one.
//
// usage: core_round_trip [TRIPS]   (default 100000; prints the median of 5 trials)
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

namespace {

bool pin_to(int cpu) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

// The first two CPUs in this process's affinity mask, or false.
bool first_two_cpus(int& a, int& b) {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) != 0) {
        return false;
    }
    std::vector<int> cpus;
    for (int cpu = 0; cpu < CPU_SETSIZE && cpus.size() < 2; ++cpu) {
        if (CPU_ISSET(cpu, &set)) {
            cpus.push_back(cpu);
        }
    }
    if (cpus.size() < 2) {
        return false;
    }
    a = cpus[0];
    b = cpus[1];
    return true;
}

// Nanoseconds per round trip of a counter between the two CPUs.
double trial(int cpu_a, int cpu_b, long trips) {
    alignas(64) static std::atomic<long> turn{0};
    turn.store(0);
    std::thread other([&] {
        pin_to(cpu_b);
        for (long k = 0; k < trips; ++k) {
            while (turn.load(std::memory_order_acquire) != 2 * k + 1) {
            }
            turn.store(2 * k + 2, std::memory_order_release);
        }
    });
    pin_to(cpu_a);
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < trips; ++k) {
        turn.store(2 * k + 1, std::memory_order_release);
        while (turn.load(std::memory_order_acquire) != 2 * k + 2) {
        }
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    other.join();
    return ns / double(trips);
}

}  // namespace

int main(int argc, char** argv) {
    const long trips = argc > 1 ? std::atol(argv[1]) : 100000;
    int cpu_a = 0, cpu_b = 0;
    if (trips <= 0 || !first_two_cpus(cpu_a, cpu_b)) {
        std::fprintf(stderr, "usage: core_round_trip [TRIPS > 0]; needs two CPUs\n");
        return 2;
    }
    constexpr int trials = 5;
    std::vector<double> ns;
    for (int t = 0; t < trials; ++t) {
        ns.push_back(trial(cpu_a, cpu_b, trips));
    }
    std::sort(ns.begin(), ns.end());
    std::printf("cache line round trip cpu %d <-> cpu %d: %.0f ns (median of %d trials of %ld; fastest %.0f)\n",
                cpu_a, cpu_b, ns[trials / 2], trials, trips, ns[0]);
    return 0;
}
