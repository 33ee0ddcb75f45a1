// SPDX-License-Identifier: MIT
// The snapshot fuzzer: snapshots and rollback states of a small world, changed byte by
// byte behind a checksum made to match, restored (in place and as a new world) and
// stepped. Any crash, sanitizer report, broken invariant (I2D_VALIDATE) or refused
// buffer that changed the world fails.
//
// The checksum is fixed after every change because a changed byte is otherwise refused at
// once (det_snapshot_refusals_leave_the_world_as_it_was covers that), and the fuzzer
// should reach the checks behind it: the loaded world's lists, links and indices.
//
// Input: a mode byte, then the change.
//   mode % 4 == 0: patches (3 bytes of offset into the payload, 1 byte of value each) to the
//                  small world's snapshot, restored into a copy of the world and made into
//                  a new world;
//   mode % 4 == 1: the same patches to the small world's rollback state, restored into it;
//   mode % 4 == 2: the rest of the input is a whole snapshot (its header made valid);
//   mode % 4 == 3: the patches to a recording of the small world (a body made, forces,
//                  a joint changed, steps), each record's checksum fixed, then replayed
//                  to its end: a refused record stops the replay, nothing crashes.
#include <impulse2d/impulse2d.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/checksum.hpp"
#include "dynamics/recording/recording_format.hpp"
#include "dynamics/snapshot/snapshot_format.hpp"

namespace {

using Bytes = std::vector<unsigned char>;

constexpr float time_step = 1.0f / 60.0f;
constexpr int steps_after = 3;

void fail(const char* what) {
    std::fprintf(stderr, "fuzz_snapshot: %s\n", what);
    std::abort();
}

// A small world with shapes of every kind, a chain, joints, a sensor and contacts.
i2d_world_id small_world() {
    const i2d_world_def wd = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&wd);
    i2d_body_def bd = i2d_default_body_def();
    const i2d_body_id ground = i2d_body_create(world, &bd);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(ground, &sd, 6.0f, 0.5f);
    const i2d_vec2 hills[] = {{-5, 2}, {-4, 1.5f}, {-2, 2}, {-1, 1.5f}, {0, 2}};
    i2d_chain_def cd = i2d_default_chain_def();
    cd.points = hills;
    cd.count = 5;
    i2d_chain_create(ground, &cd);
    i2d_shape_def sensor = sd;
    sensor.is_sensor = true;
    i2d_shape_create_offset_box(ground, &sensor, 1.0f, 1.0f, i2d_vec2{3, 1.5f}, i2d_make_rot(0));
    bd.type = I2D_BODY_DYNAMIC;
    i2d_body_id bodies[4];
    for (int k = 0; k < 4; ++k) {
        bd.position = i2d_vec2{-3.0f + 2.0f * float(k), 1.0f};
        bodies[k] = i2d_body_create(world, &bd);
        const i2d_circle circle = {{0, 0}, 0.3f};
        if (k % 2 == 0) {
            i2d_shape_create_circle(bodies[k], &sd, &circle);
        } else {
            i2d_shape_create_capsule(bodies[k], &sd, i2d_vec2{-0.2f, 0}, i2d_vec2{0.2f, 0}, 0.2f);
        }
    }
    i2d_revolute_joint_def rd = i2d_default_revolute_joint_def();
    rd.base.body_a = bodies[0];
    rd.base.body_b = bodies[1];
    rd.base.local_anchor_a = i2d_vec2{1, 0};
    i2d_joint_create_revolute(world, &rd);
    for (int s = 0; s < 20; ++s) {
        i2d_world_step(world, time_step, 4);
    }
    return world;
}

Bytes saved(i2d_world_id world, bool state) {
    Bytes bytes(state ? i2d_world_get_state_size(world) : i2d_world_get_snapshot_size(world));
    const i2d_status status = state ? i2d_world_save_state(world, bytes.data(), bytes.size(), nullptr)
                                    : i2d_world_save_snapshot(world, bytes.data(), bytes.size(), nullptr);
    if (status != I2D_OK) {
        fail("a world could not save itself");
    }
    return bytes;
}

// The header made to describe the payload as it now is.
void fix_header(Bytes& bytes) {
    const std::size_t payload = bytes.size() - i2d::snapshot_header_size;
    const uint64_t sum = i2d::checksum64(bytes.data() + i2d::snapshot_header_size, payload);
    for (int i = 0; i < 8; ++i) {
        bytes[16 + std::size_t(i)] = (unsigned char)(uint64_t(payload) >> (8 * i));
        bytes[24 + std::size_t(i)] = (unsigned char)(sum >> (8 * i));
    }
}

void apply_patches(Bytes& bytes, const uint8_t* data, std::size_t size) {
    const std::size_t payload = bytes.size() - i2d::snapshot_header_size;
    for (std::size_t k = 0; k + 4 <= size; k += 4) {
        const std::size_t offset = (std::size_t(data[k]) << 16 | std::size_t(data[k + 1]) << 8 | data[k + 2]) % payload;
        bytes[i2d::snapshot_header_size + offset] = data[k + 3];
    }
    fix_header(bytes);
}

// A refused restore leaves the world as it was; an accepted one makes a world that steps.
void restore_and_step(i2d_world_id world, const Bytes& bytes, bool state) {
    const uint64_t hash = i2d_world_get_state_hash(world);
    const Bytes before = saved(world, false);
    const i2d_status status = state ? i2d_world_restore_state(world, bytes.data(), bytes.size())
                                    : i2d_world_restore_snapshot(world, bytes.data(), bytes.size());
    if (status != I2D_OK) {
        if (status != I2D_ERR_INVALID_SNAPSHOT || i2d_world_get_state_hash(world) != hash || saved(world, false) != before) {
            fail("a refused restore changed the world, or answered another status");
        }
        return;
    }
    for (int s = 0; s < steps_after; ++s) {
        i2d_world_step(world, time_step, 4);
    }
}

void append(const void* bytes, std::size_t size, void* context) {
    Bytes& out = *static_cast<Bytes*>(context);
    out.insert(out.end(), static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
}

// A short session of the small world: every kind of argument a replay reads.
Bytes recorded_session(i2d_world_id original) {
    Bytes out;
    const Bytes start = saved(original, false);
    const i2d_world_id world = i2d_world_create_from_snapshot(start.data(), start.size(), nullptr);
    i2d_world_start_recording(world, append, &out);
    i2d_body_def bd = i2d_default_body_def();
    bd.type = I2D_BODY_DYNAMIC;
    bd.position = i2d_vec2{1, 4};
    const i2d_body_id body = i2d_body_create(world, &bd);
    bd.position = i2d_vec2{2, 4};
    const i2d_body_id other = i2d_body_create(world, &bd);
    const i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(body, &sd, 0.3f, 0.2f);
    const i2d_circle ball = {{0, 0}, 0.25f};
    i2d_shape_create_circle(other, &sd, &ball);
    i2d_distance_joint_def dd = i2d_default_distance_joint_def();
    dd.base.body_a = body;
    dd.base.body_b = other;
    dd.length = 1.0f;
    const i2d_joint_id joint = i2d_joint_create_distance(world, &dd);
    for (int s = 0; s < 6; ++s) {
        i2d_body_apply_linear_impulse(body, i2d_vec2{0.3f, 0}, i2d_vec2{1, 4}, true);
        i2d_body_set_angular_velocity(other, 0.5f);
        i2d_distance_joint_set_length(joint, 1.0f + 0.1f * float(s));
        i2d_world_step(world, time_step, 4);
    }
    i2d_world_stop_recording(world);
    i2d_world_destroy(world);
    return out;
}

// Each record's size check and checksum made to match what it now holds.
void fix_records(Bytes& recording) {
    std::size_t at = i2d::recording_header_size;
    while (recording.size() - at >= i2d::record_header_size) {
        const std::size_t payload = std::size_t(recording[at + 5]) | std::size_t(recording[at + 6]) << 8 |
                                    std::size_t(recording[at + 7]) << 16 | std::size_t(recording[at + 8]) << 24;
        if (payload > recording.size() - at - i2d::record_header_size) {
            return;
        }
        i2d::seal_record(recording.data() + at, payload);
        at += i2d::record_header_size + payload;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    static const i2d_world_id original = small_world();
    static const Bytes snapshot = saved(original, false);
    if (size == 0) {
        return 0;
    }
    const int mode = data[0] % 4;
    if (mode == 0) {
        Bytes changed = snapshot;
        apply_patches(changed, data + 1, size - 1);
        const i2d_world_id copy = i2d_world_create_from_snapshot(snapshot.data(), snapshot.size(), nullptr);
        restore_and_step(copy, changed, false);
        i2d_world_destroy(copy);
        const i2d_world_id made = i2d_world_create_from_snapshot(changed.data(), changed.size(), nullptr);
        if (!I2D_IS_NULL(made)) {
            restore_and_step(made, saved(made, false), false);  // its own snapshot round trips
            i2d_world_destroy(made);
        }
    } else if (mode == 1) {
        const i2d_world_id copy = i2d_world_create_from_snapshot(snapshot.data(), snapshot.size(), nullptr);
        Bytes state = saved(copy, true);
        apply_patches(state, data + 1, size - 1);
        restore_and_step(copy, state, true);
        i2d_world_destroy(copy);
    } else if (mode == 3) {
        static const Bytes recording = recorded_session(original);
        Bytes changed = recording;
        for (std::size_t k = 1; k + 4 <= size; k += 4) {
            const std::size_t offset = (std::size_t(data[k]) << 16 | std::size_t(data[k + 1]) << 8 | data[k + 2]) %
                                       (changed.size() - i2d::recording_header_size);
            changed[i2d::recording_header_size + offset] = data[k + 3];
        }
        fix_records(changed);
        const i2d_replay_id replay = i2d_replay_open(changed.data(), changed.size(), nullptr);
        if (replay.bits != 0) {
            i2d_replay_step(replay, 100);
            i2d_replay_seek(replay, 2);
            i2d_replay_close(replay);
        }
    } else if (size - 1 >= i2d::snapshot_header_size) {
        Bytes raw(data + 1, data + size);
        std::memcpy(raw.data(), snapshot.data(), 16);  // the magic, version and kind of a snapshot
        std::memset(raw.data() + 32, 0, 16);
        fix_header(raw);
        const i2d_world_id made = i2d_world_create_from_snapshot(raw.data(), raw.size(), nullptr);
        if (!I2D_IS_NULL(made)) {
            for (int s = 0; s < steps_after; ++s) {
                i2d_world_step(made, time_step, 4);
            }
            i2d_world_destroy(made);
        }
    }
    return 0;
}
