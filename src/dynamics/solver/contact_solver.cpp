// SPDX-License-Identifier: MIT
// The contact solver's lanes: packing contacts into blocks, running the kernels colour
// by colour, and the impulses back.
#include "dynamics/solver/contact_solver.hpp"

#include <cstring>

#include "core/assert.hpp"
#include "core/prefetch.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// A point's anchors, separation and last step's impulses; the kernels' finish_pack
// derives the rest of its row.
template <int W>
void pack_point(ContactPointLanes<W>& p, int lane, const ContactPoint& cp) {
    p.anchor_ax[lane] = cp.anchor_a.x;
    p.anchor_ay[lane] = cp.anchor_a.y;
    p.anchor_bx[lane] = cp.anchor_b.x;
    p.anchor_by[lane] = cp.anchor_b.y;
    p.base_separation[lane] = cp.separation;
    p.normal_impulse[lane] = cp.normal_impulse;
    p.tangent_impulse[lane] = cp.tangent_impulse;
}

// What the kernels must read for this contact (contact_block.hpp). Restitution's pass
// needs every point's largest push as soon as any contact in the world is elastic.
uint8_t uses_of(const Contact& contact, bool keeps_max_push) {
    uint8_t uses = keeps_max_push ? uint8_t(block_keeps_max_push) : uint8_t(0);
    if (contact.rolling_resistance != 0.0f) {
        uses |= block_rolls;
    }
    uint32_t tangent_speed_bits;
    std::memcpy(&tangent_speed_bits, &contact.tangent_speed, sizeof(tangent_speed_bits));
    if (tangent_speed_bits != 0u) {
        uses |= block_conveys;
    }
    if (contact.restitution != 0.0f || (contact.flags & contact_hit_events) != 0) {
        uses |= block_tracks_impact | block_keeps_max_push;
    }
    return uses;
}

// One contact into one lane. The block was zeroed: what a contact leaves out (a second
// point, padding lanes) stays zero, which the kernels read as nothing to do.
template <int W>
void pack_lane(ContactBlock<W>& block, PackLanes<W>& inputs, int lane, const Contact& contact,
               const ContactLayout& layout) {
    const int32_t state_a = contact.state_a != null_index ? contact.state_a : layout.fixed_state;
    const int32_t state_b = contact.state_b != null_index ? contact.state_b : layout.fixed_state;
    const BodyMotion& ma = layout.motions[state_a];
    const BodyMotion& mb = layout.motions[state_b];
    block.state_a[lane] = state_a;
    block.state_b[lane] = state_b;
    block.inv_mass_a[lane] = ma.inv_mass;
    block.inv_mass_b[lane] = mb.inv_mass;
    block.inv_inertia_a[lane] = ma.inv_inertia;
    block.inv_inertia_b[lane] = mb.inv_inertia;
    block.normal_x[lane] = contact.normal.x;
    block.normal_y[lane] = contact.normal.y;
    block.friction[lane] = contact.friction;
    block.restitution[lane] = contact.restitution;
    block.tangent_speed[lane] = contact.tangent_speed;
    block.rolling_resistance[lane] = contact.rolling_resistance;
    block.rolling_impulse[lane] = contact.rolling_impulse;
    const Vec2 relative_acceleration = mb.free_acceleration - ma.free_acceleration;
    block.approach_acceleration[lane] = max_of(-dot(relative_acceleration, contact.normal), 0.0f);
    inputs.vax[lane] = ma.start_linear_velocity.x;
    inputs.vay[lane] = ma.start_linear_velocity.y;
    inputs.wa[lane] = ma.start_angular_velocity;
    inputs.vbx[lane] = mb.start_linear_velocity.x;
    inputs.vby[lane] = mb.start_linear_velocity.y;
    inputs.wb[lane] = mb.start_angular_velocity;
    for (int32_t i = 0; i < 2; ++i) {
        const bool has = i < contact.point_count;
        inputs.has_point[i][lane] = has ? 1.0f : 0.0f;
        if (has) {
            pack_point(block.points[i], lane, contact.points[i]);
        }
    }
}

// A lane no contact fills: the fixed state's, with no point.
template <int W>
void pad_lane(ContactBlock<W>& block, PackLanes<W>& inputs, int lane, int32_t fixed_state) {
    block.state_a[lane] = block.state_b[lane] = fixed_state;
    inputs.vax[lane] = inputs.vay[lane] = inputs.wa[lane] = 0.0f;
    inputs.vbx[lane] = inputs.vby[lane] = inputs.wb[lane] = 0.0f;
    inputs.has_point[0][lane] = inputs.has_point[1][lane] = 0.0f;
}

// Contacts are read in colour order, which jumps through the contact pool: each one is
// a cache miss unless asked for ahead. The bodies' motions are asked for once the
// contact itself is close.
constexpr int32_t prefetch_contacts_ahead = 16;
constexpr int32_t prefetch_bodies_ahead = 4;

// Room between workers' parts of a colour. A core streaming through its part has the
// hardware prefetcher read on past the end, into the next part, so the worker that starts
// there finds its first blocks shared with the other core and waits for them. On the
// 2-vCPU EPYC of scenes.md a gap of 4.8 KB left that wait (a stage's first block took
// twice as long as the others), 19 KB halved it and 39 KB removed it.
constexpr std::size_t gap_bytes = 48 * 1024;

// The first two lines of a contact: what packing and storing touch.
I2D_FORCE_INLINE void prefetch_solver_data(const Contact& c) { prefetch_lines(&c, 2); }

I2D_FORCE_INLINE void prefetch_bodies(const Contact& c, const ContactLayout& layout) {
    for (const int32_t state : {c.state_a, c.state_b}) {
        if (state != null_index) {
            prefetch_object(layout.motions[state]);
        }
    }
}

// Packing reads contacts in colour order, lane by lane; -1 lanes are padding.
I2D_FORCE_INLINE void prefetch_ahead(const ContactLayout& layout, const int32_t* lane_contacts, int32_t lane,
                                     int32_t end) {
    const int32_t contact_ahead = lane + prefetch_contacts_ahead;
    if (contact_ahead < end && lane_contacts[contact_ahead] >= 0) {
        prefetch_solver_data(layout.contacts[lane_contacts[contact_ahead]]);
    }
    const int32_t bodies_ahead = lane + prefetch_bodies_ahead;
    if (bodies_ahead < end && lane_contacts[bodies_ahead] >= 0) {
        prefetch_bodies(layout.contacts[lane_contacts[bodies_ahead]], layout);
    }
}

}  // namespace

template <>
std::vector<ContactBlock<1>>& ContactSolver::blocks<1>() { return blocks1_; }
template <>
std::vector<ContactBlock<4>>& ContactSolver::blocks<4>() { return blocks4_; }
template <>
std::vector<ContactBlock<8>>& ContactSolver::blocks<8>() { return blocks8_; }
template <>
std::vector<ContactBlock<16>>& ContactSolver::blocks<16>() { return blocks16_; }

// Colour by colour, each colour's contacts W to a block, the last block padded: which
// contact goes in which lane. The blocks are zeroed and filled by pack_range. A colour
// split between workers has each worker's part start a block (no block holds two
// workers' contacts) and end with gap_bytes of blocks no one uses.
template <int W>
void ContactSolver::lay_out_colors(const ContactLayout& layout) {
    const int32_t colors = layout.color_count - 1;
    const int32_t gap_blocks = int32_t((gap_bytes + sizeof(ContactBlock<W>) - 1) / sizeof(ContactBlock<W>));
    int32_t block_total = 0;
    runs_.clear();
    parts_.clear();
    for (int32_t c = 0; c < colors; ++c) {
        const int32_t count = layout.color_starts[c + 1] - layout.color_starts[c];
        if (count == 0) {
            continue;
        }
        const int32_t* split = layout.color_parts != nullptr
                                   ? layout.color_parts + std::size_t(c) * std::size_t(layout.part_stride)
                                   : nullptr;
        const bool apart = split != nullptr && split[0] >= 0;
        const int32_t part_count = apart ? layout.part_stride - 1 : 1;
        ColorRun run{0, int32_t(parts_.size()), part_count, apart};
        for (int32_t k = 0; k < part_count; ++k) {
            const int32_t first = apart ? split[k] : 0, end = apart ? split[k + 1] : count;
            I2D_ASSERT(first <= end && end <= count);
            const int32_t blocks = (end - first + W - 1) / W;
            parts_.push_back({run.block_count, block_total, first, end - first});
            run.block_count += blocks;
            block_total += blocks + (apart && blocks > 0 ? gap_blocks : 0);
        }
        runs_.push_back(run);
    }
    blocks<W>().resize(std::size_t(block_total));
    // Gap blocks are never packed: uses of 0 keep any_bounce from reading them.
    block_uses_.assign(std::size_t(block_total), 0);
    lane_contacts_.assign(std::size_t(block_total) * W, -1);
    int32_t run = 0;
    for (int32_t c = 0; c < colors; ++c) {
        const int32_t first = layout.color_starts[c];
        if (layout.color_starts[c + 1] == first) {
            continue;
        }
        const ColorRun& r = runs_[std::size_t(run++)];
        for (int32_t p = r.first_part; p < r.first_part + r.part_count; ++p) {
            const Part& part = parts_[std::size_t(p)];
            std::memcpy(lane_contacts_.data() + std::size_t(part.first_block) * W,
                        layout.ordered + first + part.first_contact, std::size_t(part.contact_count) * sizeof(int32_t));
        }
    }
}

int32_t ContactSolver::part_first_item(int32_t run, int32_t part) const {
    const ColorRun& r = runs_[std::size_t(run)];
    return r.apart ? parts_[std::size_t(r.first_part + part)].first_item : -1;
}

template <class Piece>
void ContactSolver::for_each_piece(int32_t run, int32_t begin, int32_t end, Piece&& piece) const {
    const ColorRun& r = runs_[std::size_t(run)];
    const int32_t last = r.first_part + r.part_count;
    for (int32_t p = r.first_part; p < last && begin < end; ++p) {
        const Part& part = parts_[std::size_t(p)];
        const int32_t part_end = p + 1 < last ? parts_[std::size_t(p) + 1].first_item : r.block_count;
        if (begin < part_end) {
            const int32_t stop = std::min(end, part_end);
            piece(part.first_block + begin - part.first_item, stop - begin);
            begin = stop;
        }
    }
}

void ContactSolver::lay_out(const ContactLayout& layout) {
    fixed_state_ = layout.fixed_state;
    switch (kernels_->width) {
        case 16: lay_out_colors<16>(layout); break;
        case 8: lay_out_colors<8>(layout); break;
        case 4: lay_out_colors<4>(layout); break;
        default: lay_out_colors<1>(layout); break;
    }
    const int32_t overflow = layout.color_count - 1;
    const int32_t first = layout.color_starts[overflow], count = layout.color_starts[overflow + 1] - first;
    overflow_.resize(std::size_t(count));
    overflow_uses_.resize(std::size_t(count));
    overflow_contacts_.assign(layout.ordered + first, layout.ordered + first + count);
}

template <int W>
void ContactSolver::pack_range(const ContactLayout& layout, int32_t begin, int32_t end) {
    ContactBlock<W>* out = blocks<W>().data();
    const int32_t lane_end = end * W;
    uint8_t uses = 0;
    PackLanes<W> inputs;
    for (int32_t lane = begin * W; lane < lane_end; ++lane) {
        ContactBlock<W>& block = out[lane / W];
        if (lane % W == 0) {
            // Zeroed while its lanes are written: zeroing the whole range first streamed a
            // large world's blocks (8.8 MB in many_pyramids) through memory twice.
            std::memset(static_cast<void*>(&block), 0, sizeof(ContactBlock<W>));
        }
        const int32_t contact = lane_contacts_[std::size_t(lane)];
        if (contact >= 0) {
            prefetch_ahead(layout, lane_contacts_.data(), lane, lane_end);
            pack_lane(block, inputs, lane % W, layout.contacts[contact], layout);
            uses |= uses_of(layout.contacts[contact], layout.any_elastic);
        } else {
            pad_lane(block, inputs, lane % W, layout.fixed_state);
        }
        if (lane % W == W - 1) {
            kernels_->finish_pack(&block, &inputs);
            block_uses_[std::size_t(lane / W)] = uses;
            uses = 0;
        }
    }
}

void ContactSolver::pack(const ContactLayout& layout, int32_t run, int32_t begin, int32_t end) {
    if (run_is_sequential(run)) {
        pack_overflow(layout, begin, end);
        return;
    }
    for_each_piece(run, begin, end, [&](int32_t block, int32_t count) {
        switch (kernels_->width) {
            case 16: pack_range<16>(layout, block, block + count); break;
            case 8: pack_range<8>(layout, block, block + count); break;
            case 4: pack_range<4>(layout, block, block + count); break;
            default: pack_range<1>(layout, block, block + count); break;
        }
    });
}

void ContactSolver::pack_overflow(const ContactLayout& layout, int32_t begin, int32_t end) {
    std::memset(static_cast<void*>(overflow_.data() + begin), 0, std::size_t(end - begin) * sizeof(ContactBlock<1>));
    for (int32_t k = begin; k < end; ++k) {
        prefetch_ahead(layout, overflow_contacts_.data(), k, end);
        const Contact& contact = layout.contacts[overflow_contacts_[std::size_t(k)]];
        PackLanes<1> inputs;
        pack_lane(overflow_[std::size_t(k)], inputs, 0, contact, layout);
        scalar_contact_kernels().finish_pack(&overflow_[std::size_t(k)], &inputs);
        overflow_uses_[std::size_t(k)] = uses_of(contact, layout.any_elastic);
    }
}

int32_t ContactSolver::run_items(int32_t run) const {
    return run_is_sequential(run) ? int32_t(overflow_.size()) : runs_[std::size_t(run)].block_count;
}

ContactSolver::RunBlocks ContactSolver::overflow_blocks(int32_t first) const {
    return {&scalar_contact_kernels(), const_cast<ContactBlock<1>*>(overflow_.data() + first),
            overflow_uses_.data() + first};
}

ContactSolver::RunBlocks ContactSolver::colored_blocks(int32_t block) const {
    const std::size_t b = std::size_t(block);
    void* colored = kernels_->width == 16  ? static_cast<void*>(const_cast<ContactBlock<16>*>(blocks16_.data() + b))
                    : kernels_->width == 8 ? static_cast<void*>(const_cast<ContactBlock<8>*>(blocks8_.data() + b))
                    : kernels_->width == 4 ? static_cast<void*>(const_cast<ContactBlock<4>*>(blocks4_.data() + b))
                                           : static_cast<void*>(const_cast<ContactBlock<1>*>(blocks1_.data() + b));
    return {kernels_, colored, block_uses_.data() + b};
}

void ContactSolver::warm_start(int32_t run, int32_t begin, int32_t end, BodyState* states) const {
    if (run_is_sequential(run)) {
        const RunBlocks r = overflow_blocks(begin);
        r.kernels->warm_start(r.blocks, r.uses, end - begin, states);
        return;
    }
    for_each_piece(run, begin, end, [&](int32_t block, int32_t count) {
        const RunBlocks r = colored_blocks(block);
        r.kernels->warm_start(r.blocks, r.uses, count, states);
    });
}

void ContactSolver::solve(int32_t run, int32_t begin, int32_t end, BodyState* states, const SolvePass& pass) const {
    if (run_is_sequential(run)) {
        const RunBlocks r = overflow_blocks(begin);
        r.kernels->solve(r.blocks, r.uses, end - begin, states, pass);
        return;
    }
    for_each_piece(run, begin, end, [&](int32_t block, int32_t count) {
        const RunBlocks r = colored_blocks(block);
        r.kernels->solve(r.blocks, r.uses, count, states, pass);
    });
}

void ContactSolver::apply_restitution(int32_t run, int32_t begin, int32_t end, BodyState* states,
                                      float threshold) const {
    if (run_is_sequential(run)) {
        const RunBlocks r = overflow_blocks(begin);
        r.kernels->restitution(r.blocks, end - begin, states, threshold);
        return;
    }
    for_each_piece(run, begin, end, [&](int32_t block, int32_t count) {
        const RunBlocks r = colored_blocks(block);
        r.kernels->restitution(r.blocks, count, states, threshold);
    });
}

template <int W>
bool ContactSolver::bounces(const ContactBlock<W>* blocks, const uint8_t* uses, std::size_t count,
                            float threshold) const {
    for (std::size_t b = 0; b < count; ++b) {
        // A block whose lanes are all inelastic cannot bounce: its uses say so in a byte,
        // where reading its restitution costs a cache line.
        if ((uses[b] & block_tracks_impact) == 0) {
            continue;
        }
        const ContactBlock<W>& block = blocks[b];
        for (int lane = 0; lane < W; ++lane) {
            for (int i = 0; i < 2; ++i) {
                const ContactPointLanes<W>& p = block.points[i];
                if (block.restitution[lane] != 0.0f && p.relative_velocity[lane] < -threshold &&
                    p.max_normal_impulse[lane] != 0.0f) {
                    return true;
                }
            }
        }
    }
    return false;
}

bool ContactSolver::any_bounce(float threshold) const {
    const uint8_t* uses = block_uses_.data();
    const bool colored = kernels_->width == 16  ? bounces(blocks16_.data(), uses, blocks16_.size(), threshold)
                         : kernels_->width == 8 ? bounces(blocks8_.data(), uses, blocks8_.size(), threshold)
                         : kernels_->width == 4 ? bounces(blocks4_.data(), uses, blocks4_.size(), threshold)
                                                : bounces(blocks1_.data(), uses, blocks1_.size(), threshold);
    return colored || bounces(overflow_.data(), overflow_uses_.data(), overflow_.size(), threshold);
}

// The touching test reads each point's final separation, which the kernels compute a
// block at a time in lanes (the same arithmetic, so the same bits): computed here one lane
// at a time, it took half of large_pyramid's store.
template <int W>
void ContactSolver::store_range(const ContactKernels& kernels, const ContactBlock<W>* blocks,
                                const int32_t* contacts_of_lanes, int32_t first, int32_t end, Pool<Contact>& contacts,
                                const BodyState* states, float slop) const {
    alignas(64) float separations[2 * W];
    const int32_t lane_end = end * W;
    for (int32_t b = first; b < end; ++b) {
        const ContactBlock<W>& block = blocks[b];
        kernels.final_separations(&block, 1, states, separations);
        for (int lane = 0; lane < W; ++lane) {
            const int32_t k = b * W + lane;
            const int32_t index = contacts_of_lanes[k];
            if (index < 0) {
                continue;
            }
            const int32_t ahead = k + prefetch_contacts_ahead;
            if (ahead < lane_end && contacts_of_lanes[ahead] >= 0) {
                prefetch_solver_data(contacts[contacts_of_lanes[ahead]]);
            }
            Contact& contact = contacts[index];
            const bool hits = (contact.flags & contact_hit_events) != 0;
            for (int32_t i = 0; i < contact.point_count; ++i) {
                contact.points[i].normal_impulse = block.points[i].normal_impulse[lane];
                contact.points[i].tangent_impulse = block.points[i].tangent_impulse[lane];
                if (separations[i * W + lane] <= slop) {
                    contact.flags |= contact_touching;
                }
                // A point that pushed met at its impact speed (the speed the restitution
                // pass uses: the free approach speed when the surfaces met).
                const float approach = -block.points[i].relative_velocity[lane];
                if (hits && block.points[i].max_normal_impulse[lane] > 0.0f && approach > contact.hit_speed) {
                    contact.hit_speed = approach;
                    contact.hit_point = i;
                }
            }
            contact.rolling_impulse = block.rolling_impulse[lane];
        }
    }
}

void ContactSolver::store(Pool<Contact>& contacts, const BodyState* states, float slop, int32_t run, int32_t begin,
                          int32_t end) const {
    if (run_is_sequential(run)) {
        store_range(scalar_contact_kernels(), overflow_.data(), overflow_contacts_.data(), begin, end, contacts, states,
                    slop);
        return;
    }
    const int32_t* lanes = lane_contacts_.data();
    const ContactKernels& k = *kernels_;
    for_each_piece(run, begin, end, [&](int32_t block, int32_t count) {
        const int32_t last = block + count;
        switch (k.width) {
            case 16: store_range(k, blocks16_.data(), lanes, block, last, contacts, states, slop); break;
            case 8: store_range(k, blocks8_.data(), lanes, block, last, contacts, states, slop); break;
            case 4: store_range(k, blocks4_.data(), lanes, block, last, contacts, states, slop); break;
            default: store_range(k, blocks1_.data(), lanes, block, last, contacts, states, slop); break;
        }
    });
}

}  // namespace i2d
