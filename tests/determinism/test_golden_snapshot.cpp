// SPDX-License-Identifier: MIT
// The golden snapshot: a file saved once (tests/determinism/data/golden_snapshot.bin, written by
// make_golden_snapshot.c) goes on to the state hash recorded beside it (golden_snapshot.txt) on
// every platform this suite runs on (x86-64, AArch64 under qemu), as a new world and restored in
// place, with any worker count and SIMD path. The WebAssembly build checks the same file.
//
// A failure here after a change to the physics or the snapshot format means the file must be
// made again (make_golden_snapshot tests/determinism/data) and the commit must say why; one on
// a single platform means results differ between platforms.
#include <impulse2d/impulse2d.h>
#include <impulse2d/snapshot.h>

#include <cinttypes>
#include <cstdio>
#include <string>
#include <vector>

#include "check.h"

#ifndef I2D_GOLDEN_SNAPSHOT_DIR
#error "tests/CMakeLists.txt defines I2D_GOLDEN_SNAPSHOT_DIR (the folder of golden_snapshot.bin)"
#endif

namespace {

constexpr float time_step = 1.0f / 60.0f;
constexpr int substeps = 4;

struct Golden {
    std::vector<unsigned char> bytes;
    unsigned long long size = 0;  // as the .txt says
    uint64_t hash_at_load = 0;
    int steps = 0;
    uint64_t hash = 0;
    bool ok = false;
};

const Golden& golden() {
    static const Golden g = [] {
        Golden r;
        const std::string dir = I2D_GOLDEN_SNAPSHOT_DIR;
        if (FILE* in = std::fopen((dir + "/golden_snapshot.bin").c_str(), "rb")) {
            for (int c; (c = std::fgetc(in)) != EOF;) {
                r.bytes.push_back((unsigned char)c);
            }
            std::fclose(in);
        }
        FILE* txt = std::fopen((dir + "/golden_snapshot.txt").c_str(), "r");
        if (txt == nullptr) {
            fprintf(stderr, "    cannot read %s/golden_snapshot.txt\n", dir.c_str());
            return r;
        }
        unsigned long long at_load = 0, after = 0;
        const int fields = std::fscanf(txt, "bytes=%llu hash_at_load=%llx steps=%d hash=%llx", &r.size, &at_load,
                                       &r.steps, &after);
        std::fclose(txt);
        r.hash_at_load = at_load;
        r.hash = after;
        r.ok = fields == 4 && r.steps > 0 && !r.bytes.empty() && r.size == r.bytes.size();
        if (!r.ok) {
            fprintf(stderr, "    golden files unreadable: %d fields, %zu bytes read, %llu recorded\n", fields,
                    r.bytes.size(), r.size);
        }
        return r;
    }();
    return g;
}

uint64_t step(i2d_world_id world, int steps) {
    for (int s = 0; s < steps; ++s) {
        i2d_world_step(world, time_step, substeps);
    }
    return i2d_world_get_state_hash(world);
}

void check_hash(const char* how, uint64_t hash, uint64_t expected) {
    if (hash != expected) {
        ++i2d_check_failures;
        fprintf(stderr, "    %s: hash %016" PRIx64 ", golden %016" PRIx64 "\n", how, hash, expected);
    }
}

}  // namespace

I2D_TEST(det_golden_snapshot_made_into_a_new_world_reaches_the_golden_hash) {
    const Golden& g = golden();
    I2D_REQUIRE(g.ok);
    const i2d_world_id world = i2d_world_create_from_snapshot(g.bytes.data(), g.bytes.size(), nullptr);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    check_hash("at load", i2d_world_get_state_hash(world), g.hash_at_load);
    check_hash("a new world", step(world, g.steps), g.hash);
    i2d_world_destroy(world);
}

// Restored in place into a world elsewhere in the same scene's future, and into a world that
// never held it (an empty one).
I2D_TEST(det_golden_snapshot_restored_in_place_reaches_the_golden_hash) {
    const Golden& g = golden();
    I2D_REQUIRE(g.ok);
    const i2d_world_id world = i2d_world_create_from_snapshot(g.bytes.data(), g.bytes.size(), nullptr);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    step(world, 25);
    I2D_CHECK_STATUS(i2d_world_restore_snapshot(world, g.bytes.data(), g.bytes.size()), I2D_OK);
    check_hash("restored in place, at load", i2d_world_get_state_hash(world), g.hash_at_load);
    check_hash("restored in place", step(world, g.steps), g.hash);
    i2d_world_destroy(world);

    const i2d_world_def def = i2d_default_world_def();
    const i2d_world_id empty = i2d_world_create(&def);
    I2D_REQUIRE(!I2D_IS_NULL(empty));
    I2D_CHECK_STATUS(i2d_world_restore_snapshot(empty, g.bytes.data(), g.bytes.size()), I2D_OK);
    check_hash("restored into an empty world", step(empty, g.steps), g.hash);
    i2d_world_destroy(empty);
}

// The host's wiring is not in the file and does not change the bits.
I2D_TEST(det_golden_snapshot_reaches_the_golden_hash_on_every_simd_path_and_worker_count) {
    const Golden& g = golden();
    I2D_REQUIRE(g.ok);
    const i2d_simd_path paths[] = {I2D_SIMD_SCALAR, I2D_SIMD_SSE2, I2D_SIMD_AVX2, I2D_SIMD_AVX512, I2D_SIMD_NEON, I2D_SIMD_WASM128};
    for (const i2d_simd_path path : paths) {
        if (!i2d_simd_path_supported(path)) {
            continue;
        }
        for (const int workers : {1, 3}) {
            i2d_world_def runtime = i2d_default_world_def();
            runtime.simd_path = path;
            runtime.worker_count = workers;
            const i2d_world_id world = i2d_world_create_from_snapshot(g.bytes.data(), g.bytes.size(), &runtime);
            I2D_REQUIRE(!I2D_IS_NULL(world));
            const std::string how = "SIMD path " + std::to_string(int(path)) + ", " + std::to_string(workers) +
                                    " worker" + (workers > 1 ? "s" : "");
            check_hash(how.c_str(), step(world, g.steps), g.hash);
            i2d_world_destroy(world);
        }
    }
}
