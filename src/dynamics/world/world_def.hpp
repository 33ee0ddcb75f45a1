// SPDX-License-Identifier: MIT
// WorldDef: a world's settings, as the C API's world def gives them (with their units).
#pragma once

#include "core/task_system.hpp"
#include "dynamics/contact/mixing.hpp"
#include "dynamics/solver/simd/simd_path.hpp"
#include "math/vec2.hpp"

namespace i2d {

struct WorldDef {
    Vec2 gravity{0.0f, -10.0f};
    float contact_slop = 0.005f;
    float contact_hertz = 60.0f;
    float contact_damping_ratio = 10.0f;
    float contact_push_max_speed = 3.0f;
    float joint_hertz = 60.0f;
    float joint_damping_ratio = 2.0f;
    float restitution_threshold = 1.0f;
    float maximum_linear_speed = 400.0f;
    MixingRule friction_mixing = MixingRule::geometric_mean;
    MixingRule restitution_mixing = MixingRule::minimum;
    bool enable_sleep = true;
    float sleep_speed_threshold = 0.05f;
    float time_to_sleep = 0.5f;
    SimdPath simd_path = SimdPath::automatic;  // must be supported (simd_path_supported)
    bool enable_contact_recycling = true;      // keep manifolds of bodies that barely moved
    bool enable_profile = false;               // time the step's stages from the first step
    int32_t worker_count = 1;                  // in [1, max_worker_count]
    TaskCallbacks tasks;                       // both null: the built-in pool
    bool enable_continuous = true;             // sweep fast bodies (continuous.hpp)
    bool enable_impact_chains = true;          // impacts within a step one at a time (impact_chain.hpp)
    float hit_event_threshold = 1.0f;          // m/s: slower impacts report no hit event
    float length_units_per_meter = 1.0f;       // the world's length unit (tolerances scale with it)
};

/// A blast (World::explode, world_explode.cpp); lengths in the world's unit.
struct ExplosionDef {
    uint64_t mask_bits = ~uint64_t(0);  // shapes whose category meets it are pushed
    Vec2 position;
    float radius = 1.0f;              // full strength within it
    float falloff = 0.0f;             // fading linearly to nothing over this much beyond
    float impulse_per_length = 1.0f;  // N s per length of outline facing the blast
};

}  // namespace i2d
