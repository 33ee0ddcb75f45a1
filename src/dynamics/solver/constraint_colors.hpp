// SPDX-License-Identifier: MIT
// ConstraintColors: the order in which the solver visits contacts (graph colouring, as
// Box2D v3 does it).
//
// A colour is a set of contacts no two of which move the same body, so that its
// contacts are independent: they can later be solved side by side (SIMD lanes,
// threads), and for the sequential solver their order within the colour no longer
// matters. The colours are solved one after the other. Contacts between two moving
// bodies take the lowest free colour, counting up from the first; contacts with a fixed
// body (static, kinematic or asleep) take the highest free colour, counting down, so
// that they are solved last in each pass and have the last word: a tall pile is held
// up by the ground instead of being pushed into it by the contacts above. Solving in
// creation order instead let the first contacts of a pass take more than their share,
// and a 100-row pyramid leaned and slid apart.
#pragma once

#include <cstdint>
#include <vector>

namespace i2d {

class ConstraintColors {
public:
    /// Colours in all; the last one takes what no other colour can (a body with more
    /// contacts than colours) and is solved last.
    static constexpr int32_t count = 24;
    static constexpr int32_t overflow = count - 1;
    /// The highest colours are kept for contacts with a fixed body.
    static constexpr int32_t moving_pair_colors = count - 4;

    /// Forgets every assignment: state_count bodies may move.
    void reset(int32_t state_count);

    /// The colour of the next contact. A side that does not move (a fixed body, or a
    /// body the contact cannot move) passes null_state and takes no colour slot.
    int32_t assign(int32_t state_a, int32_t state_b);

    static constexpr int32_t null_state = -1;

private:
    int32_t assign_moving_pair(int32_t state_a, int32_t state_b);
    int32_t assign_against_fixed(int32_t state);

    std::vector<uint32_t> used_;  // per state: bit c set when colour c already moves it
};

static_assert(ConstraintColors::count <= 32, "one bit per colour in a uint32_t");

}  // namespace i2d
