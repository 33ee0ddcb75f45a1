// SPDX-License-Identifier: MIT
// Body: a rigid body's state and settings, kept in the world's body pool.
//
// Design note: the pool keeps every body; the step copies the awake ones into dense
// solver arrays (body_state.hpp) and back, so the substeps never touch this. Islands
// (island.hpp) link the bodies that touch one another, so that they sleep together. The origin
// (transform.p) and the centre of mass (center) are both kept: the solver moves the
// centre, users place the origin, and transform.p = center - rotate(q, local_center).
#pragma once

#include <cstdint>

#include "core/pool.hpp"
#include "dynamics/constants.hpp"
#include "math/vec2.hpp"

namespace i2d {

enum class BodyType : uint8_t { static_body, kinematic, dynamic, count };

struct BodyDef {
    BodyType type = BodyType::static_body;
    Vec2 position;
    Rot rotation;
    Vec2 linear_velocity;
    float angular_velocity = 0.0f;
    float linear_damping = 0.0f;
    float angular_damping = 0.0f;
    float gravity_scale = 1.0f;
    bool fixed_rotation = false;
    bool enable_sleep = true;
    bool is_bullet = false;
    void* user_data = nullptr;
};

// The fields every step reads of every awake body (the narrowphase, gathering states,
// the final pass) come first, in the first cache line; the lists and settings follow.
/// A body's float settings that can change after creation.
enum class BodySetting : uint8_t { gravity_scale, linear_damping, angular_damping, sleep_threshold, count };
/// A body's flags that can change after creation.
enum class BodyFlag : uint8_t { bullet, enable_sleep, fixed_rotation, count };

/// A mass the caller sets in place of the shapes' (overridden), or none (the shapes' again).
struct MassOverride {
    bool overridden = false;
    float mass = 0.0f;   // kg, > 0
    Vec2 local_center;   // body frame
    float inertia = 0.0f;  // about local_center, kg m^2, >= 0
};

struct alignas(64) Body {
    Transform transform;  // body origin and rotation
    Vec2 center;          // centre of mass in the world
    Vec2 linear_velocity; // of the centre of mass
    float angular_velocity = 0.0f;
    float max_extent = 0.0f;  // farthest shape point from the centre of mass, m
    float inv_mass = 0.0f, inv_inertia = 0.0f;
    int32_t awake_index = null_index;  // in the awake body list; null when static or asleep
    BodyType type = BodyType::static_body;
    bool fixed_rotation = false;
    bool enable_sleep = true;
    bool is_bullet = false;
    Vec2 force;  // accumulated until the end of the next step
    float torque = 0.0f;
    float gravity_scale = 1.0f;
    float linear_damping = 0.0f, angular_damping = 0.0f;
    Vec2 local_center;  // centre of mass in the body frame
    float sleep_time = 0.0f;  // how long the body has been resting, s
    int32_t head_shape = null_index;  // list of the body's shapes, linked through Shape
    int32_t island = null_index;      // every moving body has one; static bodies none
    int32_t move_event = null_index;  // its body move event of the last step, if any
    bool needs_cover = false;         // velocity or pose changed since its boxes were fattened
    bool quarantined = false;         // frozen by a step that found its state non-finite
    float mass = 0.0f;
    float inertia = 0.0f;  // about the centre of mass
    void* user_data = nullptr;
    int32_t shape_count = 0;
    int32_t head_contact_key = null_index;  // list of contacts, linked through ContactEdge
    int32_t contact_count = 0;
    int32_t island_prev = null_index, island_next = null_index;  // the island's body list
    int32_t head_joint_key = null_index;  // list of joints, linked through JointEdge
    int32_t joint_count = 0;
    // Continuous collision: the pose the last step started from (set for every awake
    // body by the solver's final pass) and the smallest shape thickness, m.
    Vec2 center0;
    Rot rotation0;
    float min_extent = 0.0f;
    float sleep_threshold = 0.05f;  // resting below this speed, length units per second
    bool enabled = true;            // false: out of the broadphase, contacts, islands and solver
    bool mass_overridden = false;   // mass, local_center and override_inertia set by the caller
    float override_inertia = 0.0f;  // about the centre of mass, kept while fixed_rotation zeroes inertia
};

/// Whether a dynamic body that travels this far in a step (its fastest point, m) is
/// fast: then it may pass through something thin, and the continuous stage sweeps it.
inline bool is_fast_travel(const Body& b, float travel) { return travel > continuous_safety_factor * b.min_extent; }

/// Whether the continuous stage sweeps the fast body `fast` against `other`: a dynamic
/// body against static and kinematic ones, a bullet against every other body.
inline bool is_swept_against(const Body& fast, const Body& other) {
    return fast.type == BodyType::dynamic && (other.type != BodyType::dynamic || fast.is_bullet);
}

}  // namespace i2d
