// SPDX-License-Identifier: MIT
// A scene stepped with 1 worker, 2 workers and 2 on a job system that runs the tasks
// shuffled: the state hash every hash_every steps must be the same in all three, and the
// job system must have been given work (the scene is large enough to share).
#pragma once

#include <impulse2d/impulse2d.h>

#include <cinttypes>
#include <cstdio>
#include <memory>
#include <vector>

#include "check.h"
#include "det_job_system.hpp"
#include "det_scenes.hpp"

namespace det {

constexpr int hash_every = 10;

// The world's state hash every hash_every steps, and the awake bodies at the end.
inline std::vector<uint64_t> run_scene(Scene scene, int workers, bool own_jobs, int steps, int32_t* awake_at_end,
                                int* tasks_run = nullptr) {
    std::vector<uint64_t> hashes;
    std::unique_ptr<JobSystem> jobs;
    i2d_world_def def = i2d_default_world_def();
    def.worker_count = workers;
    if (own_jobs) {
        jobs = std::make_unique<JobSystem>(2, JobSystem::Order::shuffled);
        jobs->install(def);
    }
    const i2d_world_id world = scene(def);
    if (I2D_IS_NULL(world)) {
        fprintf(stderr, "    scene: %s\n", i2d_last_error_message());
        return hashes;
    }
    for (int s = 1; s <= steps; ++s) {
        i2d_world_step(world, time_step, substeps);
        if (s % hash_every == 0) {
            hashes.push_back(i2d_world_get_state_hash(world));
        }
    }
    *awake_at_end = i2d_world_get_counters(world).awake_body_count;
    i2d_world_destroy(world);
    if (tasks_run != nullptr) {
        *tasks_run = jobs ? jobs->tasks_run() : 0;
    }
    return hashes;
}

// The first step (a multiple of hash_every) at which `other` differs from `one`; -1: none.
inline int first_difference(const std::vector<uint64_t>& one, const std::vector<uint64_t>& other) {
    for (size_t k = 0; k < one.size(); ++k) {
        if (k >= other.size() || other[k] != one[k]) {
            return int(k + 1) * hash_every;
        }
    }
    return other.size() == one.size() ? -1 : int(one.size() + 1) * hash_every;
}

// With wide_workers > 2, also that many workers (beyond the machine's cores, they take
// turns: the split of the work is what changes).
inline void check_workers(Scene scene, int steps, int wide_workers = 0) {
    int32_t awake_one = 0, awake_two = 0, awake_jobs = 0;
    const std::vector<uint64_t> one = run_scene(scene, 1, false, steps, &awake_one);
    const std::vector<uint64_t> two = run_scene(scene, 2, false, steps, &awake_two);
    int tasks = 0;
    const std::vector<uint64_t> jobs = run_scene(scene, 2, true, steps, &awake_jobs, &tasks);
    I2D_REQUIRE(!one.empty());
    const int first_two = first_difference(one, two), first_jobs = first_difference(one, jobs);
    fprintf(stderr, "    %d steps: hash %016" PRIx64 " with 1 worker (%d awake at the end); first difference: "
            "2 workers %d, 2 on shuffled jobs %d (-1: none); the job system ran %d tasks\n",
            steps, one.back(), int(awake_one), first_two, first_jobs, tasks);
    I2D_CHECK(first_two < 0);
    I2D_CHECK(first_jobs < 0);
    if (wide_workers > 2) {
        int32_t awake_wide = 0;
        const int first_wide = first_difference(one, run_scene(scene, wide_workers, false, steps, &awake_wide));
        fprintf(stderr, "    %d workers: first difference %d\n", wide_workers, first_wide);
        I2D_CHECK(first_wide < 0 && awake_wide == awake_one);
    }
    I2D_CHECK(awake_two == awake_one && awake_jobs == awake_one);
    // The scene is large enough that the step shared its work: the comparison is not of two
    // single-threaded runs.
    I2D_CHECK(tasks > 0);
}

}  // namespace det
