// SPDX-License-Identifier: MIT
#include "dynamics/solver/constraint_colors.hpp"

#include "core/bits.hpp"

namespace i2d {

void ConstraintColors::reset(int32_t state_count) {
    used_.assign(std::size_t(state_count), 0u);
}

int32_t ConstraintColors::assign(int32_t state_a, int32_t state_b) {
    if (state_a != null_state && state_b != null_state) {
        return assign_moving_pair(state_a, state_b);
    }
    if (state_a != null_state) {
        return assign_against_fixed(state_a);
    }
    if (state_b != null_state) {
        return assign_against_fixed(state_b);
    }
    return overflow;
}

// The lowest colour free for both bodies.
int32_t ConstraintColors::assign_moving_pair(int32_t state_a, int32_t state_b) {
    constexpr uint32_t moving_pair_mask = (1u << moving_pair_colors) - 1u;
    const uint32_t free = ~(used_[std::size_t(state_a)] | used_[std::size_t(state_b)]) & moving_pair_mask;
    if (free == 0u) {
        return overflow;
    }
    const int32_t color = lowest_set_bit(free);
    used_[std::size_t(state_a)] |= 1u << color;
    used_[std::size_t(state_b)] |= 1u << color;
    return color;
}

// The highest free colour below the overflow colour, down to colour 1 for a body that
// touches many fixed bodies, never colour 0 (as in Box2D v3): a contact with a fixed
// body is never solved before every moving pair.
int32_t ConstraintColors::assign_against_fixed(int32_t state) {
    constexpr uint32_t against_fixed_mask = ((1u << overflow) - 1u) & ~1u;
    const uint32_t free = ~used_[std::size_t(state)] & against_fixed_mask;
    if (free == 0u) {
        return overflow;
    }
    const int32_t color = highest_set_bit(free);
    used_[std::size_t(state)] |= 1u << color;
    return color;
}

}  // namespace i2d
