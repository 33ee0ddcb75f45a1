// SPDX-License-Identifier: MIT
// Snapshots: a world restored from one continues exactly as the saved world does, in
// place, as a new world, with other worker counts and SIMD paths, and in another process;
// ids come back; a buffer that is not a good snapshot is refused and changes nothing.
//
// "Exactly" is checked on the snapshots themselves: after the same steps, the world that
// was restored and the one that never was save to the same bytes (every body, shape,
// contact, island, tree node and free list), and their state hashes agree at every step.
#include <impulse2d/impulse2d.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#if defined(__linux__)
#include <unistd.h>
#endif

#include "check.h"
#include "det_scenes.hpp"

namespace {

using Bytes = std::vector<unsigned char>;

// Steps before the save (long enough for the pile to sleep and the bullet to meet its
// wall) and after it.
constexpr int steps_before = 70;
constexpr int steps_after = 60;

Bytes save(i2d_world_id world) {
    Bytes bytes(i2d_world_get_snapshot_size(world));
    size_t written = 0;
    if (i2d_world_save_snapshot(world, bytes.data(), bytes.size(), &written) != I2D_OK || written != bytes.size()) {
        fprintf(stderr, "    save failed: %s\n", i2d_last_error_message());
        bytes.clear();
    }
    return bytes;
}

// Steps the world, returning the state hash after each step.
std::vector<uint64_t> step(i2d_world_id world, int steps) {
    std::vector<uint64_t> hashes;
    for (int s = 0; s < steps; ++s) {
        i2d_world_step(world, det::time_step, det::substeps);
        hashes.push_back(i2d_world_get_state_hash(world));
    }
    return hashes;
}

// The snapshot scene at the save, and how it goes on without being restored.
struct Reference {
    Bytes at_save;
    std::vector<uint64_t> hashes_after;
    Bytes after;
};

const Reference& reference() {
    static const Reference ref = [] {
        Reference r;
        const i2d_world_id world = det::snapshot_scene(i2d_default_world_def());
        step(world, steps_before);
        r.at_save = save(world);
        r.hashes_after = step(world, steps_after);
        r.after = save(world);
        i2d_world_destroy(world);
        return r;
    }();
    return ref;
}

// A world restored from the reference's snapshot goes on to the same state.
void check_continues(i2d_world_id world, const char* how) {
    const Reference& ref = reference();
    const std::vector<uint64_t> hashes = step(world, steps_after);
    const Bytes after = save(world);
    const bool same = hashes == ref.hashes_after && after == ref.after;
    fprintf(stderr, "    %s: %s (last hash %016" PRIx64 ", reference %016" PRIx64 ")\n", how,
            same ? "the same bytes" : "DIFFERENT", hashes.empty() ? 0 : hashes.back(), ref.hashes_after.back());
    I2D_CHECK(same);
}

// A valid snapshot with the payload's byte `at` changed and the checksum fixed up is not
// possible from the C API (the checksum is private to the library): the unit tests do
// that. Here the checksum catches every change.
void check_refused(i2d_world_id world, const Bytes& buffer, const char* what) {
    const uint64_t hash = i2d_world_get_state_hash(world);
    const size_t size_before = i2d_world_get_snapshot_size(world);
    const i2d_status status = i2d_world_restore_snapshot(world, buffer.data(), buffer.size());
    if (status != I2D_ERR_INVALID_SNAPSHOT || i2d_world_get_state_hash(world) != hash ||
        i2d_world_get_snapshot_size(world) != size_before) {
        ++i2d_check_failures;
        fprintf(stderr, "    %s: %s (%s)\n", what, i2d_status_string(status), i2d_last_error_message());
    }
}

}  // namespace

I2D_TEST(det_snapshot_restored_in_place_goes_on_as_the_saved_world) {
    const Reference& ref = reference();
    I2D_REQUIRE(!ref.at_save.empty() && !ref.after.empty());
    const i2d_world_id world = det::snapshot_scene(i2d_default_world_def());
    step(world, steps_before + 25);  // somewhere else entirely
    I2D_REQUIRE(i2d_world_restore_snapshot(world, ref.at_save.data(), ref.at_save.size()) == I2D_OK);
    I2D_CHECK(save(world) == ref.at_save);
    check_continues(world, "restored in place");
    i2d_world_destroy(world);
}

I2D_TEST(det_snapshot_made_into_a_new_world_goes_on_as_the_saved_world) {
    const Reference& ref = reference();
    const i2d_world_id world = i2d_world_create_from_snapshot(ref.at_save.data(), ref.at_save.size(), nullptr);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    check_continues(world, "a new world");
    i2d_world_destroy(world);
}

// The host's wiring is not in the snapshot, and does not change the bits.
I2D_TEST(det_snapshot_goes_on_alike_with_other_workers_and_simd_paths) {
    const Reference& ref = reference();
    const i2d_simd_path paths[] = {I2D_SIMD_SCALAR, I2D_SIMD_SSE2, I2D_SIMD_AVX2, I2D_SIMD_AVX512, I2D_SIMD_NEON, I2D_SIMD_WASM128};
    for (const i2d_simd_path path : paths) {
        if (!i2d_simd_path_supported(path)) {
            continue;
        }
        for (const int workers : {1, 3}) {
            i2d_world_def runtime = i2d_default_world_def();
            runtime.simd_path = path;
            runtime.worker_count = workers;
            const i2d_world_id world = i2d_world_create_from_snapshot(ref.at_save.data(), ref.at_save.size(), &runtime);
            I2D_REQUIRE(!I2D_IS_NULL(world));
            I2D_CHECK(i2d_world_get_worker_count(world) == workers && i2d_world_get_simd_path(world) == path);
            const std::string how = "SIMD path " + std::to_string(int(path)) + ", " + std::to_string(workers) +
                                    " worker" + (workers > 1 ? "s" : "");
            check_continues(world, how.c_str());
            i2d_world_destroy(world);
        }
    }
}

// The test runs itself with I2D_DET_SNAPSHOT_FILE set: the child restores the file the
// parent wrote, steps, and writes its snapshot back.
I2D_TEST(det_snapshot_goes_on_alike_in_another_process) {
    if (const char* file = std::getenv("I2D_DET_SNAPSHOT_FILE")) {
        FILE* in = std::fopen(file, "rb");
        I2D_REQUIRE(in != nullptr);
        Bytes bytes;
        for (int c; (c = std::fgetc(in)) != EOF;) {
            bytes.push_back((unsigned char)c);
        }
        std::fclose(in);
        const i2d_world_id world = i2d_world_create_from_snapshot(bytes.data(), bytes.size(), nullptr);
        I2D_REQUIRE(!I2D_IS_NULL(world));
        step(world, steps_after);
        const Bytes after = save(world);
        FILE* out = std::fopen(file, "wb");
        I2D_REQUIRE(out != nullptr);
        std::fwrite(after.data(), 1, after.size(), out);
        std::fclose(out);
        i2d_world_destroy(world);
        return;
    }
#if defined(__linux__)
    const Reference& ref = reference();
    char self[4096] = {0};
    I2D_REQUIRE(readlink("/proc/self/exe", self, sizeof self - 1) > 0);
    char file[] = "/tmp/i2d_snapshot_XXXXXX";
    const int fd = mkstemp(file);
    I2D_REQUIRE(fd >= 0);
    I2D_REQUIRE(write(fd, ref.at_save.data(), ref.at_save.size()) == ssize_t(ref.at_save.size()));
    close(fd);
    const std::string command = "I2D_DET_SNAPSHOT_FILE='" + std::string(file) + "' '" + self +
                                "' det_snapshot_goes_on_alike_in_another_process >/dev/null";
    I2D_REQUIRE(std::system(command.c_str()) == 0);
    FILE* in = std::fopen(file, "rb");
    I2D_REQUIRE(in != nullptr);
    Bytes there;
    for (int c; (c = std::fgetc(in)) != EOF;) {
        there.push_back((unsigned char)c);
    }
    std::fclose(in);
    std::remove(file);
    fprintf(stderr, "    another process: %s\n", there == ref.after ? "the same bytes" : "DIFFERENT");
    I2D_CHECK(there == ref.after);
#else
    fprintf(stderr, "    not Linux: skipped\n");
#endif
}

// After an in-place restore, ids of what existed at the save work again (even if it was
// destroyed since); ids of what was made after the save are stale. A new world's ids are
// found from the old ones.
I2D_TEST(det_snapshot_brings_back_the_ids_that_existed_at_the_save) {
    const i2d_world_id world = det::mixed_scene(i2d_default_world_def());
    const i2d_body_id early = det::add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{0, 20});
    const i2d_shape_def plain = det::material(0.6f, 0.0f);
    const i2d_shape_id early_shape = i2d_shape_create_box(early, &plain, 0.5f, 0.5f);
    const Bytes at_save = save(world);
    i2d_body_destroy(early);
    const i2d_body_id late = det::add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{2, 20});
    I2D_CHECK(!i2d_body_is_valid(early) && i2d_body_is_valid(late));
    I2D_REQUIRE(i2d_world_restore_snapshot(world, at_save.data(), at_save.size()) == I2D_OK);
    I2D_CHECK(i2d_body_is_valid(early) && i2d_shape_is_valid(early_shape));
    I2D_CHECK(!i2d_body_is_valid(late));
    I2D_CHECK(I2D_ID_EQUALS(i2d_shape_get_body(early_shape), early));

    const i2d_world_id copy = i2d_world_create_from_snapshot(at_save.data(), at_save.size(), nullptr);
    I2D_REQUIRE(!I2D_IS_NULL(copy));
    const i2d_body_id there = i2d_body_in_world(early, copy);
    I2D_CHECK(i2d_body_is_valid(there) && !I2D_ID_EQUALS(there, early));
    I2D_CHECK(I2D_ID_EQUALS(i2d_body_get_world(there), copy));
    const i2d_vec2 p = i2d_body_get_position(there), q = i2d_body_get_position(early);
    I2D_CHECK(p.x == q.x && p.y == q.y);
    I2D_CHECK(I2D_ID_EQUALS(i2d_shape_in_world(early_shape, copy), i2d_shape_in_world(early_shape, copy)));
    I2D_CHECK(I2D_IS_NULL(i2d_body_in_world(late, copy)) && i2d_last_status() == I2D_OK);
    I2D_CHECK(I2D_IS_NULL(i2d_body_in_world(i2d_body_id{early_shape.bits}, copy)) &&
              i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    i2d_world_destroy(copy);
    i2d_world_destroy(world);
}

// A contact ended between steps is reported by the next step, by the world that steps
// next, in its own ids.
I2D_TEST(det_snapshot_carries_the_ends_that_wait_for_the_next_step) {
    const i2d_world_id world = det::mixed_scene(i2d_default_world_def());
    step(world, 40);
    const i2d_contact_events before = i2d_world_get_contact_events(world);
    I2D_REQUIRE(before.begin_count > 0);
    const i2d_shape_id touched = before.begin_events[0].shape_a;
    i2d_shape_destroy(before.begin_events[0].shape_b);
    const Bytes at_save = save(world);
    const i2d_world_id copy = i2d_world_create_from_snapshot(at_save.data(), at_save.size(), nullptr);
    I2D_REQUIRE(!I2D_IS_NULL(copy));
    step(copy, 1);
    const i2d_contact_events after = i2d_world_get_contact_events(copy);
    const i2d_shape_id touched_there = i2d_shape_in_world(touched, copy);
    bool reported = false;
    for (int32_t k = 0; k < after.end_count; ++k) {
        reported = reported || I2D_ID_EQUALS(after.end_events[k].shape_a, touched_there) ||
                   I2D_ID_EQUALS(after.end_events[k].shape_b, touched_there);
    }
    I2D_CHECK(reported);
    i2d_world_destroy(copy);
    i2d_world_destroy(world);
}

// Every truncation, every single-byte change (the checksum, or the header, catches it),
// zeros, a foreign buffer, a newer format and a rollback state's kind: each refused with
// a message, and the world as it was.
I2D_TEST(det_snapshot_refusals_leave_the_world_as_it_was) {
    const i2d_world_def def = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&def);
    const i2d_shape_def plain = det::material(0.6f, 0.0f);
    det::add_ground(world, plain, 5.0f);
    const i2d_body_id ball = det::add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{0, 1});
    const i2d_circle circle = {{0, 0}, 0.3f};
    i2d_shape_create_circle(ball, &plain, &circle);
    step(world, 30);
    const Bytes good = save(world);
    I2D_REQUIRE(good.size() > 48);
    for (size_t length = 0; length < good.size(); ++length) {
        check_refused(world, Bytes(good.begin(), good.begin() + std::ptrdiff_t(length)), "truncated");
    }
    for (size_t at = 0; at < good.size(); ++at) {
        Bytes flipped = good;
        flipped[at] ^= 0x10;
        check_refused(world, flipped, "a changed byte");
    }
    check_refused(world, Bytes(good.size(), 0), "zeros");
    Bytes foreign(good.size());
    for (size_t k = 0; k < foreign.size(); ++k) {
        foreign[k] = (unsigned char)(k * 131 + 7);
    }
    check_refused(world, foreign, "foreign bytes");
    Bytes newer = good;
    newer[8] = 99;  // the format version
    check_refused(world, newer, "a newer format");
    Bytes state = good;
    state[12] = 2;  // the kind: a rollback state
    check_refused(world, state, "a rollback state's kind");
    Bytes longer = good;
    longer.push_back(0);
    check_refused(world, longer, "a byte too many");
    I2D_CHECK(i2d_world_restore_snapshot(world, nullptr, 100) == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(I2D_IS_NULL(i2d_world_create_from_snapshot(good.data(), good.size() - 1, nullptr)) &&
              i2d_last_status() == I2D_ERR_INVALID_SNAPSHOT);
    // And the good one is still good.
    I2D_CHECK(i2d_world_restore_snapshot(world, good.data(), good.size()) == I2D_OK);
    i2d_world_destroy(world);
}

// A buffer too small is left holding no snapshot, and the call says how much is needed.
I2D_TEST(det_snapshot_save_says_the_size_it_needs) {
    const i2d_world_id world = det::mixed_scene(i2d_default_world_def());
    const size_t size = i2d_world_get_snapshot_size(world);
    Bytes small(size - 1, 0xAB);
    size_t written = 0;
    I2D_CHECK(i2d_world_save_snapshot(world, small.data(), small.size(), &written) == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(written == size);
    // What a short buffer got is no snapshot: its header is zeroed, and it is refused.
    I2D_CHECK(small[0] == 0 && i2d_world_restore_snapshot(world, small.data(), small.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(i2d_world_save_snapshot(world, nullptr, 0, &written) == I2D_ERR_INVALID_ARGUMENT && written == size);
    I2D_CHECK(i2d_world_get_snapshot_size(i2d_world_id{0}) == 0 && i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    i2d_world_destroy(world);
}

// ---- Rollback states ---------------------------------------------------------------------

namespace {

Bytes save_state(i2d_world_id world) {
    Bytes bytes(i2d_world_get_state_size(world));
    size_t written = 0;
    if (i2d_world_save_state(world, bytes.data(), bytes.size(), &written) != I2D_OK || written != bytes.size()) {
        fprintf(stderr, "    state save failed: %s\n", i2d_last_error_message());
        bytes.clear();
    }
    return bytes;
}

// A frame's input, the same whenever the frame is played: a push on one of the bodies.
void play_frame(i2d_world_id world, const std::vector<i2d_body_id>& bodies, int frame) {
    const i2d_body_id body = bodies[size_t(frame * 7) % bodies.size()];
    const i2d_vec2 impulse = {0.2f * float(frame % 5) - 0.4f, 0.5f};
    i2d_body_apply_linear_impulse(body, impulse, i2d_body_get_world_center_of_mass(body), true);
    i2d_world_step(world, det::time_step, det::substeps);
}

}  // namespace

// A rollback netcode's loop: every frame saved; at frame 100 the game goes back 8 frames
// and plays them again with the same inputs, then on. Every hash and the final snapshot
// are those of the run that never went back. Going back 90 frames restores a state older
// than the last 64 the world saved, which it no longer knows as its own: the checked path.
I2D_TEST(det_rollback_eight_frames_back_and_again_gives_the_same_bits) {
    constexpr int frames = 130, rollback_at = 100;
    std::vector<uint64_t> straight_hashes;
    Bytes straight_end;
    for (const int depth : {0, 8, 90}) {
        const bool roll_back = depth > 0;
        const i2d_world_id world = det::snapshot_scene(i2d_default_world_def());
        // The players' pieces: boxes the inputs push about.
        std::vector<i2d_body_id> bodies;
        const i2d_shape_def plain = det::material(0.6f, 0.0f);
        for (int k = 0; k < 8; ++k) {
            bodies.push_back(det::add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{-4.0f + float(k), 12.0f}));
            i2d_shape_create_box(bodies.back(), &plain, 0.3f, 0.3f);
        }
        step(world, steps_before);
        std::vector<Bytes> saved(frames);
        std::vector<uint64_t> hashes;
        for (int frame = 0; frame < frames; ++frame) {
            saved[size_t(frame)] = save_state(world);
            if (roll_back && frame == rollback_at) {
                I2D_REQUIRE(i2d_world_restore_state(world, saved[size_t(frame - depth)].data(),
                                                    saved[size_t(frame - depth)].size()) == I2D_OK);
                for (int again = frame - depth; again < frame; ++again) {
                    play_frame(world, bodies, again);
                    I2D_CHECK(i2d_world_get_state_hash(world) == straight_hashes[size_t(again)]);
                }
            }
            play_frame(world, bodies, frame);
            hashes.push_back(i2d_world_get_state_hash(world));
        }
        if (!roll_back) {
            straight_hashes = hashes;
            straight_end = save(world);
        } else {
            I2D_CHECK(hashes == straight_hashes);
            I2D_CHECK(save(world) == straight_end);
        }
        i2d_world_destroy(world);
    }
}

// A contact keeps only the points it has (format 6): two worlds alike but for a box lying
// flat (two points) where the other has a ball (one point) differ in their states by one
// point's bytes, and the ball's world goes on from its state as if never saved.
I2D_TEST(det_rollback_state_holds_only_the_points_a_contact_has) {
    // A point as a contact saves it: two anchors (2 x 8 bytes), its separation and two
    // impulses (3 x 4), its feature id (4) and its base separation for recycling (4).
    constexpr size_t point_bytes = 36;
    const i2d_shape_def def = det::material(0.6f, 0.0f);
    i2d_world_id worlds[2];
    size_t sizes[2];
    for (int kind = 0; kind < 2; ++kind) {
        const i2d_world_def wd = i2d_default_world_def();
        worlds[kind] = i2d_world_create(&wd);
        det::add_ground(worlds[kind], def, 5.0f);
        const i2d_body_id body = det::add_body(worlds[kind], I2D_BODY_DYNAMIC, i2d_vec2{0.0f, 0.5f});
        if (kind == 0) {
            i2d_shape_create_box(body, &def, 0.5f, 0.5f);
        } else {
            const i2d_circle ball = {{0.0f, 0.0f}, 0.5f};
            i2d_shape_create_circle(body, &def, &ball);
        }
        step(worlds[kind], 30);
        i2d_contact_data contact;
        I2D_REQUIRE(i2d_body_get_contact_data(body, &contact, 1) == 1);
        I2D_CHECK(contact.manifold.point_count == 2 - kind);
        sizes[kind] = i2d_world_get_state_size(worlds[kind]);
    }
    I2D_CHECK(sizes[0] == sizes[1] + point_bytes);
    const Bytes state = save_state(worlds[1]);
    const std::vector<uint64_t> straight = step(worlds[1], 20);
    I2D_REQUIRE(i2d_world_restore_state(worlds[1], state.data(), state.size()) == I2D_OK);
    I2D_CHECK(step(worlds[1], 20) == straight);
    i2d_world_destroy(worlds[0]);
    i2d_world_destroy(worlds[1]);
}

// A state restores only into its own world, as its structure stood; truncated, changed
// or foreign bytes are refused; each refusal leaves the world as it was.
I2D_TEST(det_rollback_state_refusals_leave_the_world_as_it_was) {
    const i2d_world_id world = det::mixed_scene(i2d_default_world_def());
    step(world, 20);
    const Bytes state = save_state(world);
    I2D_REQUIRE(!state.empty());
    step(world, 5);
    for (size_t length = 0; length < state.size(); length += 97) {
        const uint64_t hash = i2d_world_get_state_hash(world);
        I2D_CHECK(i2d_world_restore_state(world, state.data(), length) == I2D_ERR_INVALID_SNAPSHOT);
        I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    }
    for (size_t at = 0; at < state.size(); at += 13) {
        Bytes changed = state;
        changed[at] ^= 0x04;
        const uint64_t hash = i2d_world_get_state_hash(world);
        I2D_CHECK(i2d_world_restore_state(world, changed.data(), changed.size()) == I2D_ERR_INVALID_SNAPSHOT);
        I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    }
    // Another world of the same scene: not this one.
    const i2d_world_id twin = det::mixed_scene(i2d_default_world_def());
    step(twin, 20);
    I2D_CHECK(i2d_world_restore_state(twin, state.data(), state.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(std::string(i2d_last_error_message()).find("another world") != std::string::npos);
    // A full snapshot is not a state, nor the other way round.
    const Bytes snapshot = save(world);
    I2D_CHECK(i2d_world_restore_state(world, snapshot.data(), snapshot.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(i2d_world_restore_snapshot(world, state.data(), state.size()) == I2D_ERR_INVALID_SNAPSHOT);
    // Still good until the structure changes.
    I2D_CHECK(i2d_world_restore_state(world, state.data(), state.size()) == I2D_OK);
    const i2d_body_id added = det::add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{0, 30});
    I2D_CHECK(!I2D_IS_NULL(added));
    const uint64_t hash = i2d_world_get_state_hash(world);
    I2D_CHECK(i2d_world_restore_state(world, state.data(), state.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(std::string(i2d_last_error_message()).find("structure changed") != std::string::npos);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    i2d_world_destroy(twin);
    i2d_world_destroy(world);
}
