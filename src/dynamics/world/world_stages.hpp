// SPDX-License-Identifier: MIT
// WorldStages: the modules the world's step runs, held apart from the World's declaration
// so that what includes world.hpp (the C boundary above all) does not include them all.
//
// Design note: each stage owns its data (the broadphase its trees, the contact set its
// contacts, the joint set its joints, the islands the awake lists, the solver its
// per-step arrays, the continuous stage its sweeps); what one needs of another it is
// given at construction as a reference to read or write, never by holding a stage that
// holds it back. The islands and the contact set know nothing of each other: the world
// hands each what the other changed.
#pragma once

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "core/task_system.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/contact/contact_hooks.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "dynamics/solver/continuous.hpp"
#include "dynamics/solver/solver.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/world/world_def.hpp"

namespace i2d {

struct WorldStages {
    WorldStages(const WorldDef& settings, Pool<Body>& bodies, Pool<Shape>& shapes)
        : tasks(settings.worker_count, settings.tasks),
          joints(bodies),
          contacts(settings, bodies, shapes, joints, events, tasks, hooks),
          islands(bodies),
          solver(SolverLinks{bodies, shapes, joints.pool(), joints, contacts, islands, broad_phase, events, tasks},
                 settings.simd_path),
          continuous(bodies, shapes, broad_phase, events, tasks, hooks) {}

    ContactHooks hooks;  // the host's, set between steps; the stages below read them
    TaskSystem tasks;
    BroadPhase broad_phase;
    EventRecorder events;
    JointSet joints;
    ContactSet contacts;
    Islands islands;
    Solver solver;
    Continuous continuous;
};

}  // namespace i2d
