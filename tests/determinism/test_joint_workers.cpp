// SPDX-License-Identifier: MIT
// Joints keep the step's determinism: a heap of ragdolls (revolute joints with limits,
// springs and motors, coloured with the contacts) and a net of hinges (solved W at a time,
// in chunks the workers cut differently) give the same state hash at every step
// with 1 and 2 workers, and with 2 workers on a job system that runs the tasks shuffled.
#include <impulse2d/impulse2d.h>

#include <cinttypes>
#include <cstdio>
#include <memory>
#include <vector>

#include "check.h"
#include "det_job_system.hpp"
#include "det_scenes.hpp"

namespace {

constexpr int hash_every = 10;

// The world's state hash every hash_every steps, and the awake bodies at the end.
std::vector<uint64_t> run_scene(det::Scene scene, int workers, bool own_jobs, int steps, int32_t* awake_at_end,
                                int* tasks_run = nullptr) {
    std::vector<uint64_t> hashes;
    std::unique_ptr<det::JobSystem> jobs;
    i2d_world_def def = i2d_default_world_def();
    def.worker_count = workers;
    if (own_jobs) {
        jobs = std::make_unique<det::JobSystem>(2, det::JobSystem::Order::shuffled);
        jobs->install(def);
    }
    const i2d_world_id world = scene(def);
    if (I2D_IS_NULL(world)) {
        fprintf(stderr, "    scene: %s\n", i2d_last_error_message());
        return hashes;
    }
    for (int s = 1; s <= steps; ++s) {
        i2d_world_step(world, det::time_step, det::substeps);
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

void check_workers(det::Scene scene, int steps) {
    int32_t awake_one = 0, awake_two = 0, awake_jobs = 0;
    const std::vector<uint64_t> one = run_scene(scene, 1, false, steps, &awake_one);
    const std::vector<uint64_t> two = run_scene(scene, 2, false, steps, &awake_two);
    int tasks = 0;
    const std::vector<uint64_t> jobs = run_scene(scene, 2, true, steps, &awake_jobs, &tasks);
    I2D_REQUIRE(!one.empty());
    int first_two = -1, first_jobs = -1;
    for (size_t k = 0; k < one.size(); ++k) {
        if (first_two < 0 && (k >= two.size() || two[k] != one[k])) {
            first_two = int(k + 1) * hash_every;
        }
        if (first_jobs < 0 && (k >= jobs.size() || jobs[k] != one[k])) {
            first_jobs = int(k + 1) * hash_every;
        }
    }
    fprintf(stderr, "    %d steps: hash %016" PRIx64 " with 1 worker (%d awake at the end); first difference: "
            "2 workers %d, 2 on shuffled jobs %d (-1: none); the job system ran %d tasks\n",
            steps, one.back(), int(awake_one), first_two, first_jobs, tasks);
    I2D_CHECK(first_two < 0 && two.size() == one.size());
    I2D_CHECK(first_jobs < 0 && jobs.size() == one.size());
    I2D_CHECK(awake_two == awake_one && awake_jobs == awake_one);
    // The scene is large enough that the step shared its work: the comparison is not of two
    // single-threaded runs.
    I2D_CHECK(tasks > 0);
}

}  // namespace

I2D_TEST(det_joints_ragdoll_heap_gives_the_same_bits_with_1_and_2_workers) { check_workers(det::ragdoll_heap, 240); }

I2D_TEST(det_joints_hinge_net_gives_the_same_bits_with_1_and_2_workers) { check_workers(det::hinge_net, 240); }

// Until the heap sleeps: sleeping and waking islands held together by joints, too.
I2D_TEST(det_joints_long_ragdoll_heap_gives_the_same_bits_until_asleep) { check_workers(det::ragdoll_heap, 1200); }
