// SPDX-License-Identifier: MIT
// ConstraintGraph: the order the solver visits joints and contacts in, colour by colour,
// and each worker's part of every colour.
//
// Design note: joints and contacts share one colouring (constraint_colors.hpp), joints
// first, so that a colour's joints and contacts are independent of one another too. The
// colours are kept while nothing they depend on changes (the awake joints and their
// bodies' states, the awake contacts with points, the workers' shares of the bodies), so
// that a resting pile is not coloured again every step; then the contact solver's layout,
// which the workers read, is kept too (rewritten, it would leave their cores for the
// calling thread's). Within a colour, whose constraints are independent, the order changes
// no bit of a result: contacts are placed by the worker whose share holds the lowest body
// each moves, then two-point contacts before single points, then by that body.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "core/task_system.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/joint/joint.hpp"
#include "dynamics/solver/constraint_colors.hpp"

namespace i2d {

class BodyShares;
class ContactSet;
class Islands;
class JointSet;
class ShareBalance;

/// What the colouring reads; the world owns all of it.
struct GraphLinks {
    const Pool<Joint>& joints;
    const Pool<Body>& bodies;
    const JointSet& joint_set;
    const ContactSet& contacts;
    const Islands& islands;
    TaskSystem& tasks;
};

/// The joints to solve this step (those with an awake body), gathered again only when the
/// joints or the awake list changed, and what their colours depend on.
class AwakeJoints {
public:
    /// Gathers the joints again if the joints or the awake list changed since the last
    /// step; returns whether it did. A long awake list is gathered in parts by the workers
    /// and the parts joined in order: the same list as one pass over it.
    bool gather(const GraphLinks& links);
    /// Whether what the joints' colours depend on (which joint, and the states each
    /// moves), as gathered, differs from what was last coloured; if so it becomes what is
    /// coloured.
    bool take_changed_key();
    void forget() {
        gathered_ = false;
        colored_key_.clear();
    }
    /// Per awake joint: the joint, then the states it moves on sides A and B, or -1.
    const std::vector<int32_t>& colored_key() const { return colored_key_; }
    /// Whether a joint gathered last moves one of its bodies and not the other.
    bool any_joint_to_fixed() const { return any_joint_to_fixed_; }

private:
    struct Part {
        std::vector<int32_t> joints, key;
        bool any_joint_to_fixed = false;
    };
    static void gather_parts(const GraphLinks& links, AwakeJoints& self, const NoStageArg&, int32_t begin,
                             int32_t end, int32_t worker);
    void gather_part(const GraphLinks& links, int32_t part);

    bool gathered_ = false;
    bool any_joint_to_fixed_ = false;
    uint64_t joint_version_ = 0, awake_version_ = 0;
    std::vector<Part> parts_;
    std::vector<int32_t> key_, colored_key_;
    StageRunner runner_;
    std::vector<Stage> stages_;
};

class ConstraintGraph {
public:
    explicit ConstraintGraph(const GraphLinks& links) : links_(links) {}

    /// Colours the awake joints and contacts anew when anything the colours depend on
    /// changed, with the awake bodies cut into `share_count` shares (one per worker when
    /// the step is shared, else one); `workers`: the world's worker count; `parts`:
    /// whether the colours are laid out in the workers' parts. Returns whether the
    /// contacts were coloured anew.
    bool update(int32_t share_count, int32_t workers, bool parts, BodyShares& shares, ShareBalance& balance);
    /// Colour and gather afresh at the next update.
    void forget() {
        colored_ = false;
        awake_joints_.forget();
    }
    /// Whether ordered_contacts() holds a colouring: false before the first and after
    /// forget() (a restored world's contacts are not those it names).
    bool is_colored() const { return colored_; }
    /// Whether the last update gathered the joints again (their trees must be found again).
    bool joints_regathered() const { return joints_regathered_; }
    /// Whether a joint to solve moves one of its bodies and not the other (the only kind
    /// that can hold a group of joints for the exact solve).
    bool any_joint_to_fixed() const { return awake_joints_.any_joint_to_fixed(); }

    /// The joints to solve, colour by colour; per colour, where its joints begin (count +
    /// 1 entries).
    const std::vector<int32_t>& ordered_joints() const { return ordered_joints_; }
    const std::vector<int32_t>& joint_color_starts() const { return joint_color_starts_; }
    /// The contacts to solve, colour by colour; per colour, where its contacts begin.
    const std::vector<int32_t>& ordered_contacts() const { return ordered_contacts_; }
    const std::vector<int32_t>& color_starts() const { return color_starts_; }
    /// Per colour, workers + 1 entries: where each worker's part begins (ContactLayout::
    /// color_parts); empty when the colours are kept whole.
    const std::vector<int32_t>& color_parts() const { return color_parts_; }
    /// Some coloured contact is elastic: the restitution pass may run.
    bool any_elastic_contact() const { return max_restitution_ != 0.0f; }
    /// The largest restitution among the coloured contacts.
    float max_restitution() const { return max_restitution_; }

private:
    struct ColoredContact {
        int32_t contact;
        int32_t key;   // sort_key(): colour, then share, then a single point after the pairs
        int32_t body;  // the lowest state it moves; the state count if it moves none
    };
    static int32_t sort_key(int32_t share_count, int32_t color, int32_t share, bool single_point = false) {
        return 2 * (color * share_count + share) + (single_point ? 1 : 0);
    }
    void color_joints();
    void color_contacts(int32_t share_count, BodyShares& shares, ShareBalance& balance);
    void order_by_body();
    void split_colors_by_share(int32_t workers, bool parts, const BodyShares& shares);

    GraphLinks links_;
    ConstraintColors colors_;
    AwakeJoints awake_joints_;
    bool joints_regathered_ = false;
    std::vector<int8_t> joint_colors_;         // per awake joint, or -1 when it moves nothing
    std::vector<int32_t> joint_color_starts_;  // per colour: its first slot in ordered_joints_
    std::vector<int32_t> ordered_joints_;
    std::vector<ColoredContact> colored_contacts_;  // in awake order
    std::vector<ColoredContact> body_ordered_;      // the same, by body
    std::vector<int32_t> key_starts_;               // per sort key: its first slot
    std::vector<int32_t> body_starts_;              // per state: its first slot in body_ordered_
    std::vector<int32_t> color_starts_;             // per colour: its first slot in ordered_contacts_
    std::vector<int32_t> ordered_contacts_;         // the contacts to solve, colour by colour
    std::vector<int32_t> scratch_starts_;
    std::vector<int32_t> color_parts_;
    float max_restitution_ = 0.0f;  // among the coloured contacts
    // What the contacts were last coloured for.
    bool colored_ = false;
    uint64_t colored_version_ = 0;
    int32_t colored_body_count_ = 0;
};

}  // namespace i2d
