// SPDX-License-Identifier: MIT
// The contact solver's lanes: packing contacts into blocks, running the kernels colour
// by colour, and the impulses back.
#include "dynamics/contact_solver.hpp"

#include <cstring>

#include "core/prefetch.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// 1 / (invMassA + invMassB + (rA x d)^2 invIA + (rB x d)^2 invIB), or 0 when nothing moves.
float effective_mass(const BodyMotion& a, const BodyMotion& b, Vec2 r_a, Vec2 r_b, Vec2 direction) {
    const float ra = cross(r_a, direction), rb = cross(r_b, direction);
    const float k = a.inv_mass + b.inv_mass + a.inv_inertia * ra * ra + b.inv_inertia * rb * rb;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

Vec2 relative_velocity(const BodyState& a, const BodyState& b, Vec2 r_a, Vec2 r_b) {
    return (b.linear_velocity + cross(b.angular_velocity, r_b)) - (a.linear_velocity + cross(a.angular_velocity, r_a));
}

template <int W>
void pack_point(ContactPointLanes<W>& p, int lane, const ContactPoint& cp, Vec2 normal, const BodyState& sa,
                const BodyState& sb, const BodyMotion& ma, const BodyMotion& mb) {
    p.anchor_ax[lane] = cp.anchor_a.x;
    p.anchor_ay[lane] = cp.anchor_a.y;
    p.anchor_bx[lane] = cp.anchor_b.x;
    p.anchor_by[lane] = cp.anchor_b.y;
    p.base_separation[lane] = cp.separation - dot(cp.anchor_b - cp.anchor_a, normal);
    const float speed = dot(relative_velocity(sa, sb, cp.anchor_a, cp.anchor_b), normal);
    p.relative_velocity[lane] = speed;
    p.start_speed[lane] = speed;
    p.normal_mass[lane] = effective_mass(ma, mb, cp.anchor_a, cp.anchor_b, normal);
    p.tangent_mass[lane] = effective_mass(ma, mb, cp.anchor_a, cp.anchor_b, left_perp(normal));
    p.normal_impulse[lane] = cp.normal_impulse;
    p.tangent_impulse[lane] = cp.tangent_impulse;
    p.max_normal_impulse[lane] = 0.0f;
}

// One contact into one lane. The block was zeroed: what a contact leaves out (a second
// point, padding lanes) stays zero, which the kernels read as nothing to do.
template <int W>
void pack_lane(ContactBlock<W>& block, int lane, const Contact& contact, const ContactLayout& layout) {
    const int32_t state_a = contact.state_a != null_index ? contact.state_a : layout.fixed_state;
    const int32_t state_b = contact.state_b != null_index ? contact.state_b : layout.fixed_state;
    const BodyMotion& ma = layout.motions[state_a];
    const BodyMotion& mb = layout.motions[state_b];
    const BodyState& sa = layout.states[state_a];
    const BodyState& sb = layout.states[state_b];
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
    for (int32_t i = 0; i < contact.point_count; ++i) {
        pack_point(block.points[i], lane, contact.points[i], contact.normal, sa, sb, ma, mb);
    }
}

// Contacts are read in colour order, which jumps through the contact pool: each one is
// a cache miss unless asked for ahead. The bodies' states and motions are asked for
// once the contact itself is close.
constexpr int32_t prefetch_contacts_ahead = 16;
constexpr int32_t prefetch_bodies_ahead = 4;

// The first two lines of a contact: what packing and storing touch.
I2D_FORCE_INLINE void prefetch_solver_data(const Contact& c) {
    prefetch_line(&c);
    prefetch_line(reinterpret_cast<const char*>(&c) + 64);
}

I2D_FORCE_INLINE void prefetch_bodies(const Contact& c, const ContactLayout& layout) {
    for (const int32_t state : {c.state_a, c.state_b}) {
        if (state != null_index) {
            prefetch_line(layout.states + state);
            prefetch_line(layout.motions + state);
        }
    }
}

I2D_FORCE_INLINE void prefetch_ahead(const ContactLayout& layout, int32_t index, int32_t end) {
    const int32_t contact_ahead = index + prefetch_contacts_ahead;
    if (contact_ahead < end) {
        prefetch_solver_data(layout.contacts[layout.ordered[contact_ahead]]);
    }
    const int32_t bodies_ahead = index + prefetch_bodies_ahead;
    if (bodies_ahead < end) {
        prefetch_bodies(layout.contacts[layout.ordered[bodies_ahead]], layout);
    }
}

// Separation of a lane's point where the substeps left the bodies, m.
template <int W>
float final_separation(const ContactBlock<W>& block, int lane, int i, const BodyState* states) {
    const ContactPointLanes<W>& p = block.points[i];
    const BodyState& a = states[block.state_a[lane]];
    const BodyState& b = states[block.state_b[lane]];
    const Vec2 anchor_a{p.anchor_ax[lane], p.anchor_ay[lane]}, anchor_b{p.anchor_bx[lane], p.anchor_by[lane]};
    const Vec2 moved = (b.delta_position - a.delta_position) +
                       (rotate(b.delta_rotation, anchor_b) - rotate(a.delta_rotation, anchor_a));
    return dot(moved, Vec2{block.normal_x[lane], block.normal_y[lane]}) + p.base_separation[lane];
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

// Colour by colour, each colour's contacts W to a block, the last block padded.
template <int W>
void ContactSolver::pack_colors(const ContactLayout& layout) {
    const int32_t colors = layout.color_count - 1;
    color_block_starts_.assign(std::size_t(colors) + 1, 0);
    for (int32_t c = 0; c < colors; ++c) {
        const int32_t count = layout.color_starts[c + 1] - layout.color_starts[c];
        color_block_starts_[std::size_t(c) + 1] = color_block_starts_[std::size_t(c)] + (count + W - 1) / W;
    }
    std::vector<ContactBlock<W>>& out = blocks<W>();
    out.resize(std::size_t(color_block_starts_[std::size_t(colors)]));
    if (!out.empty()) {
        std::memset(static_cast<void*>(out.data()), 0, out.size() * sizeof(ContactBlock<W>));
    }
    lane_contacts_.assign(out.size() * W, -1);
    runs_.clear();
    for (int32_t c = 0; c < colors; ++c) {
        const int32_t first = layout.color_starts[c], count = layout.color_starts[c + 1] - first;
        const int32_t first_lane = color_block_starts_[std::size_t(c)] * W;
        const int32_t lanes = (count + W - 1) / W * W;
        if (count > 0) {
            runs_.push_back({color_block_starts_[std::size_t(c)], lanes / W});
        }
        for (int32_t k = 0; k < lanes; ++k) {
            ContactBlock<W>& block = out[std::size_t((first_lane + k) / W)];
            if (k < count) {
                const int32_t contact = layout.ordered[first + k];
                prefetch_ahead(layout, first + k, layout.color_starts[layout.color_count]);
                pack_lane(block, k % W, layout.contacts[contact], layout);
                lane_contacts_[std::size_t(first_lane + k)] = contact;
            } else {
                block.state_a[k % W] = block.state_b[k % W] = layout.fixed_state;
            }
        }
    }
}

void ContactSolver::pack_overflow(const ContactLayout& layout) {
    const int32_t overflow = layout.color_count - 1;
    const int32_t first = layout.color_starts[overflow], count = layout.color_starts[overflow + 1] - first;
    overflow_.resize(std::size_t(count));
    if (count > 0) {
        std::memset(static_cast<void*>(overflow_.data()), 0, overflow_.size() * sizeof(ContactBlock<1>));
    }
    overflow_contacts_.assign(layout.ordered + first, layout.ordered + first + count);
    for (int32_t k = 0; k < count; ++k) {
        prefetch_ahead(layout, first + k, first + count);
        pack_lane(overflow_[std::size_t(k)], 0, layout.contacts[overflow_contacts_[std::size_t(k)]], layout);
    }
}

void ContactSolver::prepare(const ContactLayout& layout) {
    switch (kernels_->width) {
        case 16: pack_colors<16>(layout); break;
        case 8: pack_colors<8>(layout); break;
        case 4: pack_colors<4>(layout); break;
        default: pack_colors<1>(layout); break;
    }
    pack_overflow(layout);
}

// The colours in order, then the overflow colour one contact at a time: stage(kernels,
// blocks, count).
template <class Stage>
void ContactSolver::for_each_color(Stage&& stage) {
    void* colored = kernels_->width == 16  ? static_cast<void*>(blocks16_.data())
                    : kernels_->width == 8 ? static_cast<void*>(blocks8_.data())
                    : kernels_->width == 4 ? static_cast<void*>(blocks4_.data())
                                           : static_cast<void*>(blocks1_.data());
    const std::size_t block_bytes = kernels_->width == 16  ? sizeof(ContactBlock<16>)
                                    : kernels_->width == 8 ? sizeof(ContactBlock<8>)
                                    : kernels_->width == 4 ? sizeof(ContactBlock<4>)
                                                           : sizeof(ContactBlock<1>);
    for (const ColorRun& run : runs_) {
        stage(*kernels_, static_cast<char*>(colored) + block_bytes * std::size_t(run.first_block), run.block_count);
    }
    if (!overflow_.empty()) {
        stage(scalar_contact_kernels(), static_cast<void*>(overflow_.data()), int32_t(overflow_.size()));
    }
}

void ContactSolver::warm_start(BodyState* states) {
    for_each_color([states](const ContactKernels& k, void* blocks, int32_t count) { k.warm_start(blocks, count, states); });
}

void ContactSolver::solve(BodyState* states, const SolvePass& pass) {
    for_each_color(
        [states, &pass](const ContactKernels& k, void* blocks, int32_t count) { k.solve(blocks, count, states, pass); });
}

template <int W>
bool ContactSolver::any_bounce(const std::vector<ContactBlock<W>>& blocks, float threshold) const {
    for (const ContactBlock<W>& block : blocks) {
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

// Only when something bounces, and then over every contact that pushed, a few times.
void ContactSolver::apply_restitution(BodyState* states, float threshold) {
    const bool colored = kernels_->width == 16  ? any_bounce(blocks16_, threshold)
                         : kernels_->width == 8 ? any_bounce(blocks8_, threshold)
                         : kernels_->width == 4 ? any_bounce(blocks4_, threshold)
                                                : any_bounce(blocks1_, threshold);
    if (!colored && !any_bounce(overflow_, threshold)) {
        return;
    }
    constexpr int32_t restitution_iterations = 4;
    for (int32_t iteration = 0; iteration < restitution_iterations; ++iteration) {
        for_each_color([states, threshold](const ContactKernels& k, void* blocks, int32_t count) {
            k.restitution(blocks, count, states, threshold);
        });
    }
}

template <int W>
void ContactSolver::store_blocks(const std::vector<ContactBlock<W>>& blocks, const std::vector<int32_t>& contacts_of_lanes,
                                 Pool<Contact>& contacts, const BodyState* states, float slop) const {
    for (std::size_t k = 0; k < contacts_of_lanes.size(); ++k) {
        const int32_t index = contacts_of_lanes[k];
        if (index < 0) {
            continue;
        }
        const std::size_t ahead = k + std::size_t(prefetch_contacts_ahead);
        if (ahead < contacts_of_lanes.size() && contacts_of_lanes[ahead] >= 0) {
            prefetch_solver_data(contacts[contacts_of_lanes[ahead]]);
        }
        const ContactBlock<W>& block = blocks[k / W];
        const int lane = int(k % W);
        Contact& contact = contacts[index];
        for (int32_t i = 0; i < contact.point_count; ++i) {
            contact.points[i].normal_impulse = block.points[i].normal_impulse[lane];
            contact.points[i].tangent_impulse = block.points[i].tangent_impulse[lane];
            if (final_separation(block, lane, i, states) <= slop) {
                contact.flags |= contact_touching;
            }
        }
        contact.rolling_impulse = block.rolling_impulse[lane];
    }
}

void ContactSolver::store(Pool<Contact>& contacts, const BodyState* states, float slop) const {
    switch (kernels_->width) {
        case 16: store_blocks(blocks16_, lane_contacts_, contacts, states, slop); break;
        case 8: store_blocks(blocks8_, lane_contacts_, contacts, states, slop); break;
        case 4: store_blocks(blocks4_, lane_contacts_, contacts, states, slop); break;
        default: store_blocks(blocks1_, lane_contacts_, contacts, states, slop); break;
    }
    store_blocks(overflow_, overflow_contacts_, contacts, states, slop);
}

}  // namespace i2d
