// SPDX-License-Identifier: MIT
#include "dynamics/constraint_colors.hpp"

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

int32_t ConstraintColors::assign_moving_pair(int32_t state_a, int32_t state_b) {
    const uint32_t taken = used_[std::size_t(state_a)] | used_[std::size_t(state_b)];
    for (int32_t color = 0; color < moving_pair_colors; ++color) {
        const uint32_t bit = 1u << color;
        if ((taken & bit) == 0) {
            used_[std::size_t(state_a)] |= bit;
            used_[std::size_t(state_b)] |= bit;
            return color;
        }
    }
    return overflow;
}

// Down to colour 1 for a body that touches many fixed bodies, never colour 0 (as in
// Box2D v3): a contact with a fixed body is never solved before every moving pair.
int32_t ConstraintColors::assign_against_fixed(int32_t state) {
    const uint32_t taken = used_[std::size_t(state)];
    for (int32_t color = overflow - 1; color >= 1; --color) {
        const uint32_t bit = 1u << color;
        if ((taken & bit) == 0) {
            used_[std::size_t(state)] |= bit;
            return color;
        }
    }
    return overflow;
}

}  // namespace i2d
