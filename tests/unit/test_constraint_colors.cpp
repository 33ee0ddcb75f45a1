// SPDX-License-Identifier: MIT
// ConstraintColors: no colour but the overflow moves a body twice, contacts with a fixed
// body come after every moving pair, and a body with more contacts than colours spills
// into the overflow colour instead of breaking the rule.
#include <cstdint>
#include <vector>

#include "check.h"
#include "dynamics/solver/constraint_colors.hpp"
#include "test_rng.hpp"

using i2d::ConstraintColors;

namespace {

constexpr int32_t fixed = ConstraintColors::null_state;

struct Pair {
    int32_t a, b;
};

// Whether any colour other than the overflow moves one body twice.
bool colors_share_a_body(const std::vector<Pair>& pairs, const std::vector<int32_t>& colors, int32_t body_count) {
    std::vector<uint32_t> seen(std::size_t(body_count), 0u);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (colors[i] == ConstraintColors::overflow) {
            continue;
        }
        const uint32_t bit = 1u << colors[i];
        for (const int32_t body : {pairs[i].a, pairs[i].b}) {
            if (body == fixed) {
                continue;
            }
            if ((seen[std::size_t(body)] & bit) != 0) {
                return true;
            }
            seen[std::size_t(body)] |= bit;
        }
    }
    return false;
}

}  // namespace

I2D_TEST(unit_colors_a_chain_alternates_two_colours) {
    // Bodies 0-1-2-3-4 in a chain: each contact shares a body with the one before.
    ConstraintColors colors;
    colors.reset(5);
    const int32_t expected[] = {0, 1, 0, 1};
    for (int32_t i = 0; i < 4; ++i) {
        I2D_CHECK(colors.assign(i, i + 1) == expected[i]);
    }
}

I2D_TEST(unit_colors_fixed_contacts_come_after_moving_pairs) {
    ConstraintColors colors;
    colors.reset(3);
    const int32_t moving = colors.assign(0, 1);
    const int32_t on_ground = colors.assign(0, fixed);
    const int32_t ground_first = colors.assign(fixed, 2);
    I2D_CHECK(moving == 0);
    I2D_CHECK(on_ground == ConstraintColors::overflow - 1);
    I2D_CHECK(ground_first == ConstraintColors::overflow - 1);  // another body: same colour is free
    // A second fixed contact of body 0 (a box in a corner) takes the next colour down.
    I2D_CHECK(colors.assign(fixed, 0) == ConstraintColors::overflow - 2);
    // Two fixed sides: nothing to move; it never shares a real colour.
    I2D_CHECK(colors.assign(fixed, fixed) == ConstraintColors::overflow);
}

I2D_TEST(unit_colors_a_crowded_body_spills_into_overflow) {
    // Body 0 touches 40 others: only moving_pair_colors of those contacts fit in colours.
    ConstraintColors colors;
    colors.reset(41);
    int32_t overflowed = 0;
    for (int32_t other = 1; other <= 40; ++other) {
        const int32_t color = colors.assign(0, other);
        I2D_CHECK(color < ConstraintColors::moving_pair_colors || color == ConstraintColors::overflow);
        overflowed += color == ConstraintColors::overflow;
    }
    I2D_CHECK(overflowed == 40 - ConstraintColors::moving_pair_colors);
    // Fixed contacts of the same body: colours 22 down to 1 are all free of fixed
    // contacts, but colours below moving_pair_colors are taken by its moving pairs.
    int32_t fixed_overflowed = 0;
    for (int32_t k = 0; k < 10; ++k) {
        const int32_t color = colors.assign(0, fixed);
        I2D_CHECK(color >= ConstraintColors::moving_pair_colors);
        fixed_overflowed += color == ConstraintColors::overflow;
    }
    I2D_CHECK(fixed_overflowed == 10 - (ConstraintColors::overflow - ConstraintColors::moving_pair_colors));
}

I2D_TEST(unit_colors_random_graphs_never_share_a_body_within_a_colour) {
    TestRng rng(20261122u);
    for (int32_t round = 0; round < 50; ++round) {
        const int32_t body_count = 2 + rng.below(200);
        const int32_t pair_count = rng.below(2000);
        std::vector<Pair> pairs;
        std::vector<int32_t> assigned;
        ConstraintColors colors;
        colors.reset(body_count);
        for (int32_t i = 0; i < pair_count; ++i) {
            Pair p{rng.below(body_count), rng.below(body_count)};
            if (rng.below(4) == 0) {
                (rng.below(2) == 0 ? p.a : p.b) = fixed;
            }
            if (p.a == p.b) {
                continue;  // a contact joins two different bodies
            }
            pairs.push_back(p);
            assigned.push_back(colors.assign(p.a, p.b));
        }
        I2D_CHECK(!colors_share_a_body(pairs, assigned, body_count));
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            const bool both_move = pairs[i].a != fixed && pairs[i].b != fixed;
            I2D_CHECK(assigned[i] == ConstraintColors::overflow ||
                      (both_move ? assigned[i] < ConstraintColors::moving_pair_colors : assigned[i] >= 1));
        }
    }
}
