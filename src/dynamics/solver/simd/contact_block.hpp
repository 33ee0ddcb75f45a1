// SPDX-License-Identifier: MIT
// ContactBlock: W contact constraints side by side, one SIMD lane each (structure of
// arrays), as the contact kernels (contact_kernels.hpp) read and write them.
//
// Design note: every field is an array of W values so that a kernel loads W contacts'
// worth with one instruction. A block holds contacts of one colour, which never share a
// body the solver moves, so the W lanes are solved at once without races. W is 16 for
// AVX-512, 8 for AVX2, 4 for SSE2 and NEON, and 1 for the scalar path and for the overflow colour, whose
// contacts do share bodies and are solved one at a time. A manifold with one point
// leaves point 2 zeroed: a zero normal mass marks it, and the kernels mask it out, so
// that a block of single points can skip point 2 altogether with the same result.
// Padding lanes at the end of a colour name the fixed state and are zeroed the same way.
// What can be derived cheaply is not stored (the softness follows from whether a body
// is fixed, the rolling mass from the inertias): the solve passes stream every block
// from memory, and a block is 38 values per contact. Everything here is plain data (no
// constructors): the AVX2 kernels are compiled with other flags, and must not share
// inline code with the rest of the library.
#pragma once

#include <cstdint>

#include "dynamics/joint/hinge_columns.hpp"

namespace i2d {

template <int W>
struct ContactPointLanes {
    float anchor_ax[W], anchor_ay[W];  // from A's centre of mass, m, world orientation
    float anchor_bx[W], anchor_by[W];
    float base_separation[W];     // separation minus dot(anchor_b - anchor_a, normal), m
    float relative_velocity[W];   // normal speed at impact, for restitution, m/s
    float start_speed[W];         // normal speed when the step began, m/s
    float normal_mass[W], tangent_mass[W];  // kg; normal mass 0 marks a missing point 2
    float normal_impulse[W], tangent_impulse[W];  // accumulated, N s
    float max_normal_impulse[W];  // largest push in one iteration: did the point push?
};

template <int W>
struct alignas(W >= 4 ? 4 * W : 4) ContactBlock {
    int32_t state_a[W], state_b[W];  // in the state array; the fixed state for fixed bodies
    float inv_mass_a[W], inv_mass_b[W];  // 0 for a body the contact cannot move
    float inv_inertia_a[W], inv_inertia_b[W];
    float normal_x[W], normal_y[W];  // unit, from A to B
    float friction[W], restitution[W];
    float tangent_speed[W];          // surface speed along left_perp(normal), m/s
    float rolling_resistance[W];     // torque arm, m
    float rolling_impulse[W];
    float approach_acceleration[W];  // m/s^2 along -normal from gravity and forces, >= 0
    ContactPointLanes<W> points[2];
};

/// What packing gathers of a block's contacts one lane at a time for the kernels to
/// finish all lanes at once (ContactKernels::finish_pack): the arithmetic of packing
/// (effective masses, speeds, base separations) costs more one lane at a time than
/// gathering its inputs. Lanes with no point i have has_point[i] 0.
template <int W>
struct alignas(W >= 4 ? 4 * W : 4) PackLanes {
    float vax[W], vay[W], wa[W];  // body A's velocities when the step began
    float vbx[W], vby[W], wb[W];
    float has_point[2][W];  // 1 where the lane's contact has point i, else 0
};

/// What some lane of a block needs beyond a plain contact, so that the solve passes
/// read only those fields: in a 16-lane block every field is a cache line, and the
/// passes stream every block from memory. A block's uses are the union of its lanes'.
enum BlockUses : uint8_t {
    block_rolls = 1,           // rolling resistance
    block_conveys = 2,         // a tangent speed other than +0 (moving surfaces)
    block_tracks_impact = 4,   // a bounce or hit events: impact speeds are followed
    block_keeps_max_push = 8,  // the largest push per point, for restitution or hit events
};

/// Softness as the kernels take it (softness.hpp makes it).
struct LaneSoftness {
    float bias_rate, mass_scale, impulse_scale;
};

/// What one solve pass needs besides the constraints.
struct SolvePass {
    float inv_h;           // 1 / substep, 1/s
    float push_max_speed;  // m/s
    float elapsed;         // time since the step began, s
    bool use_bias;         // push overlap out and pull drift back (solve) or not (relax)
    float anchor_rate;     // 1/s: share of a sticking point's drift that friction removes per second
    LaneSoftness soft;        // between two moving bodies
    LaneSoftness fixed_soft;  // against a body the contact cannot move (twice as stiff)
};

struct BodyState;

/// One instruction set's contact kernels over `count` blocks of its width, and its
/// kernels for hinges (hinge_kernels.hpp), which the joint solver borrows.
struct ContactKernels {
    int32_t width;
    const char* name;
    // `uses` holds one BlockUses per block.
    void (*warm_start)(void* blocks, const uint8_t* uses, int32_t count, BodyState* states);
    void (*solve)(void* blocks, const uint8_t* uses, int32_t count, BodyState* states, const SolvePass& pass);
    void (*restitution)(void* blocks, int32_t count, BodyState* states, float threshold);
    // Each point's separation where the substeps left the bodies, m: 2 W floats per block,
    // point 0's lanes then point 1's (store sets touching from them).
    void (*final_separations)(const void* blocks, int32_t count, const BodyState* states, float* separations);
    // One block packed lane by lane (anchors, normal, masses, impulses, and each point's
    // separation in base_separation) finished from `inputs` (a PackLanes of the width):
    // base separations, normal speeds, effective masses.
    void (*finish_pack)(void* block, const void* inputs);
    HingeKernel warm_start_hinges;
    HingeKernel solve_hinges;
};

/// Always there: one lane at a time, plain C++. The overflow colour always uses it.
const ContactKernels& scalar_contact_kernels();
/// 4 lanes; null unless the library was built for x86-64.
const ContactKernels* sse2_contact_kernels();
/// 8 lanes; null unless built for x86-64 with a compiler that can target AVX2. The CPU
/// must be checked before use.
const ContactKernels* avx2_contact_kernels();
/// 16 lanes in AVX-512F; the same conditions.
const ContactKernels* avx512_contact_kernels();
/// 4 lanes in NEON; null unless the library was built for AArch64 (where NEON is always there).
const ContactKernels* neon_contact_kernels();
/// 4 lanes in WebAssembly SIMD; null unless the library was built for wasm with -msimd128.
const ContactKernels* wasm128_contact_kernels();

}  // namespace i2d
