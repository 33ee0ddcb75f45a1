// SPDX-License-Identifier: MIT
// Recording and replay: a recorded session (creations, destructions, forces, setters,
// bulk writes, a rollback, an origin shift) replays with every step's hash as recorded, forwards and after
// seeking back; a replay whose world is nudged reports the step where it diverges; a
// recording changed in any record, of another format or not a recording at all is
// refused, and one cut short mid-record replays the whole records it holds.
#include <impulse2d/impulse2d.h>

#include <cstring>
#include <vector>

#include "check.h"
#include "det_scenes.hpp"

namespace {

using Bytes = std::vector<unsigned char>;

void append(const void* bytes, size_t size, void* context) {
    Bytes& out = *static_cast<Bytes*>(context);
    const auto* b = static_cast<const unsigned char*>(bytes);
    out.insert(out.end(), b, b + size);
}

// Steps of the recorded session, and what happens at some of them.
constexpr int session_steps = 150;

struct Session {
    Bytes recording;
    uint64_t final_hash = 0;
    uint64_t hash_at_step_60 = 0;
};

void step(i2d_world_id world) { i2d_world_step(world, det::time_step, det::substeps); }

// The runtime API's calls (issue 40): a body's, a shape's and the world's settings.
void record_runtime_settings(i2d_world_id world, const std::vector<i2d_body_id>& made) {
    const i2d_body_id crate = made[5];
    I2D_CHECK_STATUS(i2d_body_set_mass_data(crate, i2d_mass_data{3.0f, i2d_vec2{0.1f, 0}, 0.4f}), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_gravity_scale(crate, 0.5f), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_linear_damping(crate, 0.2f), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_angular_damping(crate, 0.3f), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_sleep_threshold(crate, 0.1f), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_bullet(crate, true), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_enable_sleep(crate, false), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_fixed_rotation(crate, true), I2D_OK);
    const i2d_transform ahead{i2d_vec2{10.5f, 10}, i2d_make_rot(0.1f)};
    I2D_CHECK_STATUS(i2d_body_set_target_transform(made[4], ahead, det::time_step), I2D_OK);
    i2d_shape_id shapes[1];
    i2d_body_get_shapes(made[3], shapes, 1);
    const i2d_circle grown{i2d_vec2{0, 0}, 0.4f};
    I2D_CHECK_STATUS(i2d_shape_set_circle(shapes[0], &grown), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_set_density(shapes[0], 2.0f, true), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_set_material(shapes[0], i2d_surface_material{0.4f, 0.2f, 0.1f, 0.5f}), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_enable_hit_events(shapes[0], true), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_enable_contact_events(shapes[0], false), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_enable_sensor_events(shapes[0], false), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_enable_sleeping(world, false), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_enable_continuous(world, false), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_set_contact_tuning(world, 40.0f, 8.0f, 2.0f), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_set_joint_tuning(world, 50.0f, 1.0f), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_set_restitution_threshold(world, 0.5f), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_set_hit_event_threshold(world, 2.0f), I2D_OK);
}

// The snapshot scene, recorded through a session that touches every recorded call kind.
const Session& session() {
    static const Session recorded = [] {
        Session s;
        const i2d_world_def wd = i2d_default_world_def();
        const i2d_world_id world = det::snapshot_scene(wd);
        for (int k = 0; k < 20; ++k) {
            step(world);
        }
        i2d_world_start_recording(world, append, &s.recording);
        const i2d_shape_def plain = det::material(0.5f, 0.1f);
        std::vector<i2d_body_id> made;
        Bytes rollback;
        for (int k = 1; k <= session_steps; ++k) {
            if (k % 10 == 1) {  // a crate and a capsule dropped, pushed and spun
                const i2d_vec2 at = {-4.0f + 0.1f * float(k % 7), 20};
                const i2d_body_id crate = det::add_body(world, I2D_BODY_DYNAMIC, at);
                det::add_mixed_shape(crate, k % 5, &plain);
                i2d_body_apply_linear_impulse(crate, i2d_vec2{0.5f, 0}, i2d_vec2{-4, 20.1f}, true);
                i2d_body_apply_torque(crate, 3.0f, true);
                made.push_back(crate);
            }
            if (k % 10 == 5) {
                i2d_body_apply_force(made.back(), i2d_vec2{4, 0}, i2d_vec2{-4, 19}, true);
                i2d_body_apply_force_to_center(made.back(), i2d_vec2{0, 3}, true);
                i2d_body_apply_angular_impulse(made.back(), 0.2f, true);
                i2d_body_set_angular_velocity(made.front(), 1.5f);
            }
            if (k == 30) {  // settings and materials
                i2d_world_set_gravity(world, i2d_vec2{0.5f, -9.0f});
                const i2d_body_id first = made.front();
                i2d_body_set_linear_velocity(first, i2d_vec2{1, 2});
                i2d_body_set_user_data(first, reinterpret_cast<void*>(uintptr_t(0x1234)));
                i2d_filter filter = i2d_default_filter();
                filter.group_index = -3;
                i2d_shape_id shapes[1];
                i2d_body_get_shapes(first, shapes, 1);
                i2d_shape_set_filter(shapes[0], filter);
                i2d_shape_set_friction(shapes[0], 0.9f);
                i2d_shape_set_restitution(shapes[0], 0.3f);
            }
            if (k == 40) {  // a joint made, changed and destroyed; a chain made and destroyed
                i2d_revolute_joint_def hinge = i2d_default_revolute_joint_def();
                hinge.base.body_a = made[0];
                hinge.base.body_b = made[1];
                hinge.base.local_anchor_a = i2d_vec2{0.5f, 0};
                hinge.enable_motor = true, hinge.max_motor_torque = 4.0f;
                const i2d_joint_id joint = i2d_joint_create_revolute(world, &hinge);
                i2d_revolute_joint_set_motor_speed(joint, -2.0f);
                i2d_joint_wake_bodies(joint);
                const i2d_body_id ledge = det::add_body(world, I2D_BODY_STATIC, i2d_vec2{10, 10});
                const i2d_vec2 points[] = {{-2, 0}, {-1, 0}, {1, 0.2f}, {2, 0}};
                i2d_chain_def chain = i2d_default_chain_def();
                chain.points = points;
                chain.count = 4;
                const i2d_chain_id made_chain = i2d_chain_create(ledge, &chain);
                i2d_chain_destroy(made_chain);
                made.push_back(ledge);
            }
            if (k == 50) {  // bulk writes, a type change, sleep and wake
                const i2d_body_id bodies[2] = {made[2], made[3]};
                const i2d_transform to[2] = {{{3, 15}, i2d_make_rot(0.3f)}, {{5, 15}, i2d_make_rot(-0.2f)}};
                i2d_world_set_body_transforms(world, bodies, 2, to);
                const i2d_vec2 linear[2] = {{0, -1}, {1, 0}};
                const float angular[2] = {0.5f, -0.5f};
                i2d_world_set_body_velocities(world, bodies, 2, linear, angular);
                i2d_body_set_type(made[4], I2D_BODY_KINEMATIC);
                i2d_body_set_awake(made[3], false);
                i2d_body_set_awake(made[3], true);
                i2d_shape_id shapes[1];
                i2d_body_get_shapes(made[2], shapes, 1);
                i2d_shape_destroy(shapes[0]);
                i2d_body_destroy(made[1]);  // takes the hinge with it
                rollback.resize(i2d_world_get_state_size(world));
                i2d_world_save_state(world, rollback.data(), rollback.size(), nullptr);
            }
            if (k == 55) {  // five steps undone and run again with other inputs
                i2d_world_restore_state(world, rollback.data(), rollback.size());
                i2d_body_apply_linear_impulse(made[2], i2d_vec2{0, 2}, i2d_vec2{3, 15}, true);
            }
            if (k == 70) {
                record_runtime_settings(world, made);
            }
            if (k == 80) {  // the shapes' mass again, and a polygon in place of the circle
                I2D_CHECK_STATUS(i2d_body_apply_mass_from_shapes(made[5]), I2D_OK);
                i2d_shape_id shapes[1];
                i2d_body_get_shapes(made[3], shapes, 1);
                const i2d_polygon box = i2d_make_box(0.3f, 0.2f);
                I2D_CHECK_STATUS(i2d_shape_set_polygon(shapes[0], &box), I2D_OK);
                I2D_CHECK_STATUS(i2d_world_enable_sleeping(world, true), I2D_OK);
            }
            if (k == 90) {  // the origin moved: replayed through i2d_world_shift_origin
                I2D_CHECK(i2d_world_shift_origin(world, i2d_vec2{300.0f, -120.0f}) == I2D_OK);
            }
            if (k == 95) {  // a crate and the kinematic ledge out of the world for ten steps
                I2D_CHECK_STATUS(i2d_body_disable(made[2]), I2D_OK);
                I2D_CHECK_STATUS(i2d_body_disable(made[4]), I2D_OK);
                const i2d_vec2 center = i2d_body_get_world_center_of_mass(made[2]);
                I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(made[2], i2d_vec2{1, 0}, center, false), I2D_OK);
            }
            if (k == 105) {
                I2D_CHECK_STATUS(i2d_body_enable(made[2]), I2D_OK);
                I2D_CHECK_STATUS(i2d_body_enable(made[4]), I2D_OK);
            }
            step(world);
            if (k == 60) {
                s.hash_at_step_60 = i2d_world_get_state_hash(world);
            }
        }
        i2d_world_stop_recording(world);
        step(world);  // not recorded
        s.final_hash = i2d_world_get_state_hash(world);
        i2d_world_destroy(world);
        return s;
    }();
    return recorded;
}

uint64_t replay_hash(i2d_replay_id replay) { return i2d_world_get_state_hash(i2d_replay_get_world(replay)); }

}  // namespace

I2D_TEST(det_replay_of_a_recorded_session_never_diverges) {
    const Session& s = session();
    const i2d_replay_id replay = i2d_replay_open(s.recording.data(), s.recording.size(), nullptr);
    I2D_REQUIRE(replay.bits != 0);
    I2D_CHECK(i2d_replay_get_step_count(replay) == session_steps);
    I2D_CHECK(i2d_replay_step(replay, 60) == 60);
    I2D_CHECK(replay_hash(replay) == s.hash_at_step_60);
    I2D_CHECK(i2d_replay_step(replay, 1000) == session_steps - 60);
    I2D_CHECK(i2d_replay_get_step(replay) == session_steps);
    I2D_CHECK(i2d_replay_get_divergent_step(replay) == -1);
    I2D_CHECK(i2d_replay_step(replay, 1) == 0);  // the end
    // Back to step 60 from the start's snapshot, and on to the end again.
    I2D_CHECK(i2d_replay_seek(replay, 60) == I2D_OK);
    I2D_CHECK(replay_hash(replay) == s.hash_at_step_60);
    I2D_CHECK(i2d_replay_seek(replay, session_steps) == I2D_OK);
    I2D_CHECK(i2d_replay_get_divergent_step(replay) == -1);
    I2D_CHECK(i2d_replay_seek(replay, session_steps + 1) == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_replay_close(replay) == I2D_OK);
    I2D_CHECK(i2d_replay_close(replay) == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_replay_get_step(replay) == 0 && i2d_last_status() == I2D_ERR_INVALID_HANDLE);
}

// A nudge to the replay's world after step 40 stands in for a build that computes
// differently from there: the replay names step 41.
I2D_TEST(det_replay_reports_the_step_where_the_world_diverges) {
    const Session& s = session();
    const i2d_replay_id replay = i2d_replay_open(s.recording.data(), s.recording.size(), nullptr);
    I2D_REQUIRE(replay.bits != 0);
    I2D_CHECK(i2d_replay_seek(replay, 40) == I2D_OK);
    I2D_CHECK(i2d_replay_get_divergent_step(replay) == -1);
    const i2d_world_id world = i2d_replay_get_world(replay);
    i2d_body_def bd = i2d_default_body_def();
    bd.type = I2D_BODY_DYNAMIC;
    bd.position = i2d_vec2{-40, 40};
    const i2d_body_id stray = i2d_body_create(world, &bd);
    const i2d_circle c = {{0, 0}, 0.1f};
    const i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_circle(stray, &sd, &c);
    I2D_CHECK(i2d_replay_step(replay, 100) == 1);  // stops at the divergence
    I2D_CHECK(i2d_replay_get_divergent_step(replay) == 41);
    i2d_replay_close(replay);
}

// Any changed byte is refused (each record carries a checksum), so is a recording of a
// newer format or none; a recording cut short replays the whole records it holds.
I2D_TEST(det_recording_refusals_and_a_cut_short_recording) {
    const Session& s = session();
    for (size_t at = 0; at < s.recording.size(); at += 997) {
        Bytes changed = s.recording;
        changed[at] ^= 0x10;
        const i2d_replay_id replay = i2d_replay_open(changed.data(), changed.size(), nullptr);
        I2D_CHECK(replay.bits == 0 && i2d_last_status() == I2D_ERR_INVALID_SNAPSHOT);
    }
    Bytes newer = s.recording;
    newer[8] = 0x7f;
    I2D_CHECK(i2d_replay_open(newer.data(), newer.size(), nullptr).bits == 0);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "newer") != nullptr);
    const char junk[] = "not a recording at all";
    I2D_CHECK(i2d_replay_open(junk, sizeof junk, nullptr).bits == 0);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(i2d_replay_open(nullptr, 16, nullptr).bits == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    const Bytes cut(s.recording.begin(), s.recording.end() - 5);
    const i2d_replay_id replay = i2d_replay_open(cut.data(), cut.size(), nullptr);
    I2D_REQUIRE(replay.bits != 0);
    I2D_CHECK(i2d_replay_get_step_count(replay) == session_steps - 1);
    I2D_CHECK(i2d_replay_step(replay, session_steps) == session_steps - 1);
    I2D_CHECK(i2d_replay_get_divergent_step(replay) == -1);
    i2d_replay_close(replay);
}

// Recording is refused without a writer and inside the world's callbacks, and a stopped
// recording takes nothing more.
I2D_TEST(det_recording_refuses_a_null_writer_and_stops) {
    const i2d_world_def wd = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&wd);
    I2D_CHECK(i2d_world_start_recording(world, nullptr, nullptr) == I2D_ERR_INVALID_ARGUMENT);
    Bytes out;
    I2D_CHECK(i2d_world_start_recording(world, append, &out) == I2D_OK);
    const size_t at_start = out.size();
    I2D_CHECK(at_start > 16);  // the header and the first snapshot
    step(world);
    I2D_CHECK(out.size() > at_start);
    I2D_CHECK(i2d_world_stop_recording(world) == I2D_OK);
    const size_t stopped = out.size();
    step(world);
    I2D_CHECK(out.size() == stopped);
    i2d_world_destroy(world);
}
