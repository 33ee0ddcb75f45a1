// SPDX-License-Identifier: MIT
// The world def at the C boundary (world_def.cpp): its checks, its conversions, and a new
// world's registration.
#pragma once

#include <memory>

#include "boundary.hpp"

namespace i2d::capi {

/// A def's worker_count in [1, I2D_MAX_WORKERS], and both or neither of its job system's
/// callbacks; def_name starts the message.
bool valid_job_system(Call& call, const char* def_name, int32_t worker_count, bool has_enqueue, bool has_finish);
/// A step's time step (0, or in [min_time_step, max_time_step]) and substep count.
bool valid_step(Call& call, float time_step, int32_t substep_count);
/// Every field of a world def in its documented range, and the cookie set.
bool validate_world_def(Call& call, const i2d_world_def* def);
WorldDef to_core(const i2d_world_def& def);
/// The def a world's settings would come from (cookie set): for checking settings that
/// came from elsewhere (a snapshot) against the same rules.
i2d_world_def to_public(const WorldDef& core);
/// Registers a new world and installs its id encoding; I2D_NULL_WORLD_ID (the world
/// freed, the status set) when max_worlds are alive.
i2d_world_id register_new_world(Call& call, std::unique_ptr<World> world);

}  // namespace i2d::capi
