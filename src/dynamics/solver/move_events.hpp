// SPDX-License-Identifier: MIT
// MoveEvents: the body move events of a step, numbered in awake order by the workers.
//
// Design note: each moved body's event gets the next index in awake order. Each worker's
// share of the bodies (body_shares.hpp) numbers its moved bodies from 0 on that worker;
// one thread then turns the shares' counts into where their events start, and writing an
// event adds its share's start. Numbered on one thread, the events cost large_pyramid 13
// to 16 microseconds a step at 2 workers while the other worker waited.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/step_context.hpp"
#include "dynamics/world/events.hpp"

namespace i2d {

class BodyPass;
class BodyShares;
class Islands;

/// What the numbering reads and writes outside its own arrays.
struct MoveEventLinks {
    Pool<Body>& bodies;
    const Islands& islands;
    EventRecorder& events;
    const BodyPass& body_pass;
    const BodyShares& shares;
};

class MoveEvents {
public:
    explicit MoveEvents(const MoveEventLinks& links) : links_(links) {}

    /// Room for the awake bodies and the shares (one thread, before the stages).
    void begin(int32_t awake_count, int32_t share_count);

    /// Over shares [begin, end): numbers each share's moved bodies from 0.
    static void count(const StepContext& step, MoveEvents& events, const NoStageArg&, int32_t begin, int32_t end,
                      int32_t worker);
    /// One item: where each share's events start, and room for them all.
    static void place(const StepContext& step, MoveEvents& events, const NoStageArg&, int32_t begin, int32_t end,
                      int32_t worker);
    /// Over awake bodies [begin, end): each body's event index, and its event.
    static void write(const StepContext& step, MoveEvents& events, const NoStageArg&, int32_t begin, int32_t end,
                      int32_t worker);

private:
    MoveEventLinks links_;
    // Per awake body: its event's index within its share, if it moved; per share, the
    // moved bodies, then where their events start (share count + 1).
    std::vector<int32_t> event_slots_;
    std::vector<int32_t> move_starts_;
};

}  // namespace i2d
