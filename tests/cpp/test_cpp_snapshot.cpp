// SPDX-License-Identifier: MIT
// The C++17 wrappers of snapshots and rollback states: a world brought back from bytes
// steps on to the same state hashes as a world that was never saved; refused bytes throw
// (or fill the Status) and change nothing.
#include <impulse2d/impulse2d.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "check.h"

namespace {

constexpr int steps_before = 40;
constexpr int steps_after = 30;

// A pile of boxes and circles falling onto a ground; the dynamic bodies.
std::vector<impulse2d::Body> build(impulse2d::World& world) {
    impulse2d::Body ground = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, -1.0f}));
    ground.create_box(20.0f, 1.0f);
    std::vector<impulse2d::Body> bodies;
    for (int i = 0; i < 12; ++i) {
        const i2d_vec2 at = {static_cast<float>(i % 4) * 1.1f - 1.6f, 0.6f + 1.1f * static_cast<float>(i / 4)};
        const float angle = 0.1f * static_cast<float>(i % 5);
        impulse2d::Body body = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, at, angle));
        if (i % 2 != 0) {
            body.create_circle(0.45f);
        } else {
            body.create_box(0.45f, 0.45f);
        }
        bodies.push_back(body);
    }
    return bodies;
}

std::vector<uint64_t> step(impulse2d::World& world, int steps) {
    std::vector<uint64_t> hashes;
    for (int s = 0; s < steps; ++s) {
        world.step(1.0f / 60.0f, 4);
        hashes.push_back(world.state_hash());
    }
    return hashes;
}

// The hashes a world of the scene takes after the save point, never saved.
const std::vector<uint64_t>& reference_after() {
    static const std::vector<uint64_t> hashes = [] {
        impulse2d::World world;
        build(world);
        step(world, steps_before);
        return step(world, steps_after);
    }();
    return hashes;
}

}  // namespace

I2D_TEST(cpp_snapshot_restored_and_new_worlds_go_on_as_the_world_never_saved) {
    const std::vector<uint64_t>& reference = reference_after();
    I2D_REQUIRE(reference.size() == steps_after && reference.front() != reference.back());
    impulse2d::World world;
    std::vector<impulse2d::Body> bodies = build(world);
    step(world, steps_before);
    const uint64_t at_save = world.state_hash();
    const std::vector<std::uint8_t> snapshot = world.save_snapshot();
    I2D_REQUIRE(snapshot.size() == i2d_world_get_snapshot_size(world.id()));

    i2d_world_def runtime = i2d_default_world_def();
    runtime.worker_count = 2;
    impulse2d::World copy = impulse2d::World::from_snapshot(snapshot, runtime);
    I2D_CHECK(copy.valid() && copy.id().bits != world.id().bits && copy.state_hash() == at_save);
    const impulse2d::Body found = bodies[3].in(copy);
    I2D_CHECK(found.valid() && found != bodies[3]);
    I2D_CHECK(found.position().x == bodies[3].position().x && found.position().y == bodies[3].position().y);
    I2D_CHECK(bodies[3].shapes()[0].in(copy) == found.shapes()[0]);
    I2D_CHECK(step(copy, steps_after) == reference);

    step(world, 25);  // somewhere else
    const impulse2d::Body late = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 20.0f}));
    world.restore_snapshot(snapshot);
    I2D_CHECK(world.state_hash() == at_save && !late.valid() && bodies[3].valid());
    I2D_CHECK(world.save_snapshot() == snapshot);
    I2D_CHECK(step(world, steps_after) == reference);
    I2D_CHECK(!late.in(copy).valid());  // the copy never had it
}

I2D_TEST(cpp_snapshot_refused_bytes_throw_or_fill_the_status_and_change_nothing) {
    impulse2d::World world;
    build(world);
    step(world, steps_before);
    std::vector<std::uint8_t> bad = world.save_snapshot();
    bad[bad.size() / 2] ^= 0x10;
    const uint64_t hash = world.state_hash();
    try {
        world.restore_snapshot(bad);
        I2D_CHECK(false);
    } catch (const impulse2d::Error& e) {
        I2D_CHECK(e.status() == I2D_ERR_INVALID_SNAPSHOT);
        I2D_CHECK(std::string(e.what()).find("i2d_world_restore_snapshot: snapshot refused") == 0);
    }
    I2D_CHECK(world.state_hash() == hash);

    impulse2d::Status status;
    const impulse2d::World none = impulse2d::World::from_snapshot(bad, i2d_default_world_def(), status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_SNAPSHOT && !none.valid() && none.id().bits == 0);
    I2D_CHECK(status.message.find("snapshot refused") != std::string::npos);
    bad.resize(bad.size() / 3);
    world.restore_snapshot(bad, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_SNAPSHOT && world.state_hash() == hash);
    world.restore_snapshot(world.save_snapshot(), status);
    I2D_CHECK(status.ok() && world.state_hash() == hash);
}

I2D_TEST(cpp_snapshot_rollback_eight_frames_and_simulate_again) {
    impulse2d::World world;
    std::vector<impulse2d::Body> bodies = build(world);
    std::vector<std::vector<std::uint8_t>> ring(8);
    std::vector<uint64_t> hashes;
    for (int frame = 0; frame < 20; ++frame) {
        ring[frame % 8] = world.save_state();
        hashes.push_back(world.state_hash());
        world.step(1.0f / 60.0f, 4);
    }
    const uint64_t at_20 = world.state_hash();
    world.restore_state(ring[12 % 8]);
    I2D_CHECK(world.state_hash() == hashes[12]);
    bodies[0].apply_linear_impulse({5.0f, 0.0f}, bodies[0].world_center_of_mass());  // a late input
    I2D_CHECK(step(world, 8).back() != at_20);
    world.restore_state(ring[12 % 8]);
    I2D_CHECK(step(world, 8).back() == at_20);

    impulse2d::World other;
    build(other);
    const uint64_t other_hash = other.state_hash();
    impulse2d::Status status;
    other.restore_state(ring[0], status);  // the same scene at frame 0, but another world's state
    I2D_CHECK(status.code == I2D_ERR_INVALID_SNAPSHOT && other.state_hash() == other_hash);
    I2D_CHECK(other_hash == hashes[0]);
    world.create_body();
    try {
        world.restore_state(ring[0]);  // saved before the world gained a body
        I2D_CHECK(false);
    } catch (const impulse2d::Error& e) {
        I2D_CHECK(e.status() == I2D_ERR_INVALID_SNAPSHOT);
    }
}
