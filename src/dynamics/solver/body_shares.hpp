// SPDX-License-Identifier: MIT
// BodyShares: the awake bodies cut into one share of consecutive states per worker, so
// that every stage of the solver gives each worker the same bodies; ShareBalance: how
// much of the work each share gets, from the workers' speeds.
//
// A shared step hands data from core to core wherever a body one worker moved in a stage
// is moved by another in the next. Split evenly, each colour's share began at a different
// body, and 2 workers handed over 12,400 body states a step in large_pyramid, 8,100 in
// many_pyramids and 168,000 in the spinner (whose body stages and colours split at
// unrelated places). Cut once, with a contact going to the share of the lowest body it
// moves, mostly the bodies that contacts across a cut reach are handed over: 3,500, 1,500
// and 13,000 (counted from the stages' shares at step 20). On a virtual machine whose
// cores trade a cache line in 120 to 480 ns, each hand-over costs far more than the
// arithmetic on the body.
#pragma once

#include <cstdint>
#include <vector>

#include "core/stage_runner.hpp"

namespace i2d {

class BodyShares {
public:
    /// Cuts states [0, body_count) into `count` shares of work: each body weighs 1 and
    /// each contact contact_weight, on the lowest body it moves. contacts_before[b] is the
    /// number of contacts whose lowest body is below b, for b in [0, body_count]. Share s
    /// gets fractions[s] of the work (`count` fractions summing to 1), or an even part
    /// when fractions is null.
    void cut(int32_t count, const int32_t* contacts_before, int32_t body_count, const double* fractions = nullptr);

    int32_t count() const { return int32_t(starts_.size()) - 1; }
    /// The share that holds state `body`; a state past the last body is in the last share.
    /// Asked for every coloured contact: inline, and a scan, since shares are few.
    int32_t share_of(int32_t body) const {
        int32_t share = 0;
        const int32_t last = count() - 1;
        while (share < last && starts_[std::size_t(share) + 1] <= body) {
            ++share;
        }
        return share;
    }
    /// Where each share begins: count() + 1 states, the last the body count.
    const int32_t* starts() const { return starts_.data(); }

    /// A contact is packed, stored, and warm started, solved and relaxed each substep
    /// (about 26 ns a substep in large_pyramid), where a body is integrated twice a
    /// substep: a rough weight is enough, since a worker that runs out of work takes
    /// over the other's last blocks.
    static constexpr int64_t contact_weight = 4;

private:
    std::vector<int32_t> starts_{0, 0};
};

/// Each worker's share of the work, from how fast it ran its blocks. On a shared machine
/// one vCPU can run a third slower than the other for minutes (its core busy with another
/// guest), and which one changes. Cut evenly, every stage then waits for the slower
/// worker, or the faster one takes over its last blocks, whose data it must fetch from the
/// other core (and hand back in the next colour). Cut by speed, the stages end together.
/// Timing decides only which worker moves which bodies: the order of a colour's contacts
/// changes no bit of a result, so the world's results stay the same for any cut.
class ShareBalance {
public:
    /// Notes what each of `workers` workers did in a run (StageRunner::worker_times).
    /// Workers that ran no block are left out.
    void note_run(const StageRunner::WorkerTime* times, int32_t workers);
    /// Each of `workers` workers' fraction of the work, summing to 1; null unless the
    /// runs noted had that many workers.
    const double* fractions(int32_t workers) const {
        return int32_t(fractions_.size()) == workers ? fractions_.data() : nullptr;
    }
    /// Whether the fractions moved far enough from those of the last cut to cut again.
    bool wants_cut() const;
    /// The shares were cut with fractions().
    void cut_made();

    /// The weight of a run's speeds against those before: over about 10 runs.
    static constexpr double smoothing = 0.1;
    /// A fraction moves at most this far from even (of an even fraction): a worker that
    /// was descheduled for a run does not lose its share.
    static constexpr double max_tilt = 0.5;
    /// A new cut needs a fraction this far from the last cut's (of the whole work)...
    static constexpr double cut_threshold = 0.03;
    /// ... and this many runs since: a cut rewrites the solver's layout.
    static constexpr int32_t runs_between_cuts = 30;

private:
    std::vector<double> rates_;  // per worker: blocks per unit of busy time, smoothed
    std::vector<double> fractions_, cut_fractions_;
    int32_t runs_since_cut_ = 0;
};

}  // namespace i2d
