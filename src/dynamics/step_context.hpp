// SPDX-License-Identifier: MIT
// StepContext: what every stage of one step reads about the step itself, made once by the
// world at the step's start and passed to each stage (Box2D's b2StepContext, Jolt's
// PhysicsUpdateContext).
//
// Design note: the time step and what follows from it (the substep, its inverse, the
// constraints' softness) are computed here once, so that no stage keeps a copy of its own
// that could disagree with another's; a stage function receives the context, its owner
// and its own typed argument (core/stage_runner.hpp).
#pragma once

#include <cstdint>

#include "dynamics/constants.hpp"
#include "dynamics/joint/joint_constraint.hpp"
#include "dynamics/solver/softness.hpp"
#include "dynamics/tolerances.hpp"
#include "dynamics/world/world_def.hpp"
#include "math/math.hpp"

namespace i2d {

struct StepContext {
    const WorldDef& settings;
    float time_step;       // s, never 0 (a paused step runs no stage)
    int32_t substep_count;
    float substep;         // h = time_step / substep_count, s
    float inv_substep;     // substep_count / time_step, 1/s
    // The contacts' push-out springs: between two moving bodies, and against a body the
    // contact cannot move (twice the frequency).
    Softness contact_softness;
    Softness fixed_contact_softness;
    JointStep joint_step;  // what the joints' rows read
    int32_t worker_count;
    Tolerances tolerances;  // the slop, margins and distances in the world's length unit

    StepContext(const WorldDef& world_settings, float step, int32_t substeps, int32_t workers)
        : settings(world_settings),
          time_step(step),
          substep_count(substeps),
          substep(step / float(substeps)),
          inv_substep(float(substeps) / step),
          contact_softness(make_softness(contact_hertz(), world_settings.contact_damping_ratio, substep)),
          fixed_contact_softness(make_softness(2.0f * contact_hertz(), world_settings.contact_damping_ratio, substep)),
          joint_step(substep, inv_substep,
                     make_softness(min_of(world_settings.joint_hertz, stiffness_limit()),
                                   world_settings.joint_damping_ratio, substep),
                     world_settings.maximum_linear_speed, max_rotation_per_substep / substep),
          worker_count(workers),
          tolerances(world_settings.length_units_per_meter) {}

    /// Stiffness is capped at a quarter of the substep rate, beyond which the implicit
    /// spring stops being accurate, Hz.
    float stiffness_limit() const { return 0.25f / substep; }
    float contact_hertz() const { return min_of(settings.contact_hertz, stiffness_limit()); }
    /// The fastest a body may turn in a substep, as a speed, rad/s.
    float max_spin() const { return max_rotation_per_substep / substep; }
};

}  // namespace i2d
