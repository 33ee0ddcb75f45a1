// SPDX-License-Identifier: MIT
// HingeColumns: the step's plain hinges (revolute joints with no spring, motor or limit,
// whose only row holds the two anchors together) as columns, one float per joint, so
// that the hinge kernels (hinge_kernels.hpp) load W joints' worth with one instruction.
//
// Design note: a grid or chain of hinges spends most of its step in this one row, and
// solved one joint at a time it is a chain of dependent scalar operations. The columns
// are indexed like the joint solver's constraints (solve order), so a colour's run of
// consecutive plain hinges is solved W at a time; while the step runs, the columns hold
// the hinge's impulses, and the joint solver copies them back when it stores. Plain data
// only: the kernels are compiled with other instruction-set flags (see contact_block.hpp).
#pragma once

#include <cstdint>

namespace i2d {

// The joint solver fills every column in prepare; the kernels write only the impulses
// and reset.
struct HingeColumns {
    int32_t* state_a;  // in the state array; the fixed state for a fixed body
    int32_t* state_b;
    float* inv_mass_a;  // 0 for a body the joint cannot move
    float* inv_mass_b;
    float* inv_inertia_a;
    float* inv_inertia_b;
    float* anchor_ax;  // from A's centre of mass, world orientation, at the step's start
    float* anchor_ay;
    float* anchor_bx;
    float* anchor_by;
    float* center_x;  // centre B - centre A at the step's start
    float* center_y;
    float* impulse_x;  // the anchor row's accumulated impulse, N s
    float* impulse_y;
    float* angular_impulse;  // warm start only: the sum the revolute rows kept from earlier steps
    float* reset;            // 1 once the guard undid a pass: the joint gave up every impulse
};

/// One pass over the hinges: how the rigid row acts (softness.hpp; plainly rigid, no
/// bias, when relaxing) and the guard's limits (JointStep).
struct HingePass {
    float bias_rate, mass_scale, impulse_scale;
    bool use_bias;
    float runaway_speed_sum, runaway_spin_sum;
};

struct BodyState;

/// `count` hinges from `first`, solved `width` at a time (count a multiple of the width).
using HingeKernel = void (*)(const HingeColumns& hinges, int32_t first, int32_t count, BodyState* states,
                             const HingePass& pass);

}  // namespace i2d
