// SPDX-License-Identifier: MIT
// The recording format: a header, then records, each one call that changed the world or
// one step, streamed to the caller's writer as they happen.
//
//   offset  size  field
//        0     8  magic "i2drec", 0, then 0x1a
//        8     4  format version (recording_format_version)
//       12     4  0 (reserved)
//       16        records, each:
//                   4  the low 32 bits of checksum64 (core/checksum.hpp) of the rest
//                   1  what it is (RecordedOp)
//                   4  payload size, bytes
//                   4  the low 32 bits of checksum64 of the 5 bytes above (format 2 on)
//                      payload
//
// The first record is a `snapshot`: the world's full snapshot when recording started.
// Then one record per call, in order, with the core's arguments as its payload (bodies,
// shapes, chains and joints by their pool index; floats as their bits; user data as its
// 64-bit value), and one per step: time step, substep count, and the state hash the step
// produced. A world restored while recording gives a `snapshot` record of what it became.
// A reader takes the whole records a stream holds: one cut short at the end (a program
// that stopped mid-write) is left out; a record whose checksum does not match is refused.
// The size's own check lets a reader tell a record cut short from one whose size was
// changed to reach past the end, which format 1 took for a cut and so dropped the rest.
#pragma once

#include <cstddef>
#include <cstdint>

namespace i2d {

enum class RecordedOp : uint8_t {
    snapshot = 1,
    step,
    create_body,
    destroy_body,
    set_type,
    set_transforms,
    set_linear_velocity,
    set_angular_velocity,
    apply_force,
    apply_force_to_center,
    apply_torque,
    apply_linear_impulse,
    apply_angular_impulse,
    set_body_user_data,
    wake_body,
    sleep_body,
    wake_all,
    create_shape,
    destroy_shape,
    set_friction,
    set_restitution,
    set_filter,
    set_shape_user_data,
    create_chain,
    destroy_chain,
    create_joint,
    destroy_joint,
    set_joint_def,
    set_joint_user_data,
    set_gravity,
    rebuild_static_tree,
    // Added with the runtime API (issue 40): new kinds go last, so that older recordings
    // keep their numbers.
    set_mass_data,
    set_body_enabled,
    set_body_setting,   // a body's float setting (BodySetting) and its value
    set_body_flag,      // a body's flag (BodyFlag) and its value
    set_shape_geometry,
    set_shape_density,
    set_shape_material,
    set_shape_flag,     // a shape's event flag (ShapeFlag) and its value
    set_world_settings, // the simulation's settings whole
    shift_origin,
    count
};

/// Receives a recording's bytes, a record at a time.
using RecordWriter = void (*)(const void* bytes, std::size_t size, void* context);

// 2 added the shape def's opt-ins to the contact hooks (off in older recordings). 3 added
// the world's enable_impact_chains to its recorded settings (on in older recordings).
constexpr uint32_t recording_format_version = 3;
constexpr std::size_t recording_header_size = 16;
constexpr std::size_t record_header_size = 13;
constexpr std::size_t record_header_size_v1 = 9;  // format 1: no size check

/// Fills in a record's payload size, size check and checksum: the first
/// record_header_size bytes of `record`, which the payload follows.
void seal_record(unsigned char* record, std::size_t payload_size);
/// The size check a record's header holds (format 2 on): of its kind and size bytes.
uint32_t record_size_check(const unsigned char* record);
constexpr unsigned char recording_magic[8] = {'i', '2', 'd', 'r', 'e', 'c', 0, 0x1a};

}  // namespace i2d
