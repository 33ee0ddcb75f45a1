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
#include "dynamics/solver/body_state.hpp"
#include "dynamics/contact/contact.hpp"
#include "dynamics/solver/simd/contact_block.hpp"

namespace i2d {

/// The contacts to solve, already coloured, and what they need of their bodies.
struct ContactLayout {
    const Pool<Contact>& contacts;
    const int32_t* ordered;       // contact indices, colour by colour, in solve order
    const int32_t* color_starts;  // per colour: its first slot in `ordered`; one more at the end
    int32_t color_count;          // the last colour is the overflow colour
    const BodyMotion* motions;    // with the velocities before the step
    int32_t fixed_state;          // index of the shared fixed state
    bool any_elastic;             // some contact has restitution: the restitution pass may run
    /// When set, where each worker's part of each colour begins, in contacts from the
    /// colour's first: part_stride entries per colour, rising from 0 to its contact count,
    /// or -1 first for a colour kept whole. Each part starts a block of its own, and parts
    /// are placed apart in memory.
    const int32_t* color_parts = nullptr;
    int32_t part_stride = 0;
};

class ContactSolver {
public:
    void set_kernels(const ContactKernels& kernels) { kernels_ = &kernels; }
    const ContactKernels& kernels() const { return *kernels_; }

    // The solver's work comes in ranges, so that workers can share it (stage_runner.hpp):
    // lay_out on one thread, then every other call over any split of its range. A
    // "run" is a colour's blocks; the last run, run_count() - 1 when there is overflow,
    // is the overflow colour, which must be done whole, on one worker.

    /// Places the contacts in blocks, colour by colour (one thread).
    void lay_out(const ContactLayout& layout);
    /// Blocks of the colours, and contacts of the overflow colour.
    int32_t block_count() const { return int32_t(lane_contacts_.size()) / kernels_->width; }
    int32_t overflow_count() const { return int32_t(overflow_contacts_.size()); }

    int32_t run_count() const { return int32_t(runs_.size()) + (overflow_.empty() ? 0 : 1); }
    /// The first item of each part of a colour run laid out in parts (ContactLayout::
    /// color_parts): part_stride - 1 of them; -1 for a run kept whole.
    int32_t part_first_item(int32_t run, int32_t part) const;
    /// The run's items: blocks of a colour, or the overflow's contacts.
    int32_t run_items(int32_t run) const;
    bool run_is_sequential(int32_t run) const { return run == int32_t(runs_.size()); }
    /// Packs the run's items [begin, end): effective masses, anchors, the restitution
    /// speeds from the velocities before the step, last step's impulses.
    void pack(const ContactLayout& layout, int32_t run, int32_t begin, int32_t end);
    void warm_start(int32_t run, int32_t begin, int32_t end, BodyState* states) const;
    /// One pass; pass.use_bias pushes overlap out, without it the pass relaxes.
    void solve(int32_t run, int32_t begin, int32_t end, BodyState* states, const SolvePass& pass) const;
    /// Whether any point bounces: only then does the restitution pass run.
    bool any_bounce(float threshold) const;
    void apply_restitution(int32_t run, int32_t begin, int32_t end, BodyState* states, float threshold) const;
    /// Impulses of the run's items [begin, end) back to their contacts; contacts with a
    /// point within `slop` of touching where the substeps left the bodies get
    /// contact_touching.
    void store(Pool<Contact>& contacts, const BodyState* states, float slop, int32_t run, int32_t begin,
               int32_t end) const;

private:
    void pack_overflow(const ContactLayout& layout, int32_t begin, int32_t end);
    template <int W>
    std::vector<ContactBlock<W>>& blocks();
    template <int W>
    void lay_out_colors(const ContactLayout& layout);
    template <int W>
    void pack_range(const ContactLayout& layout, int32_t begin, int32_t end);
    // Blocks [first, end): their lanes' impulses into their contacts.
    template <int W>
    void store_range(const ContactKernels& kernels, const ContactBlock<W>* blocks, const int32_t* contacts_of_lanes,
                     int32_t first, int32_t end, Pool<Contact>& contacts, const BodyState* states, float slop) const;
    template <int W>
    bool bounces(const ContactBlock<W>* blocks, const uint8_t* uses, std::size_t count, float threshold) const;
    // The kernels and the address of a block.
    struct RunBlocks {
        const ContactKernels* kernels;
        void* blocks;
        const uint8_t* uses;
    };
    RunBlocks colored_blocks(int32_t block) const;
    RunBlocks overflow_blocks(int32_t first) const;
    /// Calls piece(block, count) for the items [begin, end) of a colour run, in pieces
    /// that each lie within one part: `count` blocks from block `block` on.
    template <class Piece>
    void for_each_piece(int32_t run, int32_t begin, int32_t end, Piece&& piece) const;

    const ContactKernels* kernels_ = &scalar_contact_kernels();
    // The colours' blocks, in the kernels' width; the overflow colour's one per contact.
    std::vector<ContactBlock<1>> blocks1_;
    std::vector<ContactBlock<4>> blocks4_;
    std::vector<ContactBlock<8>> blocks8_;
    std::vector<ContactBlock<16>> blocks16_;
    std::vector<ContactBlock<1>> overflow_;
    std::vector<uint8_t> block_uses_, overflow_uses_;  // BlockUses per block
    struct ColorRun {
        int32_t block_count;
        int32_t first_part, part_count;  // in parts_
        bool apart;                      // laid out in the workers' parts
    };
    // Consecutive blocks of a colour: its first item (block of the colour), where it lies
    // in the block arrays, and its contacts (from the colour's first).
    struct Part {
        int32_t first_item, first_block;
        int32_t first_contact, contact_count;
    };
    std::vector<ColorRun> runs_;  // the colours that have contacts, in solve order
    std::vector<Part> parts_;
    std::vector<int32_t> lane_contacts_;       // per lane of the colours' blocks: its contact, or -1
    std::vector<int32_t> overflow_contacts_;
    int32_t fixed_state_ = 0;
};

}  // namespace i2d
