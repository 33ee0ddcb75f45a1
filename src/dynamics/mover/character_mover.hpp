// SPDX-License-Identifier: MIT
// The character mover: a capsule moved through a world by game code in one call (walk,
// slide, climb slopes and steps, keep to the ground, push what it runs into). The
// algorithm is sketched at the top of character_mover.cpp.
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"
#include "dynamics/body/shape.hpp"
#include "math/vec2.hpp"

namespace i2d {

class World;

/// How a character moves; the C boundary checked every field (i2d_character_def).
struct CharacterDef {
    float max_slope_angle = 0.7854f;  // rad, in [0, pi/2): steeper ground is a wall
    float step_height = 0.25f;        // length units, >= 0
    float snap_distance = 0.2f;       // length units, >= 0
    float skin = 0.01f;               // length units, > 0: the gap kept to every surface
    int32_t max_iterations = 5;       // slide rounds, in [1, 64]
    float push_mass = 80.0f;          // kg, >= 0; 0: it pushes nothing
    QueryFilter filter;
};

struct CharacterResult {
    Vec2 position;
    Vec2 velocity;  // asked for, clipped by what the character ends touching
    bool on_ground = false;
    Vec2 ground_normal;
    int32_t ground_shape = null_index;
    Vec2 ground_velocity;  // of the ground's body at the feet
    int32_t hit_count = 0;  // distinct shapes touched, counted up to max_counted_hits
};

/// Distinct shapes a move counts in CharacterResult::hit_count at most.
constexpr int32_t max_counted_hits = 64;

/// Moves the capsule (in the character's frame, its origin at `position`) by velocity *
/// time_step. Changes the world only by impulses on the dynamic bodies it pushes
/// (push_mass > 0), which wake them.
CharacterResult move_character(World& world, const CharacterDef& def, const Capsule& capsule, Vec2 position,
                               Vec2 velocity, float time_step);

}  // namespace i2d
