// SPDX-License-Identifier: MIT
// i2d_worlds_step gives each world of a batch the state hash it has when stepped alone,
// at every step: with 1, 2 and 4 batch workers, on a job system that runs the batch's
// tasks shuffled, and with worlds that share their own steps among 2 workers inside the
// batch. The worlds differ in size, so workers finish them at different times and take
// them in a different order every run. ThreadSanitizer runs this suite in CI.
#include <cinttypes>
#include <cstdio>
#include <memory>
#include <vector>

#include "check.h"
#include "det_job_system.hpp"
#include "det_scenes.hpp"

namespace {

constexpr int batch_steps = 60;
const det::Scene batch_scenes[] = {det::mixed_scene, det::bullet_room, det::hinge_net,
                                   det::hooked_bin,  det::sleeping_bin, det::mixed_scene};
constexpr int batch_size = int(sizeof batch_scenes / sizeof batch_scenes[0]);

using Hashes = std::vector<std::vector<uint64_t>>;  // [world][step]

std::vector<i2d_world_id> make_worlds(int world_workers) {
    std::vector<i2d_world_id> worlds;
    for (const det::Scene scene : batch_scenes) {
        i2d_world_def def = i2d_default_world_def();
        def.worker_count = world_workers;
        worlds.push_back(scene(def));
    }
    return worlds;
}

void destroy_worlds(const std::vector<i2d_world_id>& worlds) {
    for (const i2d_world_id world : worlds) {
        i2d_world_destroy(world);
    }
}

Hashes stepped_alone() {
    const std::vector<i2d_world_id> worlds = make_worlds(1);
    Hashes hashes(worlds.size());
    for (int s = 0; s < batch_steps; ++s) {
        for (std::size_t w = 0; w < worlds.size(); ++w) {
            I2D_CHECK(i2d_world_step(worlds[w], det::time_step, det::substeps) == I2D_OK);
            hashes[w].push_back(i2d_world_get_state_hash(worlds[w]));
        }
    }
    destroy_worlds(worlds);
    return hashes;
}

Hashes stepped_in_batch(int batch_workers, det::JobSystem* jobs, int world_workers) {
    const std::vector<i2d_world_id> worlds = make_worlds(world_workers);
    i2d_batch_def def = i2d_default_batch_def();
    def.worker_count = batch_workers;
    if (jobs != nullptr) {
        jobs->install(def);
    }
    Hashes hashes(worlds.size());
    for (int s = 0; s < batch_steps; ++s) {
        I2D_CHECK(i2d_worlds_step(worlds.data(), batch_size, det::time_step, det::substeps, &def) == I2D_OK);
        for (std::size_t w = 0; w < worlds.size(); ++w) {
            hashes[w].push_back(i2d_world_get_state_hash(worlds[w]));
        }
    }
    destroy_worlds(worlds);
    return hashes;
}

// Reports each world's first step that differs from the world stepped alone.
void check_same_as_alone(const char* how, const Hashes& alone, const Hashes& batched) {
    I2D_REQUIRE(batched.size() == alone.size());
    for (std::size_t w = 0; w < alone.size(); ++w) {
        int first = -1;
        for (std::size_t s = 0; s < alone[w].size() && first < 0; ++s) {
            if (s >= batched[w].size() || batched[w][s] != alone[w][s]) {
                first = int(s) + 1;
            }
        }
        if (first >= 0) {
            fprintf(stderr, "    %s: world %zu first differs at step %d\n", how, w, first);
        }
        I2D_CHECK(first < 0);
    }
}

}  // namespace

I2D_TEST(det_batch_steps_each_world_as_alone_with_1_2_and_4_workers) {
    const Hashes alone = stepped_alone();
    I2D_REQUIRE(alone.size() == std::size_t(batch_size) && alone[0].size() == std::size_t(batch_steps));
    fprintf(stderr, "    alone: world 0 hash %016" PRIx64 " after %d steps\n", alone[0].back(), batch_steps);
    for (const int workers : {1, 2, 4}) {
        char how[48];
        std::snprintf(how, sizeof how, "%d batch workers", workers);
        check_same_as_alone(how, alone, stepped_in_batch(workers, nullptr, 1));
    }
}

I2D_TEST(det_batch_on_a_shuffled_job_system_and_with_threaded_worlds) {
    const Hashes alone = stepped_alone();
    det::JobSystem jobs(2, det::JobSystem::Order::shuffled);
    check_same_as_alone("3 batch workers on shuffled jobs", alone, stepped_in_batch(3, &jobs, 1));
    I2D_CHECK(jobs.tasks_run() > 0);
    check_same_as_alone("2 batch workers, worlds of 2 workers", alone, stepped_in_batch(2, nullptr, 2));
}
