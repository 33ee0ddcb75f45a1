// SPDX-License-Identifier: MIT
// ContactSolver: contacts of the soft step (Box2D v3's solver, after Catto's Solver2D),
// laid out in SIMD lanes colour by colour.
//
// Every normal impulse is the seed's j = -(vn - vn_target) / K with the full effective
// mass K = invMassA + invMassB + (rA x n)^2 invIA + (rB x n)^2 invIB, clamped so that the
// accumulated impulse never pulls. What changed from the seed is where vn_target comes
// from and when it is applied:
// - Overlap is pushed out by a soft constraint (softness.hpp) instead of moving
//   positions: at most push_max_speed, with no jitter.
// - A gap (a speculative point) allows approach up to closing it within the substep,
//   so that fast bodies stop at the surface instead of passing through.
// - Each substep solves with that push-out, then relaxes (solves again without it), so
//   that the push-out velocity does not become bounce.
// - Two-point manifolds are solved as one 2x2 block (Box2D 2.4's block solver, after
//   Catto's GDC talks, extended to soft terms): solving the points one after the other
//   lets the first take more than its share, which turns a resting box and makes tall
//   stacks lean. Where the block is ill-conditioned or no case fits, point by point.
// - Restitution is one pass after the substeps, towards -e times the normal speed the
//   pair had at impact: exactly the seed's (1 + e) impulse for an isolated pair. Until a
//   point first pushes, that impact speed follows the pair's free motion (start speed
//   plus gravity and forces, over the remaining gap), so that a bounce keeps its energy.
//   It runs over every contact that pushed, a few times, and only when something
//   bounces: a ball bouncing off a row of touching balls must push the whole row.
// Friction is clamped to mu times the normal impulse; rolling resistance clamps a torque
// the same way. Impulses accumulated in one substep warm-start the next, and the last
// ones go back to the contact (by feature id) to warm-start the next step.
//
// Design note: the contacts of one colour share no body the solver moves, so W of them
// are solved at once in SIMD lanes (contact_block.hpp, contact_kernels.hpp), W set by
// the instruction set chosen at run time (simd_path.hpp). The overflow colour, whose
// contacts do share bodies, is solved one contact at a time with the same arithmetic,
// so every path gives the same bits.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "dynamics/body_state.hpp"
#include "dynamics/contact.hpp"
#include "dynamics/contact_block.hpp"

namespace i2d {

/// The contacts to solve, already coloured, and what they need of their bodies.
struct ContactLayout {
    const Pool<Contact>& contacts;
    const int32_t* ordered;       // contact indices, colour by colour, in solve order
    const int32_t* color_starts;  // per colour: its first slot in `ordered`; one more at the end
    int32_t color_count;          // the last colour is the overflow colour
    const BodyState* states;      // velocities before the step
    const BodyMotion* motions;
    int32_t fixed_state;          // index of the shared fixed state
};

class ContactSolver {
public:
    void set_kernels(const ContactKernels& kernels) { kernels_ = &kernels; }
    const ContactKernels& kernels() const { return *kernels_; }

    /// Packs the contacts into blocks: effective masses, anchors, the restitution speeds
    /// from the velocities before the step, last step's impulses.
    void prepare(const ContactLayout& layout);
    void warm_start(BodyState* states);
    /// One pass over every contact; pass.use_bias pushes overlap out, without it the
    /// pass relaxes.
    void solve(BodyState* states, const SolvePass& pass);
    void apply_restitution(BodyState* states, float threshold);
    /// Impulses back to the contacts; contacts with a point within `slop` of touching
    /// where the substeps left the bodies get contact_touching.
    void store(Pool<Contact>& contacts, const BodyState* states, float slop) const;

private:
    template <int W>
    std::vector<ContactBlock<W>>& blocks();
    template <int W>
    void pack_colors(const ContactLayout& layout);
    void pack_overflow(const ContactLayout& layout);
    template <int W>
    void store_blocks(const std::vector<ContactBlock<W>>& blocks, const std::vector<int32_t>& contacts_of_lanes,
                      Pool<Contact>& contacts, const BodyState* states, float slop) const;
    template <int W>
    bool any_bounce(const std::vector<ContactBlock<W>>& blocks, float threshold) const;
    template <class Stage>
    void for_each_color(Stage&& stage);

    const ContactKernels* kernels_ = &scalar_contact_kernels();
    // The colours' blocks, in the kernels' width; the overflow colour's one per contact.
    std::vector<ContactBlock<1>> blocks1_;
    std::vector<ContactBlock<4>> blocks4_;
    std::vector<ContactBlock<8>> blocks8_;
    std::vector<ContactBlock<16>> blocks16_;
    std::vector<ContactBlock<1>> overflow_;
    std::vector<int32_t> color_block_starts_;  // per colour (overflow excluded), one more at the end
    struct ColorRun {
        int32_t first_block, block_count;
    };
    std::vector<ColorRun> runs_;  // the colours that have contacts, in solve order
    std::vector<int32_t> lane_contacts_;       // per lane of the colours' blocks: its contact, or -1
    std::vector<int32_t> overflow_contacts_;
};

}  // namespace i2d
