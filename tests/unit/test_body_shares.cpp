// SPDX-License-Identifier: MIT
// BodyShares: the cuts split the work (a body 1, a contact contact_weight on its lowest
// body) as evenly as whole bodies allow, or in the shares asked for, every body falls in
// the share whose run holds it, and more shares than bodies leave some empty rather than
// fail. ShareBalance: a faster worker's share grows to its speed, within the tilt allowed,
// and a new cut is asked for only past the threshold and the runs between cuts.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "check.h"
#include "dynamics/solver/body_shares.hpp"

using i2d::BodyShares;
using i2d::ShareBalance;

namespace {

// contacts_before for `per_body` contacts on each body's lowest slot.
std::vector<int32_t> contacts_before(const std::vector<int32_t>& per_body) {
    std::vector<int32_t> before(per_body.size() + 1, 0);
    for (std::size_t b = 0; b < per_body.size(); ++b) {
        before[b + 1] = before[b] + per_body[b];
    }
    return before;
}

int64_t work_of(const std::vector<int32_t>& per_body, int32_t begin, int32_t end) {
    int64_t work = 0;
    for (int32_t b = begin; b < end; ++b) {
        work += 1 + BodyShares::contact_weight * per_body[std::size_t(b)];
    }
    return work;
}

// The heaviest body: no cut can split the work more evenly than that.
int64_t heaviest_body(const std::vector<int32_t>& per_body) {
    int64_t heaviest = 0;
    for (std::size_t b = 0; b < per_body.size(); ++b) {
        heaviest = std::max<int64_t>(heaviest, work_of(per_body, int32_t(b), int32_t(b) + 1));
    }
    return heaviest;
}

// Notes `runs` runs in which each worker ran `blocks` blocks at its own speed (ticks per
// block).
void note_runs(ShareBalance& balance, const std::vector<uint64_t>& ticks_per_block, int32_t runs,
               int32_t blocks = 100) {
    std::vector<i2d::StageRunner::WorkerTime> times;
    for (const uint64_t ticks : ticks_per_block) {
        times.push_back({blocks, uint64_t(blocks) * ticks});
    }
    for (int32_t run = 0; run < runs; ++run) {
        balance.note_run(times.data(), int32_t(times.size()));
    }
}

}  // namespace

I2D_TEST(unit_body_shares_cut_in_the_shares_asked_for) {
    const std::vector<int32_t> per_body(2000, 1);
    const std::vector<int32_t> before = contacts_before(per_body);
    const int64_t total = work_of(per_body, 0, 2000);
    const int64_t body = 1 + BodyShares::contact_weight;
    const double shares[] = {0.3, 0.5, 0.2};
    BodyShares cut;
    cut.cut(3, before.data(), 2000, shares);
    for (int32_t r = 0; r < 3; ++r) {
        const int64_t share = work_of(per_body, cut.starts()[r], cut.starts()[r + 1]);
        I2D_CHECK(std::llabs(share - int64_t(shares[r] * double(total))) <= 2 * body);
    }
    I2D_CHECK(cut.starts()[3] == 2000);
}

I2D_TEST(unit_share_balance_gives_the_faster_worker_more) {
    ShareBalance balance;
    I2D_CHECK(balance.fractions(2) == nullptr);  // nothing noted yet
    // Worker 1 runs a block in half the time of worker 0: two thirds of the work.
    note_runs(balance, {200, 100}, 60);
    const double* shares = balance.fractions(2);
    I2D_REQUIRE(shares != nullptr);
    I2D_CHECK(std::fabs(shares[0] - 1.0 / 3.0) < 0.01);
    I2D_CHECK(std::fabs(shares[0] + shares[1] - 1.0) < 1e-9);
    I2D_CHECK(balance.fractions(3) == nullptr);
    I2D_CHECK(balance.wants_cut());
    balance.cut_made();
    I2D_CHECK(!balance.wants_cut());
    // A worker ten times slower keeps the least share allowed.
    ShareBalance tilted;
    note_runs(tilted, {1000, 100}, 60);
    I2D_CHECK(std::fabs(tilted.fractions(2)[0] - (1.0 - ShareBalance::max_tilt) / 2.0) < 1e-9);
}

I2D_TEST(unit_share_balance_waits_for_runs_and_a_real_difference) {
    ShareBalance same;
    note_runs(same, {100, 101, 99}, 100);
    I2D_CHECK(!same.wants_cut());  // within the threshold
    ShareBalance early;
    note_runs(early, {300, 100}, ShareBalance::runs_between_cuts - 1);
    I2D_CHECK(!early.wants_cut());  // not yet
    note_runs(early, {300, 100}, 1);
    I2D_CHECK(early.wants_cut());
    // A worker that ran no block (its task started after the others had finished) says
    // nothing of its speed: the shares stay where the runs with both put them.
    ShareBalance idle;
    note_runs(idle, {100, 100}, 40);
    const i2d::StageRunner::WorkerTime times[] = {{100, 10000}, {0, 0}};
    for (int32_t run = 0; run < 40; ++run) {
        idle.note_run(times, 2);
    }
    I2D_CHECK(std::fabs(idle.fractions(2)[0] - 0.5) < 1e-9);
}

I2D_TEST(unit_body_shares_share_the_work_within_one_body) {
    // Contacts crowded at the start (a pile on the ground, then falling bodies).
    std::vector<int32_t> per_body(1000, 0);
    for (int32_t b = 0; b < 300; ++b) {
        per_body[std::size_t(b)] = 3;
    }
    const std::vector<int32_t> before = contacts_before(per_body);
    const int64_t total = work_of(per_body, 0, 1000);
    for (const int32_t shares : {1, 2, 3, 4, 8}) {
        BodyShares cut;
        cut.cut(shares, before.data(), 1000);
        I2D_CHECK(cut.count() == shares);
        I2D_CHECK(cut.starts()[0] == 0 && cut.starts()[shares] == 1000);
        for (int32_t r = 0; r < shares; ++r) {
            const int64_t share = work_of(per_body, cut.starts()[r], cut.starts()[r + 1]);
            I2D_CHECK(std::llabs(share * shares - total) <= int64_t(shares) * (heaviest_body(per_body) + 1));
        }
    }
    // The pile is cut, not shared evenly by body count: with 2 shares the cut is
    // inside the 300 bodies that carry 3,900 of the 4,600 work.
    BodyShares two;
    two.cut(2, before.data(), 1000);
    I2D_CHECK(two.starts()[1] > 0 && two.starts()[1] < 300);
}

I2D_TEST(unit_body_shares_place_every_body_in_the_run_that_holds_it) {
    const std::vector<int32_t> per_body = {0, 5, 0, 0, 9, 1, 1, 0, 2, 0, 0, 0, 4};
    const std::vector<int32_t> before = contacts_before(per_body);
    const int32_t bodies = int32_t(per_body.size());
    for (const int32_t shares : {1, 2, 3, 5}) {
        BodyShares cut;
        cut.cut(shares, before.data(), bodies);
        for (int32_t b = 0; b < bodies; ++b) {
            const int32_t r = cut.share_of(b);
            I2D_CHECK(r >= 0 && r < shares);
            I2D_CHECK(cut.starts()[r] <= b && b < cut.starts()[r + 1]);
        }
        I2D_CHECK(cut.share_of(bodies) == shares - 1);  // a contact that moves no body
    }
}

I2D_TEST(unit_body_shares_leave_shares_empty_when_bodies_are_few) {
    const std::vector<int32_t> per_body = {2, 0, 1};
    const std::vector<int32_t> before = contacts_before(per_body);
    BodyShares cut;
    cut.cut(8, before.data(), 3);
    I2D_CHECK(cut.count() == 8);
    for (int32_t r = 0; r < 8; ++r) {
        I2D_CHECK(cut.starts()[r] <= cut.starts()[r + 1]);
    }
    I2D_CHECK(cut.starts()[8] == 3);
    BodyShares none;
    none.cut(2, before.data(), 0);
    I2D_CHECK(none.starts()[0] == 0 && none.starts()[1] == 0 && none.starts()[2] == 0);
}
