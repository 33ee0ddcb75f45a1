// SPDX-License-Identifier: MIT
// ConstraintGraph: gathering the awake joints, colouring joints and contacts, laying them
// out colour by colour and cutting each colour into the workers' parts.
#include "dynamics/solver/constraint_graph.hpp"

#include "core/assert.hpp"
#include "core/prefetch.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "dynamics/solver/body_shares.hpp"

namespace i2d {

namespace {

// An awake list is gathered in parts when it is at least this long and several workers
// share the step: rain's 9,500 awake ragdoll bodies took 0.16 ms on one thread, every step
// that a ragdoll fell asleep or woke.
constexpr int32_t min_bodies_to_share_gathering = 1024;
constexpr int32_t gathering_parts_per_worker = 4;

}  // namespace

bool AwakeJoints::gather(const GraphLinks& links) {
    const uint64_t joint_version = links.joint_set.version(), awake_version = links.islands.awake_version();
    if (gathered_ && joint_version == joint_version_ && awake_version == awake_version_) {
        return false;
    }
    gathered_ = true;
    joint_version_ = joint_version;
    awake_version_ = awake_version;
    const int32_t workers = links.tasks.worker_count();
    const bool shared = workers > 1 && int32_t(links.islands.awake_bodies().size()) >= min_bodies_to_share_gathering;
    const int32_t part_count = shared ? workers * gathering_parts_per_worker : 1;
    parts_.resize(std::size_t(part_count));
    if (shared) {
        stages_.assign(1, make_stage<&AwakeJoints::gather_parts>(*this, NoStageArg{}, part_count, workers, true, 1));
        runner_.run(links.tasks, stages_, true, &links);
    } else {
        gather_part(links, 0);
    }
    key_.clear();
    any_joint_to_fixed_ = false;
    for (const Part& part : parts_) {
        key_.insert(key_.end(), part.key.begin(), part.key.end());
        any_joint_to_fixed_ = any_joint_to_fixed_ || part.any_joint_to_fixed;
    }
    return true;
}

void AwakeJoints::gather_parts(const GraphLinks& links, AwakeJoints& self, const NoStageArg&, int32_t begin,
                               int32_t end, int32_t) {
    for (int32_t part = begin; part < end; ++part) {
        self.gather_part(links, part);
    }
}

// The joints of one part of the awake list, and their key.
void AwakeJoints::gather_part(const GraphLinks& links, int32_t part) {
    const std::vector<int32_t>& awake = links.islands.awake_bodies();
    const int64_t count = int64_t(awake.size()), parts = int64_t(parts_.size());
    const int32_t* first = awake.data() + count * part / parts;
    const int32_t* last = awake.data() + count * (part + 1) / parts;
    Part& p = parts_[std::size_t(part)];
    p.joints.clear();
    links.joint_set.gather_awake(first, last, p.joints);
    p.key.clear();
    p.any_joint_to_fixed = false;
    for (const int32_t joint : p.joints) {
        const JointDef& d = links.joints[joint].def;
        const Body& a = links.bodies[d.body_a];
        const Body& b = links.bodies[d.body_b];
        const bool a_moves = d.type != JointType::mouse && a.type == BodyType::dynamic;
        const bool b_moves = b.type == BodyType::dynamic;
        const int32_t state_a = a_moves ? a.awake_index : null_index;
        const int32_t state_b = b_moves ? b.awake_index : null_index;
        p.key.push_back(joint);
        p.key.push_back(state_a);
        p.key.push_back(state_b);
        p.any_joint_to_fixed = p.any_joint_to_fixed || ((state_a == null_index) != (state_b == null_index));
    }
}

bool AwakeJoints::take_changed_key() {
    if (key_ == colored_key_) {
        return false;
    }
    colored_key_.swap(key_);
    return true;
}

bool ConstraintGraph::update(int32_t share_count, int32_t workers, bool parts, BodyShares& shares,
                             ShareBalance& balance) {
    // The joints to solve change only with the joints or the awake list.
    joints_regathered_ = awake_joints_.gather(links_);
    const bool joints_differ = joints_regathered_ && awake_joints_.take_changed_key();
    const uint64_t version = links_.contacts.layout_version();
    const int32_t awake_bodies = int32_t(links_.islands.awake_bodies().size());
    if (colored_ && version == colored_version_ && awake_bodies == colored_body_count_ && !joints_differ &&
        share_count == shares.count() && (share_count == 1 || !balance.wants_cut())) {
        return false;  // nothing the colours depend on changed: a resting pile keeps them
    }
    colored_ = true;
    colored_version_ = version;
    colored_body_count_ = awake_bodies;
    colors_.reset(awake_bodies);
    color_joints();
    color_contacts(share_count, shares, balance);
    split_colors_by_share(workers, parts, shares);
    return true;
}

// The joints' colours, before the contacts take theirs, laid out colour by colour in
// gathering order. A joint that moves no body (both sides fixed) is not solved.
void ConstraintGraph::color_joints() {
    const std::vector<int32_t>& key = awake_joints_.colored_key();
    const std::size_t count = key.size() / 3;
    joint_colors_.resize(count);
    joint_color_starts_.assign(ConstraintColors::count + 1, 0);
    for (std::size_t k = 0; k < count; ++k) {
        const int32_t a = key[3 * k + 1], b = key[3 * k + 2];
        int32_t color = -1;
        if (a != null_index || b != null_index) {
            color = colors_.assign(a != null_index ? a : ConstraintColors::null_state,
                                   b != null_index ? b : ConstraintColors::null_state);
            ++joint_color_starts_[std::size_t(color) + 1];
        }
        joint_colors_[k] = int8_t(color);
    }
    for (int32_t color = 0; color < ConstraintColors::count; ++color) {
        joint_color_starts_[std::size_t(color) + 1] += joint_color_starts_[std::size_t(color)];
    }
    ordered_joints_.resize(std::size_t(joint_color_starts_[ConstraintColors::count]));
    scratch_starts_.assign(joint_color_starts_.begin(), joint_color_starts_.end() - 1);
    for (std::size_t k = 0; k < count; ++k) {
        const int32_t color = joint_colors_[k];
        if (color >= 0) {
            ordered_joints_[std::size_t(scratch_starts_[std::size_t(color)]++)] = key[3 * k];
        }
    }
}

// A colour for every awake contact the solver will see, then the contacts laid out
// colour by colour, the order they are solved in. Within a colour, whose contacts are
// independent, the contacts of each worker's share (that of the lowest body a contact
// moves) come in the order of the shares, so that each worker's part of every colour
// moves its own bodies. Within a share, two-point contacts come first, so that SIMD
// blocks hold one kind and blocks of single points skip the second, and each kind is in
// the order of the lowest body it moves (order_by_body). The overflow colour is solved in
// sequence and keeps awake order. A body the contact cannot move (static, kinematic,
// asleep) takes no colour slot. Only contacts with points are read (ContactSet::solvable):
// most of a tumbling heap's have none.
void ConstraintGraph::color_contacts(int32_t share_count, BodyShares& shares, ShareBalance& balance) {
    const std::vector<int32_t>& solvable = links_.contacts.solvable();
    const Pool<Contact>& contacts = links_.contacts.pool();
    colored_contacts_.clear();
    body_starts_.assign(std::size_t(colored_body_count_) + 2, 0);
    max_restitution_ = 0.0f;
    // The list jumps through the contact pool: ask for contacts ahead.
    constexpr std::size_t contacts_ahead = 32;
    for (std::size_t k = 0; k < solvable.size(); ++k) {
        if (k + contacts_ahead < solvable.size()) {
            prefetch_line(&contacts[solvable[k + contacts_ahead]]);
        }
        const Contact& contact = contacts[solvable[k]];
        I2D_ASSERT(is_solvable(contact));
        const int32_t color =
            colors_.assign((contact.flags & contact_moves_a) ? contact.state_a : ConstraintColors::null_state,
                           (contact.flags & contact_moves_b) ? contact.state_b : ConstraintColors::null_state);
        max_restitution_ = max_of(max_restitution_, contact.restitution);
        const bool single_after_pairs = color != ConstraintColors::overflow && contact.point_count == 1;
        const int32_t a = (contact.flags & contact_moves_a) ? contact.state_a : colored_body_count_;
        const int32_t b = (contact.flags & contact_moves_b) ? contact.state_b : colored_body_count_;
        const int32_t lowest = a < b ? a : b;
        // The key until the shares are cut: the colour and the kind.
        colored_contacts_.push_back({solvable[k], 2 * color + (single_after_pairs ? 1 : 0), lowest});
        ++body_starts_[std::size_t(lowest) + 1];
    }
    for (int32_t k = 0; k <= colored_body_count_; ++k) {
        body_starts_[std::size_t(k) + 1] += body_starts_[std::size_t(k)];
    }
    shares.cut(share_count, body_starts_.data(), colored_body_count_, balance.fractions(share_count));
    if (share_count > 1) {
        balance.cut_made();
    }
    const int32_t key_count = sort_key(share_count, ConstraintColors::count, 0);
    key_starts_.assign(std::size_t(key_count) + 1, 0);
    for (ColoredContact& c : colored_contacts_) {
        const int32_t color = c.key / 2;
        const int32_t share = color == ConstraintColors::overflow ? 0 : shares.share_of(c.body);
        c.key = sort_key(share_count, color, share, (c.key & 1) != 0);
        ++key_starts_[std::size_t(c.key) + 1];
    }
    for (int32_t key = 0; key < key_count; ++key) {
        key_starts_[std::size_t(key) + 1] += key_starts_[std::size_t(key)];
    }
    color_starts_.resize(ConstraintColors::count + 1);
    for (int32_t color = 0; color <= ConstraintColors::count; ++color) {
        color_starts_[std::size_t(color)] = key_starts_[std::size_t(sort_key(share_count, color, 0))];
    }
    ordered_contacts_.resize(colored_contacts_.size());
    order_by_body();
    std::vector<int32_t>& next = scratch_starts_;
    next.assign(key_starts_.begin(), key_starts_.end() - 1);
    const int32_t overflow_key = sort_key(share_count, ConstraintColors::overflow, 0);
    for (const ColoredContact& c : body_ordered_) {
        if (c.key != overflow_key) {
            ordered_contacts_[std::size_t(next[std::size_t(c.key)]++)] = c.contact;
        }
    }
    for (const ColoredContact& c : colored_contacts_) {
        if (c.key == overflow_key) {
            ordered_contacts_[std::size_t(next[std::size_t(c.key)]++)] = c.contact;
        }
    }
}

// The coloured contacts by the lowest body each moves (the scatter of a counting sort
// whose counts color_contacts made). Each worker solves a contiguous share of every
// colour, so in this order its shares of all colours move mostly the same bodies, whose
// states then stay in its core's cache. In awake order, 2 workers both moved 1237 of the
// tumbler's 1969 touched bodies, 4285 of the spinner's 6013 and 1233 of rain's 2739; in
// this order 170, 1235 and 181. The spinner steps 4 % faster with 1 worker and with 2
// (paired runs).
void ConstraintGraph::order_by_body() {
    std::vector<int32_t>& next = scratch_starts_;
    next.assign(body_starts_.begin(), body_starts_.end() - 1);
    body_ordered_.resize(colored_contacts_.size());
    for (const ColoredContact& c : colored_contacts_) {
        body_ordered_[std::size_t(next[std::size_t(c.body)]++)] = c;
    }
}

// Where each worker's part of each colour begins, in its contacts: the first contact of
// the worker's share. Colours with joints (their runs are ordered by joint, not by body)
// and the overflow colour are kept whole, and so are all when the step runs on one thread.
void ConstraintGraph::split_colors_by_share(int32_t workers, bool parts, const BodyShares& shares) {
    const std::size_t stride = std::size_t(workers) + 1;
    color_parts_.clear();
    if (!parts || shares.count() != workers) {
        return;
    }
    const int32_t share_count = shares.count();
    color_parts_.assign(std::size_t(ConstraintColors::count) * stride, -1);
    for (int32_t color = 0; color < ConstraintColors::overflow; ++color) {
        const int32_t first = key_starts_[std::size_t(sort_key(share_count, color, 0))];
        const int32_t count = key_starts_[std::size_t(sort_key(share_count, color + 1, 0))] - first;
        const bool has_joints = joint_color_starts_[std::size_t(color) + 1] > joint_color_starts_[std::size_t(color)];
        if (count == 0 || has_joints) {
            continue;
        }
        int32_t* starts = color_parts_.data() + std::size_t(color) * stride;
        for (int32_t w = 0; w <= workers; ++w) {
            starts[w] = key_starts_[std::size_t(sort_key(share_count, color, w))] - first;
        }
    }
}

}  // namespace i2d
