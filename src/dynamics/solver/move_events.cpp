// SPDX-License-Identifier: MIT
// MoveEvents: counting, placing and writing the step's body move events.
#include "dynamics/solver/move_events.hpp"

#include "dynamics/island/island.hpp"
#include "dynamics/solver/body_pass.hpp"
#include "dynamics/solver/body_shares.hpp"

namespace i2d {

void MoveEvents::begin(int32_t awake_count, int32_t share_count) {
    event_slots_.resize(std::size_t(awake_count));
    move_starts_.resize(std::size_t(share_count) + 1);
}

void MoveEvents::count(const StepContext&, MoveEvents& self, const NoStageArg&, int32_t begin, int32_t end, int32_t) {
    const int32_t* starts = self.links_.shares.starts();
    for (int32_t r = begin; r < end; ++r) {
        int32_t moved_here = 0;
        for (int32_t k = starts[r]; k < starts[r + 1]; ++k) {
            const bool moved = self.links_.body_pass.moved(k);
            self.event_slots_[std::size_t(k)] = moved ? moved_here : null_index;
            moved_here += moved ? 1 : 0;
        }
        self.move_starts_[std::size_t(r) + 1] = moved_here;
    }
}

void MoveEvents::place(const StepContext&, MoveEvents& self, const NoStageArg&, int32_t, int32_t, int32_t) {
    std::vector<BodyMoveEvent>& moves = self.links_.events.current.body_moves;
    const int32_t shares = self.links_.shares.count();
    self.move_starts_[0] = int32_t(moves.size());
    for (int32_t r = 0; r < shares; ++r) {
        self.move_starts_[std::size_t(r) + 1] += self.move_starts_[std::size_t(r)];
    }
    moves.resize(std::size_t(self.move_starts_[std::size_t(shares)]));
}

void MoveEvents::write(const StepContext&, MoveEvents& self, const NoStageArg&, int32_t begin, int32_t end, int32_t) {
    const std::vector<int32_t>& awake = self.links_.islands.awake_bodies();
    const EventRecorder& events = self.links_.events;
    BodyMoveEvent* moves = self.links_.events.current.body_moves.data();
    const int32_t* share_starts = self.links_.shares.starts();
    int32_t share = self.links_.shares.share_of(begin);
    for (int32_t k = begin; k < end; ++k) {
        while (k >= share_starts[share + 1]) {
            ++share;
        }
        const int32_t local = self.event_slots_[std::size_t(k)];
        const int32_t slot = local != null_index ? self.move_starts_[std::size_t(share)] + local : null_index;
        const int32_t index = awake[std::size_t(k)];
        Body& b = self.links_.bodies[index];
        b.move_event = slot;
        if (slot != null_index) {
            moves[slot] = {b.transform, events.ids.body_id(index, self.links_.bodies.generation(index)), b.user_data,
                           false};
        }
    }
}

}  // namespace i2d
