// SPDX-License-Identifier: MIT
// Snapshots whose checksum was made to match after their bytes were changed: what the
// checksum cannot catch, the load's checks must. Each such snapshot is refused with a
// message, or makes a world that steps (under I2D_VALIDATE, every step checks the world's
// invariants, so a world the checks let through that breaks one aborts the test). The
// settings a snapshot carries are held to the world def's ranges.
//
// The world is built through the C API (the unit tests link the C boundary), and the
// checksum is fixed with the library's own function, which the C API does not offer.
#include <impulse2d/impulse2d.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "check.h"
#include "core/checksum.hpp"
#include "dynamics/snapshot/snapshot_format.hpp"
#include "test_rng.hpp"

namespace {

using Bytes = std::vector<unsigned char>;

constexpr float time_step = 1.0f / 60.0f;

// A small world with one of most things: shapes of every kind, a chain, joints, a
// sensor, contacts, a sleeping body, disabled bodies (a moving one with a joint, a static
// one), whose shapes have no proxies.
i2d_world_id small_world() {
    const i2d_world_def wd = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&wd);
    i2d_body_def bd = i2d_default_body_def();
    const i2d_body_id ground = i2d_body_create(world, &bd);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(ground, &sd, 10.0f, 0.5f);
    const i2d_vec2 hills[] = {{-9, 3}, {-8, 2}, {-6, 2.5f}, {-4, 2}, {-3, 3}};
    i2d_chain_def cd = i2d_default_chain_def();
    cd.points = hills;
    cd.count = 5;
    i2d_chain_create(ground, &cd);
    i2d_shape_def sensor = sd;
    sensor.is_sensor = true;
    i2d_shape_create_offset_box(ground, &sensor, 1.0f, 1.0f, i2d_vec2{5, 2}, i2d_make_rot(0));
    bd.type = I2D_BODY_DYNAMIC;
    i2d_body_id bodies[6];
    for (int k = 0; k < 6; ++k) {
        bd.position = i2d_vec2{-6.0f + 2.0f * float(k), 1.0f + 0.6f * float(k % 3)};
        bodies[k] = i2d_body_create(world, &bd);
        const i2d_circle circle = {{0, 0}, 0.3f};
        switch (k % 3) {
            case 0: i2d_shape_create_circle(bodies[k], &sd, &circle); break;
            case 1: i2d_shape_create_capsule(bodies[k], &sd, i2d_vec2{-0.2f, 0}, i2d_vec2{0.2f, 0}, 0.2f); break;
            default: i2d_shape_create_box(bodies[k], &sd, 0.3f, 0.3f); break;
        }
    }
    i2d_revolute_joint_def rd = i2d_default_revolute_joint_def();
    rd.base.body_a = bodies[0];
    rd.base.body_b = bodies[1];
    rd.base.local_anchor_a = i2d_vec2{1, 0};
    i2d_joint_create_revolute(world, &rd);
    i2d_distance_joint_def dd = i2d_default_distance_joint_def();
    dd.base.body_a = bodies[3];
    dd.base.body_b = bodies[4];
    dd.length = 2.0f;
    i2d_joint_create_distance(world, &dd);
    bd.position = i2d_vec2{6, 4};
    bd.linear_velocity = i2d_vec2{1, 0};
    const i2d_body_id away = i2d_body_create(world, &bd);
    i2d_shape_create_box(away, &sd, 0.3f, 0.3f);
    rd.base.body_a = bodies[2];
    rd.base.body_b = away;
    i2d_joint_create_revolute(world, &rd);
    bd = i2d_default_body_def();
    bd.position = i2d_vec2{-2, 4};
    const i2d_body_id away_static = i2d_body_create(world, &bd);
    i2d_shape_create_box(away_static, &sd, 1.0f, 0.2f);
    for (int s = 0; s < 40; ++s) {
        if (s == 20) {
            i2d_body_disable(away);
            i2d_body_disable(away_static);
        }
        i2d_world_step(world, time_step, 4);
    }
    i2d_body_set_awake(bodies[5], false);
    return world;
}

Bytes save(i2d_world_id world) {
    Bytes bytes(i2d_world_get_snapshot_size(world));
    i2d_world_save_snapshot(world, bytes.data(), bytes.size(), nullptr);
    return bytes;
}

// The header's checksum made to match the payload again.
void fix_checksum(Bytes& bytes) {
    const uint64_t sum = i2d::checksum64(bytes.data() + i2d::snapshot_header_size, bytes.size() - i2d::snapshot_header_size);
    for (int i = 0; i < 8; ++i) {
        bytes[24 + std::size_t(i)] = (unsigned char)(sum >> (8 * i));
    }
}

// Snapshot values are little-endian on every platform.
uint32_t read_u32(const Bytes& bytes, std::size_t at) {
    return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 | uint32_t(bytes[at + 3]) << 24;
}

void write_u32(Bytes& bytes, std::size_t at, uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) {
        bytes[at + i] = (unsigned char)(value >> (8 * i));
    }
}

}  // namespace

// Bytes changed at random (1 to 4 of them, to random values or to values an index field
// trips on: -1, 0, a large count) in a payload whose checksum is then fixed: refused, or
// stepped without a broken invariant.
I2D_TEST(unit_snapshot_changed_behind_its_checksum_is_refused_or_steps) {
    const i2d_world_id world = small_world();
    const Bytes good = save(world);
    I2D_REQUIRE(good.size() > i2d::snapshot_header_size + 64);
    TestRng rng(4242);
    int refused = 0, stepped = 0;
    const unsigned char tricky[] = {0x00, 0xff, 0x7f, 0x80, 0x01, 0x10};
    for (int trial = 0; trial < 3000; ++trial) {
        Bytes changed = good;
        const int bytes = 1 + int(rng.below(4));
        for (int k = 0; k < bytes; ++k) {
            const std::size_t at = i2d::snapshot_header_size + std::size_t(rng.below(int32_t(good.size() - i2d::snapshot_header_size)));
            changed[at] = rng.below(2) ? (unsigned char)rng.below(256) : tricky[rng.below(sizeof tricky)];
        }
        fix_checksum(changed);
        const i2d_world_id loaded = i2d_world_create_from_snapshot(changed.data(), changed.size(), nullptr);
        if (I2D_IS_NULL(loaded)) {
            I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_SNAPSHOT && i2d_last_error_message()[0] != '\0');
            ++refused;
            continue;
        }
        for (int s = 0; s < 3; ++s) {
            i2d_world_step(loaded, time_step, 4);
        }
        i2d_world_destroy(loaded);
        ++stepped;
    }
    fprintf(stderr, "    3000 changed snapshots: %d refused, %d stepped\n", refused, stepped);
    I2D_CHECK(refused > 0 && stepped > 0);
    i2d_world_destroy(world);
}

// Settings the world def would refuse are refused in a snapshot too: the contact
// stiffness is the fourth float of the settings section, made negative.
I2D_TEST(unit_snapshot_settings_out_of_range_are_refused) {
    const i2d_world_id world = small_world();
    Bytes bad = save(world);
    // Header, then the settings section's tag and size, gravity (2 floats), slop, hertz.
    const std::size_t hertz_at = i2d::snapshot_header_size + 4 + 8 + 4 * 3;
    const float negative = -5.0f;
    std::memcpy(&bad[hertz_at], &negative, sizeof negative);
    fix_checksum(bad);
    const uint64_t hash = i2d_world_get_state_hash(world);
    I2D_CHECK(i2d_world_restore_snapshot(world, bad.data(), bad.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "contact_hertz") != nullptr);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    I2D_CHECK(I2D_IS_NULL(i2d_world_create_from_snapshot(bad.data(), bad.size(), nullptr)));
    i2d_world_destroy(world);
}

// The checksum tells every single-byte change for certain, and sees lengths.
I2D_TEST(unit_checksum_changes_with_every_byte_and_the_length) {
    Bytes data(1000);
    for (std::size_t k = 0; k < data.size(); ++k) {
        data[k] = (unsigned char)(k * 37 + 11);
    }
    for (const std::size_t size : {std::size_t(0), std::size_t(7), std::size_t(31), std::size_t(33), data.size()}) {
        const uint64_t sum = i2d::checksum64(data.data(), size);
        for (std::size_t at = 0; at < size; ++at) {
            for (const unsigned char flip : {0x01, 0x80, 0xff}) {
                Bytes changed(data.begin(), data.begin() + std::ptrdiff_t(size));
                changed[at] ^= flip;
                I2D_CHECK(i2d::checksum64(changed.data(), size) != sum);
            }
        }
        if (size > 0) {
            I2D_CHECK(i2d::checksum64(data.data(), size - 1) != sum);
        }
    }
    const Bytes zeros(64, 0);
    I2D_CHECK(i2d::checksum64(zeros.data(), 32) != i2d::checksum64(zeros.data(), 33));
}

namespace {

// A world whose values are each unique as bits, so a test finds one in a snapshot's
// bytes: a circle of radius 0.4321 m and density 2.718 kg/m^2 hinged to a box (which
// carries the smallest box a call makes), its angle limited to [-0.123, 0.456] rad.
i2d_world_id world_of_distinct_values() {
    const i2d_world_def wd = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&wd);
    i2d_body_def bd = i2d_default_body_def();
    bd.type = I2D_BODY_DYNAMIC;
    const i2d_body_id box = i2d_body_create(world, &bd);
    bd.position = i2d_vec2{1.5f, 0.0f};
    const i2d_body_id ball = i2d_body_create(world, &bd);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(box, &sd, 0.5f, 0.5f);
    i2d_shape_create_offset_box(box, &sd, 1.0e-4f, 1.0e-4f, i2d_vec2{0.4f, 0.4f}, i2d_make_rot(0));  // smallest
    sd.density = 2.718f;
    const i2d_circle circle = {{0, 0}, 0.4321f};
    i2d_shape_create_circle(ball, &sd, &circle);
    i2d_revolute_joint_def rd = i2d_default_revolute_joint_def();
    rd.base.body_a = box;
    rd.base.body_b = ball;
    rd.base.local_anchor_a = i2d_vec2{0.75f, 0.0f};
    rd.base.local_anchor_b = i2d_vec2{-0.75f, 0.0f};
    rd.enable_limit = true;
    rd.lower_angle = -0.123f;
    rd.upper_angle = 0.456f;
    i2d_joint_create_revolute(world, &rd);
    i2d_world_step(world, time_step, 4);
    return world;
}

// The snapshot with every float of value `from` set to `to`, its checksum fixed; false
// when `from` is not in it.
bool replace_float(Bytes& bytes, float from, float to) {
    bool found = false;
    for (std::size_t at = i2d::snapshot_header_size; at + sizeof(float) <= bytes.size(); ++at) {
        if (std::memcmp(&bytes[at], &from, sizeof from) == 0) {
            std::memcpy(&bytes[at], &to, sizeof to);
            found = true;
        }
    }
    fix_checksum(bytes);
    return found;
}

}  // namespace

// Values the calls that make and change objects would refuse are refused in a snapshot
// too, with a message naming the field, and the world keeps its state: a negative radius,
// a density its body's mass does not follow from, joint limits out of order.
I2D_TEST(unit_snapshot_values_no_call_could_set_are_refused) {
    struct Change {
        float from, to;
        const char* message;
    };
    const Change changes[] = {
        {0.4321f, -0.4321f, "geometry"},          // circle radius
        {2.718f, 5.0f, "not its shapes'"},        // density, mass unchanged
        {2.718f, -1.0f, "density"},               // density out of range
        {-0.123f, 0.9f, "lower_angle"},           // lower above upper
        {0.456f, 3.13f, "upper_angle"},           // beyond the revolute limit
        {-0.75f, 2.0e5f, "local_anchor_b"},       // anchor beyond a body's reach
    };
    const i2d_world_id world = world_of_distinct_values();
    const Bytes good = save(world);
    const uint64_t hash = i2d_world_get_state_hash(world);
    for (const Change& change : changes) {
        Bytes bad = good;
        I2D_REQUIRE(replace_float(bad, change.from, change.to));
        I2D_CHECK(i2d_world_restore_snapshot(world, bad.data(), bad.size()) == I2D_ERR_INVALID_SNAPSHOT);
        I2D_CHECK(std::strstr(i2d_last_error_message(), change.message) != nullptr);
        I2D_CHECK(i2d_world_get_state_hash(world) == hash);
        I2D_CHECK(I2D_IS_NULL(i2d_world_create_from_snapshot(bad.data(), bad.size(), nullptr)));
    }
    I2D_CHECK(i2d_world_restore_snapshot(world, good.data(), good.size()) == I2D_OK);  // the smallest box too
    i2d_world_destroy(world);
}

namespace {

// Where the content of the section tagged `tag` starts (after its tag and its size).
std::size_t section_content_at(const Bytes& bytes, uint32_t tag) {
    std::size_t at = i2d::snapshot_header_size;
    while (at + 12 <= bytes.size() && read_u32(bytes, at) != tag) {
        at += 12 + std::size_t(read_u32(bytes, at + 4));  // sections are far below 4 GB
    }
    return at + 12;
}

// Where the islands section's first island with a link keeps its link count: the section
// holds the island pool (a slot count, then per slot its generation, its live byte and,
// if live, the island's six int32 fields, link_count the fourth). Returns 0 when none.
std::size_t linked_island_count_at(const Bytes& bytes) {
    std::size_t at = section_content_at(bytes, i2d::islands_section);
    const int32_t slots = int32_t(read_u32(bytes, at));
    at += 4;
    for (int32_t slot = 0; slot < slots && at < bytes.size(); ++slot) {
        const bool live = bytes[at + 2] != 0;
        at += 3;
        if (live) {
            if (read_u32(bytes, at + 12) > 0) {
                return at + 12;
            }
            at += 6 * 4;
        }
    }
    return 0;
}

}  // namespace

// An island's link count one short of its joints and contacts would go below zero as
// they end; one that says it lost links past the cap would overflow. Both are refused,
// and the world they were restored into is as it was.
I2D_TEST(unit_snapshot_island_link_counts_must_match_the_links) {
    const i2d_world_id world = small_world();
    const Bytes good = save(world);
    const std::size_t count_at = linked_island_count_at(good);
    I2D_REQUIRE(count_at != 0);
    const uint64_t hash = i2d_world_get_state_hash(world);

    Bytes short_count = good;
    write_u32(short_count, count_at, read_u32(good, count_at) - 1);
    fix_checksum(short_count);
    I2D_CHECK(i2d_world_restore_snapshot(world, short_count.data(), short_count.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "link count") != nullptr);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);

    Bytes too_many_lost = good;
    write_u32(too_many_lost, count_at + 4, 0x7fffffffu);
    fix_checksum(too_many_lost);
    I2D_CHECK(I2D_IS_NULL(i2d_world_create_from_snapshot(too_many_lost.data(), too_many_lost.size(), nullptr)));
    I2D_CHECK(std::strstr(i2d_last_error_message(), "island") != nullptr);

    I2D_CHECK(i2d_world_restore_snapshot(world, good.data(), good.size()) == I2D_OK);
    i2d_world_destroy(world);
}

// A rollback state is held to the calls' rules as a snapshot is, unless the world saved
// it itself: the ground (the first body in the state's body section: a count, then each
// body's transform, centre and linear velocity before its angular velocity) made to turn
// is refused, and the world keeps its state.
I2D_TEST(unit_rollback_state_values_no_call_could_set_are_refused) {
    constexpr std::size_t angular_velocity_at = 4 + 16 + 8 + 8;
    const i2d_world_id world = small_world();
    Bytes state(i2d_world_get_state_size(world));
    I2D_REQUIRE(i2d_world_save_state(world, state.data(), state.size(), nullptr) == I2D_OK);
    const std::size_t at = section_content_at(state, i2d::dynamic_bodies_section) + angular_velocity_at;
    I2D_REQUIRE(at + 4 <= state.size());
    float spin = 0.0f;
    std::memcpy(&spin, &state[at], sizeof spin);
    I2D_REQUIRE(spin == 0.0f);
    spin = 1.0f;
    std::memcpy(&state[at], &spin, sizeof spin);
    fix_checksum(state);
    const uint64_t hash = i2d_world_get_state_hash(world);
    I2D_CHECK(i2d_world_restore_state(world, state.data(), state.size()) == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "rollback state refused") != nullptr);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "static and moves") != nullptr);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    i2d_world_destroy(world);
}
