// SPDX-License-Identifier: MIT
// HingeColumns: the step's hinges (revolute joints, with or without their spring, motor
// and limit rows) as columns, one float per joint, so that the hinge kernels
// (hinge_kernels.hpp) load W joints' worth with one instruction.
//
// Design note: grids, chains and ragdolls spend most of their step in revolute joints,
// and solved one joint at a time each is a chain of dependent scalar operations. The
// columns are indexed like the joint solver's constraints (solve order), so a colour's
// run of consecutive hinges is solved W at a time; a row some lanes lack is computed
// for all and kept only where the joint has it. While the step runs, the columns hold
// the hinges' impulses, and the joint solver copies them back when it stores. Plain data
// only: the kernels are compiled with other instruction-set flags (see contact_block.hpp).
#pragma once

#include <cstdint>

namespace i2d {

// The joint solver fills every column in prepare; the kernels write only the impulses.
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
    // The rows: 1 where the joint has the row this step, else 0 (JointConstraint::rows).
    float* has_spring;
    float* has_motor;
    float* has_limit;
    float* delta_angle;  // angle B - angle A - reference at the step's start, unwound
    float* axial_mass;   // effective mass of the angular rows
    float* spring_position_rate;  // the spring (SpringRow)
    float* spring_speed_scale;
    float* spring_impulse_scale;
    float* spring_relaxes;  // 1 when it also acts in the relax pass
    float* target_angle;
    float* motor_speed;
    float* max_motor_impulse;  // substep times the largest torque, N m s
    float* lower_angle;
    float* upper_angle;
    // Accumulated impulses: the anchor row's (N s) and the angular rows' (N m s).
    float* impulse_x;
    float* impulse_y;
    float* spring_impulse;
    float* motor_impulse;
    float* lower_impulse;
    float* upper_impulse;
};

/// One pass over the hinges: the substep, how the rigid rows act (softness.hpp; plainly
/// rigid, no bias, when relaxing) and the guard's limits (JointStep).
struct HingePass {
    float inv_h;
    float bias_rate, mass_scale, impulse_scale;
    bool use_bias;
    float runaway_speed_sum, runaway_spin_sum;
};

struct BodyState;

/// `count` hinges from `first`, solved `width` at a time (count a multiple of the width).
using HingeKernel = void (*)(const HingeColumns& hinges, int32_t first, int32_t count, BodyState* states,
                             const HingePass& pass);

}  // namespace i2d
