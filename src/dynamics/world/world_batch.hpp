// SPDX-License-Identifier: MIT
// Many worlds stepped in one call, as reinforcement learning runs its environments.
//
// Design note: the worlds are the work items. Each is stepped start to end by one
// worker, on its own task system as when stepped alone, so its bits do not depend on the
// batch; workers claim the next unstepped world from one counter, so that a few large
// worlds do not hold up the rest (a fixed split would leave a worker idle behind them).
#pragma once

#include <cstdint>

namespace i2d {

class TaskSystem;
class World;

enum class BatchOutcome : int32_t { stepped, out_of_memory, internal_error };

/// Steps every world by time_step on the task system's workers. Until it returns the
/// worlds count as stepping (World::is_stepping), so that a contact hook or job-system
/// callback of one cannot reach another that a different worker is stepping. A world
/// whose step throws stops there; the others are stepped, and the worst outcome is
/// returned.
BatchOutcome step_worlds(World* const* worlds, int32_t count, float time_step, int32_t substep_count,
                         TaskSystem& tasks);

}  // namespace i2d
