// SPDX-License-Identifier: MIT
// BodyState and BodyMotion: the solver's dense per-step copies of the awake bodies.
//
// Design note: the substep loops touch only these arrays, indexed by a body's place in
// the awake set, never the body pool (Box2D v3's BodyState). The state holds what the
// substeps change: velocities and the motion since the step began (delta position and
// delta rotation). Positions themselves are not needed while solving: contacts measure
// separation from the motion of their anchors, so one shared "fixed" state (zero
// velocity, no motion) stands in for every static or sleeping body. A state is 32
// bytes, aligned, so that SIMD lanes load a body in one or two instructions; `moves`
// says whether contacts may write its velocities (dynamic and awake), so that a fixed or
// kinematic state shared by several lanes is only ever read.
#pragma once

#include <cstdint>

#include "math/vec2.hpp"

namespace i2d {

struct alignas(32) BodyState {
    Vec2 linear_velocity;
    float angular_velocity = 0.0f;
    float moves = 0.0f;   // 1 when contacts may change the velocities, else 0
    Vec2 delta_position;  // of the centre of mass since the step began
    Rot delta_rotation;   // turn since the step began
};

static_assert(sizeof(BodyState) == 32, "a body state is one 32-byte load for 8-wide lanes");

/// What integrating velocities and packing contacts need, fixed for the whole step; one
/// cache line, as packing reads two at random per contact.
struct alignas(64) BodyMotion {
    Vec2 force;  // N, accumulated by the caller
    float torque = 0.0f;
    float inv_mass = 0.0f, inv_inertia = 0.0f;
    float gravity_scale = 1.0f;
    float linear_damping = 0.0f;  // 1/s
    // Implicit damping over one substep, v -> v / (1 + h c): the divisions once a step
    // rather than once a substep, where they cost as much as the rest of the integration.
    float linear_damping_factor = 1.0f, angular_damping_factor = 1.0f;
    Vec2 free_acceleration;  // gravity and force over mass, m/s^2; zero unless dynamic
    // The velocities the step began with, for the restitution speeds packing measures:
    // by then the first substep has integrated the states' (the two share a stage).
    Vec2 start_linear_velocity;
    float start_angular_velocity = 0.0f;
    bool is_dynamic = false;
};

static_assert(sizeof(BodyMotion) == 64, "a body motion is one cache line");

}  // namespace i2d
