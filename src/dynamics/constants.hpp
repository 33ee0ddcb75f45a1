// SPDX-License-Identifier: MIT
// Tuning numbers of the step, each with its unit and what changing it risks. The limits
// the C boundary holds input to are in capi/limits.hpp. Lengths are given in metres; the
// step reads those it uses through Tolerances (tolerances.hpp), scaled to the world's
// length unit.
#pragma once

#include <cstdint>

namespace i2d {

/// How far a moving shape's fat box reaches beyond its tight box: this fraction of the
/// shape's size (half the diagonal of its box), at most the maximum, m. Larger margins
/// move proxies in the tree less often but give the narrowphase more pairs, and a small
/// shape meets more pairs for the same margin than a large one: 0.1 m on a 0.25 m box
/// doubles its candidates. Since proxies move in place and the tree rebuilds only what
/// grew, moves are cheap: an eighth (0.022 m on that box, close to Box2D v3's) cut the
/// tumbler's pairs from 10 913 to 9 108 and its narrowphase by a tenth, bounds unchanged.
constexpr float aabb_margin_fraction = 0.125f;
constexpr float max_aabb_margin = 0.1f;

/// Largest turn of a body in one substep, rad. Faster spins are clamped: beyond a
/// quarter turn per substep contacts alias and thin shapes tunnel.
constexpr float max_rotation_per_substep = 0.25f * 3.14159265f;

/// Fastest spin a body is given, rad/s: set and impulse-changed angular velocities are
/// clamped to it where they enter. The step's own clamp (a quarter turn per substep) is
/// far lower at any practical substep; this one keeps w x r and its square finite for
/// the largest shapes before that clamp runs.
constexpr float max_angular_speed = 1.0e5f;

/// Contact recycling (contact.hpp): a manifold is kept while the farthest point of the
/// two bodies moved less than this relative to each other since it was made, m. The
/// linear slop: kept points stay within 5 mm of fresh ones, a resting stack skips the
/// narrowphase for many steps, and a pile that slowly turns over (the tumbler) makes
/// seven in ten of its manifolds afresh each step where it made nine in ten at 1.25 mm
/// and 1 degree (the 100-row pyramid's boxes also drift half as far sideways).
/// Larger values let points lag further: Box2D v3 keeps them for 5 cm and 11.5 degrees,
/// and at 2 cm and 5.7 degrees a heap of 100 ragdolls no longer fell asleep in 30 s.
constexpr float recycle_touching_distance = 0.005f;
/// The same for contacts that were apart: smaller, so that an approaching feature is
/// picked up before it arrives, m.
constexpr float recycle_apart_distance = 0.002f;
/// Cosine of the largest turn of either body while its manifolds are kept: 2 degrees.
/// Anchors and normals keep their world orientation, so a larger turn tilts them.
constexpr float recycle_min_cos = 0.99939f;

/// Share of a sticking contact point's tangential drift within the step that friction
/// pulls back per substep (contact_kernels.hpp, solve_friction): all of it, as the
/// push-out would for a rigid contact. In the 100-row pyramid a fifth left the boxes'
/// mean sideways displacement at 5 cm and slowly growing, a half at 3.5-4 cm; all of it
/// holds it at 2.3-2.7 cm from step 300 to step 4000.
constexpr float friction_anchor_share = 1.0f;

/// Continuous collision (continuous.hpp): a dynamic body is swept when its fastest point
/// travels more than this share of its thinnest shape's inner radius in a step (Box2D's
/// safety factor). Smaller values sweep more bodies that the speculative contacts would
/// have stopped anyway; larger ones let thin bodies tunnel through thin walls.
constexpr float continuous_safety_factor = 0.5f;

/// Sweeps of the impact impulse (impact.hpp) where the continuous stage stops a fast
/// body: one is exact for a ball, or a box landing flat without sliding (its two points
/// are one block); friction that turns the body changes its normal speeds, and a few
/// sweeps let the two agree. Fewer leave part of the approach or of the friction; more
/// cost only per impact, never per contact or per step.
constexpr int32_t impact_iterations = 8;

// Threads. Handing work to other workers costs microseconds per stage, so a world
// smaller than this runs its step on the calling thread alone (same bits either way);
// and no worker claims less than a block of this many items at a time.
#if defined(I2D_FUZZ_SHARES_SMALL_WORLDS)
// The API fuzzer's build: its programs hold at most 48 bodies, and with these their steps
// still go through the shared stages, in blocks of a few items.
constexpr int32_t parallel_min_bodies = 2;
constexpr int32_t parallel_min_contacts = 2;
constexpr int32_t parallel_min_moved_proxies = 2;
constexpr int32_t parallel_min_fast_bodies = 2;
constexpr int32_t bodies_per_work_block = 4;
constexpr int32_t contacts_per_work_block = 4;
constexpr int32_t joints_per_work_block = 2;
#else
/// Awake bodies below which the solver runs inline.
constexpr int32_t parallel_min_bodies = 256;
/// Awake contacts below which the narrowphase runs inline.
constexpr int32_t parallel_min_contacts = 512;
/// Moved proxies below which pair finding runs inline.
constexpr int32_t parallel_min_moved_proxies = 64;
/// Fast bodies (not bullets) below which the continuous sweeps run inline.
constexpr int32_t parallel_min_fast_bodies = 32;
constexpr int32_t bodies_per_work_block = 64;
constexpr int32_t contacts_per_work_block = 64;
constexpr int32_t joints_per_work_block = 32;
#endif
// A colour of at most this many work blocks is solved on one worker, in one stage with the
// small colours beside it: shared out, it would cost more in waiting than it saves.
constexpr int32_t small_color_blocks = 2;
constexpr int32_t joint_trees_per_work_block = 8;
constexpr int32_t proxies_per_work_block = 16;
// A continuous sweep takes microseconds (tree queries and times of impact).
constexpr int32_t fast_bodies_per_work_block = 4;
// The self search's parts are cut to comparable weights and are each a block of their
// own (not 8 blocks a worker as other stages): a worker done early takes parts over.
constexpr int32_t self_search_parts_per_work_block = 1;

}  // namespace i2d
