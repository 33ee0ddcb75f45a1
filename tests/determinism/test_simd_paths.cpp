// SPDX-License-Identifier: MIT
// Every SIMD path the machine supports gives bitwise the same simulation as the scalar
// path: the state hash (every body's transform and velocities, every contact's
// impulses) is compared every 50 steps of a mixed scene for 500 steps.
// The scene (det_scenes.hpp) exercises every branch the kernels blend per lane.
#include <impulse2d/impulse2d.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <vector>

#include "check.h"
#include "det_scenes.hpp"

namespace {

using det::substeps;
using det::time_step;
constexpr int steps = 500;
constexpr int hash_every = 50;

// The hashes every hash_every steps, or an empty list when the scene failed.
std::vector<uint64_t> run(i2d_simd_path path, det::Scene scene = det::mixed_scene) {
    std::vector<uint64_t> hashes;
    i2d_world_def wd = i2d_default_world_def();
    wd.simd_path = path;
    const i2d_world_id world = scene(wd);
    if (I2D_IS_NULL(world)) {
        fprintf(stderr, "    world with path %d: %s\n", int(path), i2d_last_error_message());
        return hashes;
    }
    int sleeping_seen = 0;
    for (int s = 1; s <= steps; ++s) {
        i2d_world_step(world, time_step, substeps);
        sleeping_seen = i2d_world_get_counters(world).sleeping_island_count > 0 ? 1 : sleeping_seen;
        if (s % hash_every == 0) {
            hashes.push_back(i2d_world_get_state_hash(world));
        }
    }
    if (!sleeping_seen && scene == det::mixed_scene) {
        fprintf(stderr, "    nothing fell asleep: the scene no longer covers sleeping bodies\n");
        hashes.clear();
    }
    i2d_world_destroy(world);
    return hashes;
}

void check_every_path(det::Scene scene) {
    const std::vector<uint64_t> scalar = run(I2D_SIMD_SCALAR, scene);
    I2D_REQUIRE(scalar.size() == steps / hash_every);
    const i2d_simd_path paths[] = {I2D_SIMD_SSE2, I2D_SIMD_AVX2,    I2D_SIMD_AVX512,
                                   I2D_SIMD_NEON, I2D_SIMD_WASM128, I2D_SIMD_AUTOMATIC};
    const char* names[] = {"sse2", "avx2", "avx512", "neon", "wasm128", "automatic"};
    for (size_t p = 0; p < sizeof paths / sizeof paths[0]; ++p) {
        if (!i2d_simd_path_supported(paths[p])) {
            fprintf(stderr, "    %s: not supported on this machine, skipped\n", names[p]);
            continue;
        }
        const std::vector<uint64_t> wide = run(paths[p], scene);
        I2D_REQUIRE(wide.size() == scalar.size());
        int first_difference = -1;
        for (std::size_t k = 0; k < wide.size() && first_difference < 0; ++k) {
            first_difference = wide[k] != scalar[k] ? int(k + 1) * hash_every : -1;
        }
        fprintf(stderr, "    %s: hash after %d steps %016" PRIx64 " (scalar %016" PRIx64 "), first difference %s%d\n",
                names[p], steps, wide.back(), scalar.back(), first_difference < 0 ? "none " : "at step ",
                first_difference < 0 ? 0 : first_difference);
        I2D_CHECK(first_difference < 0);
    }
}

}  // namespace

I2D_TEST(det_every_simd_path_gives_the_scalar_bits) { check_every_path(det::mixed_scene); }

// The hinge kernels: W hinges at a time, chunks cut anywhere in a colour, rows some lanes
// have and others lack, the overflow colour's one at a time, and lanes the guard undoes.
I2D_TEST(det_every_simd_path_gives_the_scalar_bits_with_hinges) { check_every_path(det::hinge_net); }

// Ragdolls: every joint a hinge with a limit and a spring, among contacts.
I2D_TEST(det_every_simd_path_gives_the_scalar_bits_with_ragdolls) { check_every_path(det::ragdoll_heap); }

I2D_TEST(det_hinges_end_in_the_recorded_state) {
    // Recorded with the scalar revolute code that solved every hinge before the hinge
    // kernels (4b0f8ee): the kernels do its arithmetic, in its order, to the bit. Moved
    // on purpose since (b48738758630e617 before): impacts the continuous stage finds are
    // solved where they happen (issue 43), and this net's bodies meet its bars there
    // (e7b01a67c4bb83c8 before): the body held at two places closes a loop, which the
    // exact solve now takes (issue 43).
    constexpr uint64_t recorded = 0x1824c0e2a186aed8ull;
    const std::vector<uint64_t> hashes = run(I2D_SIMD_AUTOMATIC, det::hinge_net);
    I2D_REQUIRE(hashes.size() == steps / hash_every);
    fprintf(stderr, "    hash after %d steps %016" PRIx64 ", recorded %016" PRIx64 "\n", steps, hashes.back(), recorded);
    I2D_CHECK(hashes.back() == recorded);
}

I2D_TEST(det_mixed_scene_ends_in_the_recorded_state) {
    // The hash after 500 steps, recorded on x86-64 (g++ 12 and clang 14, SSE2, AVX2 and
    // AVX-512) and on AArch64 (NEON, under qemu): every platform must reach these exact
    // bits. A change that alters the simulation on purpose records the new hash here (and
    // says so in its commit); one that changes it by accident fails here. Moved by issue
    // 43 (9891b9dca5ebaef0 before): fast free bodies meet static and kinematic ones at
    // their time of impact, where the impact is solved; and again (a528c1bd9106747e
    // before, which chains off still gives): its elastic bodies' impacts that pass on to
    // a neighbour within the step are taken one at a time (impact_chain.hpp).
    constexpr uint64_t recorded = 0x58a45a55ad363970ull;
    const std::vector<uint64_t> hashes = run(I2D_SIMD_AUTOMATIC);
    I2D_REQUIRE(hashes.size() == steps / hash_every);
    fprintf(stderr, "    hash after %d steps %016" PRIx64 ", recorded %016" PRIx64 "\n", steps, hashes.back(), recorded);
    I2D_CHECK(hashes.back() == recorded);
}

I2D_TEST(det_same_path_twice_gives_the_same_bits) {
    const std::vector<uint64_t> first = run(I2D_SIMD_AUTOMATIC);
    const std::vector<uint64_t> second = run(I2D_SIMD_AUTOMATIC);
    I2D_REQUIRE(first.size() == steps / hash_every);
    I2D_CHECK(first == second);
}

I2D_TEST(det_world_reports_the_path_it_uses) {
    const i2d_simd_path paths[] = {I2D_SIMD_SCALAR, I2D_SIMD_SSE2, I2D_SIMD_AVX2,
                                   I2D_SIMD_AVX512, I2D_SIMD_NEON, I2D_SIMD_WASM128};
    for (const i2d_simd_path path : paths) {
        i2d_world_def def = i2d_default_world_def();
        def.simd_path = path;
        const i2d_world_id world = i2d_world_create(&def);
        const i2d_status status = i2d_last_status();
        if (!i2d_simd_path_supported(path)) {
            I2D_CHECK(I2D_IS_NULL(world));
            I2D_CHECK(status == I2D_ERR_INVALID_ARGUMENT);
            continue;
        }
        I2D_REQUIRE(!I2D_IS_NULL(world));
        I2D_CHECK(i2d_world_get_simd_path(world) == path);
        i2d_world_destroy(world);
    }
    i2d_world_def def = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    I2D_CHECK(i2d_world_get_simd_path(world) != I2D_SIMD_AUTOMATIC);
    I2D_CHECK(i2d_simd_path_supported(i2d_world_get_simd_path(world)));
    i2d_world_destroy(world);
}
