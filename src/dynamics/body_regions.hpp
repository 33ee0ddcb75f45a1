// SPDX-License-Identifier: MIT
// BodyRegions: the awake bodies cut into one run of consecutive states per worker, so
// that every stage of the solver gives each worker the same bodies.
//
// A shared step hands data from core to core wherever a body one worker moved in a stage
// is moved by another in the next. Split evenly, each colour's share began at a different
// body, and 2 workers handed over 12,400 body states a step in large_pyramid, 8,100 in
// many_pyramids and 168,000 in the spinner (whose body stages and colours split at
// unrelated places). Cut once, with a contact going to the region of the lowest body it
// moves, mostly the bodies that contacts across a cut reach are handed over: 3,500, 1,500
// and 13,000 (counted from the stages' shares at step 20). On a virtual machine whose
// cores trade a cache line in 120 to 480 ns, each hand-over costs far more than the
// arithmetic on the body.
#pragma once

#include <cstdint>
#include <vector>

namespace i2d {

class BodyRegions {
public:
    /// Cuts states [0, body_count) into `regions` runs of about the same work: each body
    /// weighs 1 and each contact contact_weight, on the lowest body it moves.
    /// contacts_before[b] is the number of contacts whose lowest body is below b, for b
    /// in [0, body_count].
    void cut(int32_t regions, const int32_t* contacts_before, int32_t body_count);

    int32_t count() const { return int32_t(starts_.size()) - 1; }
    /// The region of state `body`; a state past the last body is in the last region.
    int32_t region_of(int32_t body) const;
    /// Where each region begins: count() + 1 states, the last the body count.
    const int32_t* starts() const { return starts_.data(); }

    /// A contact is packed, stored, and warm started, solved and relaxed each substep
    /// (about 26 ns a substep in large_pyramid), where a body is integrated twice a
    /// substep: a rough weight is enough, since a worker that runs out of work takes
    /// over the other's last blocks.
    static constexpr int64_t contact_weight = 4;

private:
    std::vector<int32_t> starts_{0, 0};
};

}  // namespace i2d
