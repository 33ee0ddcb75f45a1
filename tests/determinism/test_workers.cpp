// SPDX-License-Identifier: MIT
// Worker threads change nothing but the time a step takes: a bin of mixed shapes gives
// the same state hash at every step, the same events in the same order, and falls asleep
// at the same step, for every worker count, with the built-in threads and with a job system of the caller's that runs the
// engine's tasks late, in reverse, shuffled or inline; and in a separate process.
#include <impulse2d/impulse2d.h>

#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <unistd.h>
#endif

#include "check.h"
#include "det_job_system.hpp"
#include "det_scenes.hpp"

namespace {

using det::JobSystem;

struct WorkerSetup {
    const char* name;
    int workers;
    bool own_jobs;  // the test's job system instead of the built-in threads
    JobSystem::Order order;
    int job_threads;
};

const WorkerSetup reference = {"1 worker", 1, false, JobSystem::Order::fifo, 0};
const WorkerSetup setups[] = {
    {"2 built-in", 2, false, JobSystem::Order::fifo, 0},
    {"3 built-in", 3, false, JobSystem::Order::fifo, 0},
    {"4 built-in", 4, false, JobSystem::Order::fifo, 0},
    {"8 built-in", 8, false, JobSystem::Order::fifo, 0},
    {"2, jobs shuffled on 2 threads", 2, true, JobSystem::Order::shuffled, 2},
    {"4, jobs in reverse on 1 thread", 4, true, JobSystem::Order::lifo, 1},
    {"8, jobs shuffled on 3 threads", 8, true, JobSystem::Order::shuffled, 3},
    {"3, jobs inline", 3, true, JobSystem::Order::inline_now, 0},
};

struct BinRun {
    std::vector<uint64_t> hashes;  // every hash_every steps
    uint64_t events = 0;           // every step's event arrays, in order
    int asleep_at = -1;            // the step after which nothing was awake
    uint64_t hash_asleep = 0;
    int tasks_run = 0;             // by the test's job system
};

constexpr int hash_every = 25;

void hash_value(uint64_t& hash, uint64_t value) {
    for (int byte = 0; byte < 8; ++byte) {
        hash = (hash ^ ((value >> (8 * byte)) & 0xffu)) * 0x100000001b3ull;  // FNV-1a
    }
}

uint64_t float_bits(float f) {
    uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

// Shapes and bodies by their tags (det_scenes.hpp): the same in every world.
uint64_t tag(i2d_shape_id shape) { return uint64_t(std::uintptr_t(i2d_shape_get_user_data(shape))); }

// A list of events about a pair of shapes: its count, then each pair's tags.
template <class Event>
void hash_pair_events(uint64_t& hash, const Event* events, int32_t count, i2d_shape_id Event::*first,
                      i2d_shape_id Event::*second) {
    hash_value(hash, uint64_t(count));
    for (int32_t k = 0; k < count; ++k) {
        hash_value(hash, tag(events[k].*first) << 32 | tag(events[k].*second));
    }
}

// The step's contact and sensor begin and end events and body move events, in their order.
void hash_step_events(uint64_t& hash, i2d_world_id world) {
    const i2d_contact_events contacts = i2d_world_get_contact_events(world);
    hash_pair_events(hash, contacts.begin_events, contacts.begin_count, &i2d_contact_begin_event::shape_a,
                     &i2d_contact_begin_event::shape_b);
    hash_pair_events(hash, contacts.end_events, contacts.end_count, &i2d_contact_end_event::shape_a,
                     &i2d_contact_end_event::shape_b);
    const i2d_sensor_events sensors = i2d_world_get_sensor_events(world);
    hash_pair_events(hash, sensors.begin_events, sensors.begin_count, &i2d_sensor_begin_event::sensor_shape,
                     &i2d_sensor_begin_event::visitor_shape);
    hash_pair_events(hash, sensors.end_events, sensors.end_count, &i2d_sensor_end_event::sensor_shape,
                     &i2d_sensor_end_event::visitor_shape);
    const i2d_body_events bodies = i2d_world_get_body_events(world);
    hash_value(hash, uint64_t(bodies.move_count));
    for (int32_t k = 0; k < bodies.move_count; ++k) {
        const i2d_body_move_event& e = bodies.move_events[k];
        hash_value(hash, uint64_t(std::uintptr_t(e.user_data)) << 1 | uint64_t(e.fell_asleep));
        hash_value(hash, float_bits(e.transform.p.x) << 32 | float_bits(e.transform.p.y));
        hash_value(hash, float_bits(e.transform.q.c) << 32 | float_bits(e.transform.q.s));
    }
}

// Steps the bin (or another scene) `steps` steps, or until it sleeps when until_asleep.
BinRun run_bin(const WorkerSetup& setup, int steps, bool until_asleep, det::Scene build = det::sleeping_bin) {
    BinRun result;
    std::unique_ptr<JobSystem> jobs;
    i2d_world_def def = i2d_default_world_def();
    def.worker_count = setup.workers;
    if (setup.own_jobs) {
        jobs = std::make_unique<JobSystem>(setup.job_threads, setup.order);
        jobs->install(def);
    }
    const i2d_world_id world = build(def);
    if (I2D_IS_NULL(world)) {
        fprintf(stderr, "    %s: %s\n", setup.name, i2d_last_error_message());
        return result;
    }
    result.events = 0xcbf29ce484222325ull;  // FNV-1a's offset basis
    for (int s = 1; s <= steps; ++s) {
        i2d_world_step(world, det::time_step, det::substeps);
        hash_step_events(result.events, world);
        if (s % hash_every == 0) {
            result.hashes.push_back(i2d_world_get_state_hash(world));
        }
        if (until_asleep && i2d_world_get_counters(world).awake_body_count == 0) {
            result.asleep_at = s;
            result.hash_asleep = i2d_world_get_state_hash(world);
            break;
        }
    }
    i2d_world_destroy(world);
    result.tasks_run = jobs ? jobs->tasks_run() : 0;
    return result;
}

// The first step (a multiple of hash_every) whose hash differs, or -1.
int first_difference(const BinRun& a, const BinRun& b) {
    for (std::size_t k = 0; k < a.hashes.size() && k < b.hashes.size(); ++k) {
        if (a.hashes[k] != b.hashes[k]) {
            return int(k + 1) * hash_every;
        }
    }
    return a.hashes.size() == b.hashes.size() ? -1 : 0;
}

// Runs the scene with 1 worker and with the first setup_count setups (all by default).
void check_setups_agree(int steps, bool until_asleep, det::Scene build = det::sleeping_bin,
                        std::size_t setup_count = sizeof setups / sizeof setups[0]) {
    const BinRun expected = run_bin(reference, steps, until_asleep, build);
    I2D_REQUIRE(!expected.hashes.empty());
    if (until_asleep) {
        fprintf(stderr, "    1 worker: asleep after %d steps, hash %016" PRIx64 "\n", expected.asleep_at,
                expected.hash_asleep);
        I2D_REQUIRE(expected.asleep_at > 0);
    }
    for (std::size_t k = 0; k < setup_count; ++k) {
        const WorkerSetup& setup = setups[k];
        const BinRun got = run_bin(setup, steps, until_asleep, build);
        const int differs = first_difference(got, expected);
        fprintf(stderr, "    %s: asleep after %d, hash %016" PRIx64 ", first difference %d, job system ran %d tasks\n",
                setup.name, got.asleep_at, got.hashes.empty() ? 0 : got.hashes.back(), differs, got.tasks_run);
        I2D_CHECK(differs < 0);
        I2D_CHECK(got.events == expected.events);
        I2D_CHECK(got.asleep_at == expected.asleep_at);
        I2D_CHECK(got.hash_asleep == expected.hash_asleep);
        // The caller's job system was handed the work (the bin is large enough to share).
        I2D_CHECK(!setup.own_jobs || got.tasks_run > 0);
    }
}

// Threads of this process (Linux); -1 where unknown.
int thread_count() {
    FILE* status = std::fopen("/proc/self/status", "r");
    if (!status) {
        return -1;
    }
    char line[256];
    int threads = -1;
    while (std::fgets(line, sizeof line, status)) {
        if (std::strncmp(line, "Threads:", 8) == 0) {
            threads = std::atoi(line + 8);
        }
    }
    std::fclose(status);
    return threads;
}

// A joined thread leaves the process's count a moment after join returns (the kernel
// wakes the joiner before it removes the thread; more so under an emulator): waits up to
// a second for the count to reach `expected`, and returns the last count read.
int settled_thread_count(int expected) {
    int threads = thread_count();
    for (int tries = 0; tries < 100 && threads != expected; ++tries) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        threads = thread_count();
    }
    return threads;
}

}  // namespace

I2D_TEST(det_workers_give_the_same_bits_for_every_count) { check_setups_agree(150, false); }

I2D_TEST(det_workers_long_bin_sleeps_at_the_same_step_with_the_same_bits) { check_setups_agree(3000, true); }

I2D_TEST(det_workers_fast_bullets_give_the_same_bits_for_every_count) {
    check_setups_agree(120, false, det::bullet_room);
}

// With 2 and 3 built-in workers only: the parts do not depend on the job system (the bin's
// test runs every setup), and the suite's largest scene stays short under the sanitizers
// and the emulator.
I2D_TEST(det_workers_tall_pyramid_gives_the_same_bits_with_2_and_3_workers) {
    check_setups_agree(30, false, det::tall_pyramid, 2);
}

// The hash of a run in this process equals that of the same run in a new process (the
// test runs itself with I2D_DET_CHILD_WORKERS set, and the child prints its hash).
I2D_TEST(det_workers_separate_processes_agree) {
    constexpr int steps = 100;
    if (const char* child = std::getenv("I2D_DET_CHILD_WORKERS")) {
        WorkerSetup setup = reference;
        setup.workers = std::atoi(child);
        const BinRun run = run_bin(setup, steps, false);
        std::printf("%016" PRIx64 "\n", run.hashes.empty() ? 0 : run.hashes.back());
        return;
    }
#if defined(__linux__)
    const BinRun here = run_bin(reference, steps, false);
    I2D_REQUIRE(!here.hashes.empty());
    char self[4096] = {0};
    I2D_REQUIRE(readlink("/proc/self/exe", self, sizeof self - 1) > 0);
    for (const int workers : {1, 2}) {
        const std::string command = "I2D_DET_CHILD_WORKERS=" + std::to_string(workers) + " '" + self +
                                    "' det_workers_separate_processes_agree";
        FILE* child = popen(command.c_str(), "r");
        I2D_REQUIRE(child != nullptr);
        char line[64] = {0};
        const bool read = std::fgets(line, sizeof line, child) != nullptr;
        pclose(child);
        I2D_REQUIRE(read);
        const uint64_t there = std::strtoull(line, nullptr, 16);
        fprintf(stderr, "    this process %016" PRIx64 ", a new one with %d workers %016" PRIx64 "\n",
                here.hashes.back(), workers, there);
        I2D_CHECK(there == here.hashes.back());
    }
#else
    fprintf(stderr, "    not Linux: skipped\n");
#endif
}

// The built-in threads start with the first step large enough to share, and stop when
// the world is destroyed; a world refused for its worker settings starts none.
I2D_TEST(det_workers_built_in_threads_start_late_and_stop_with_the_world) {
    const int before = thread_count();
    if (before < 0) {
        fprintf(stderr, "    no /proc/self/status: skipped\n");
        return;
    }
    i2d_world_def def = i2d_default_world_def();
    def.worker_count = 4;
    const i2d_world_id world = det::sleeping_bin(def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    I2D_CHECK(i2d_world_get_worker_count(world) == 4);
    I2D_CHECK(thread_count() == before);
    i2d_world_step(world, det::time_step, det::substeps);
    // A sanitizer's runtime may start a thread of its own with the first one.
    const int during = thread_count();
    I2D_CHECK(during >= before + 3 && during <= before + 4);
    i2d_world_destroy(world);
    I2D_CHECK(settled_thread_count(during - 3) == during - 3);
}

I2D_TEST(det_workers_bad_settings_are_refused_and_start_nothing) {
    const int before = thread_count();
    JobSystem jobs(1, JobSystem::Order::fifo);
    const int with_jobs = thread_count();
    for (const int workers : {0, -1, I2D_MAX_WORKERS + 1, 1 << 30}) {
        i2d_world_def def = i2d_default_world_def();
        def.worker_count = workers;
        I2D_CHECK(I2D_IS_NULL(i2d_world_create(&def)));
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(std::strstr(i2d_last_error_message(), "worker_count") != nullptr);
    }
    i2d_world_def half = i2d_default_world_def();
    half.worker_count = 2;
    jobs.install(half);
    half.finish_task = nullptr;
    I2D_CHECK(I2D_IS_NULL(i2d_world_create(&half)));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "finish_task") != nullptr);
    jobs.install(half);
    half.enqueue_task = nullptr;
    I2D_CHECK(I2D_IS_NULL(i2d_world_create(&half)));
    I2D_CHECK(std::strstr(i2d_last_error_message(), "enqueue_task") != nullptr);
    I2D_CHECK(before < 0 || thread_count() == with_jobs);
    // The limit itself is accepted.
    i2d_world_def most = i2d_default_world_def();
    most.worker_count = I2D_MAX_WORKERS;
    const i2d_world_id world = i2d_world_create(&most);
    I2D_CHECK(!I2D_IS_NULL(world));
    i2d_world_destroy(world);
}

namespace {

// A job system that, before it runs each task inline, calls into the library as a
// careless game might: with the stepping world's ids, which must all be refused, and
// with another world's, which may be used.
struct IntrudingJobs {
    i2d_world_id world = I2D_NULL_WORLD_ID, other = I2D_NULL_WORLD_ID;
    i2d_body_id body = I2D_NULL_BODY_ID;
    int tasks = 0, refused = 0, accepted = 0, other_steps = 0;

    void expect_refused(bool refused_call, const char* what) {
        const bool locked = i2d_last_status() == I2D_ERR_WORLD_LOCKED &&
                            std::strstr(i2d_last_error_message(), "inside the world's step") != nullptr;
        if (refused_call && locked) {
            ++refused;
        } else {
            ++accepted;
            fprintf(stderr, "    %s inside the step: %s\n", what, i2d_last_error_message());
        }
    }

    void intrude() {
        i2d_body_def def = i2d_default_body_def();
        expect_refused(i2d_world_step(world, det::time_step, det::substeps) == I2D_ERR_WORLD_LOCKED, "step");
        expect_refused(i2d_body_set_linear_velocity(body, i2d_vec2{5.0f, 0.0f}) == I2D_ERR_WORLD_LOCKED,
                       "set velocity");
        expect_refused(I2D_IS_NULL(i2d_body_create(world, &def)), "create body");
        const i2d_vec2 p = i2d_body_get_position(body);
        expect_refused(p.x == 0.0f && p.y == 0.0f, "get position");
        expect_refused(!i2d_world_is_valid(world), "is valid");
        expect_refused(i2d_body_destroy(body) == I2D_ERR_WORLD_LOCKED, "destroy body");
        expect_refused(i2d_world_destroy(world) == I2D_ERR_WORLD_LOCKED, "destroy world");
        other_steps += i2d_world_step(other, det::time_step, det::substeps) == I2D_OK;
    }

    static void* enqueue(i2d_task_fn* task, int32_t item_count, int32_t, void* task_context, void* self) {
        IntrudingJobs& jobs = *static_cast<IntrudingJobs*>(self);
        jobs.intrude();
        task(0, item_count, 0, task_context);
        ++jobs.tasks;
        return nullptr;
    }
    static void finish(void*, void*) {}
};

// The bin with a bodiless static body placed away from it: a target for the intruder
// that changes nothing in the bin.
i2d_world_id bin_with_marker(const i2d_world_def& def, i2d_body_id& marker) {
    const i2d_world_id world = det::sleeping_bin(def);
    marker = det::add_body(world, I2D_BODY_STATIC, i2d_vec2{100.0f, 100.0f});
    return world;
}

}  // namespace

// A job system's callbacks run inside the step: every call that names the stepping
// world or one of its bodies is refused there with a message, and the step goes on to
// the same bits as a world nobody called into; another world may be stepped meanwhile.
I2D_TEST(det_workers_calls_from_inside_the_job_system_are_refused) {
    constexpr int steps = 10;
    i2d_body_id marker = I2D_NULL_BODY_ID;
    const i2d_world_id quiet = bin_with_marker(i2d_default_world_def(), marker);
    I2D_REQUIRE(!I2D_IS_NULL(quiet));
    for (int s = 0; s < steps; ++s) {
        i2d_world_step(quiet, det::time_step, det::substeps);
    }
    const uint64_t expected = i2d_world_get_state_hash(quiet);
    i2d_world_destroy(quiet);

    IntrudingJobs jobs;
    i2d_world_def def = i2d_default_world_def();
    def.worker_count = 3;
    def.enqueue_task = &IntrudingJobs::enqueue;
    def.finish_task = &IntrudingJobs::finish;
    def.user_task_context = &jobs;
    jobs.world = bin_with_marker(def, jobs.body);
    I2D_REQUIRE(!I2D_IS_NULL(jobs.world));
    const i2d_world_def other_def = i2d_default_world_def();
    jobs.other = i2d_world_create(&other_def);
    det::add_body(jobs.other, I2D_BODY_DYNAMIC, i2d_vec2{0.0f, 0.0f});
    for (int s = 0; s < steps; ++s) {
        I2D_CHECK_STATUS(i2d_world_step(jobs.world, det::time_step, det::substeps), I2D_OK);
    }
    fprintf(stderr, "    %d tasks, %d calls refused, %d accepted, other world stepped %d times\n", jobs.tasks,
            jobs.refused, jobs.accepted, jobs.other_steps);
    I2D_CHECK(jobs.tasks > 0);
    I2D_CHECK(jobs.accepted == 0);
    I2D_CHECK(jobs.refused == 7 * jobs.tasks);
    I2D_CHECK(jobs.other_steps == jobs.tasks);
    I2D_CHECK(i2d_world_get_state_hash(jobs.world) == expected);
    I2D_CHECK(i2d_body_is_valid(jobs.body));
    i2d_world_destroy(jobs.other);
    i2d_world_destroy(jobs.world);
}
