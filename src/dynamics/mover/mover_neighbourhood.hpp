// SPDX-License-Identifier: MIT
// MoverNeighbourhood: the shapes around one character move, gathered from the broadphase
// trees once, so that the move's many collides and casts test a short list.
//
// Design note: a move makes up to a dozen queries (a collide and a cast per slide round,
// three casts and a collide to try a step, a cast and a collide to snap), all within a
// box the move cannot leave: its length, the step and snap reach and the capsule's size.
// Walking the three trees once for that box and keeping the shapes (index and tight box)
// in a fixed array costs one tree walk instead of a dozen, and no allocation. A level
// dense enough to fill the array falls back to walking the trees for every query, which
// gives the same answers more slowly. Rejected: caching placed proxies too (72 bytes
// each, written for every shape although most are tested once or never).
#pragma once

#include <cstdint>

#include "collision/mover_contact.hpp"
#include "dynamics/world/world.hpp"

namespace i2d {

class MoverNeighbourhood {
public:
    /// Shapes gathered at most; more make every query walk the trees.
    static constexpr int32_t capacity = 64;

    MoverNeighbourhood(const World& world, const QueryFilter& filter, const AABB& box);
    MoverNeighbourhood(const MoverNeighbourhood&) = delete;
    MoverNeighbourhood& operator=(const MoverNeighbourhood&) = delete;

    struct Touch {
        int32_t shape = null_index;
        MoverContact contact;
    };
    /// The shapes within reach of the mover (world space) with their planes: up to
    /// out_capacity of them, the nearest kept when there are more. Returns how many it wrote.
    int32_t collide(const ShapeProxy& mover, float reach, Touch* out, int32_t out_capacity) const;

    struct Hit {
        float fraction = 1.0f;
        int32_t shape = null_index;  // what stopped the cast; null when nothing did
    };
    /// How far along translation the mover goes (mover_cast against each shape).
    Hit cast(const ShapeProxy& mover, Vec2 translation, float target, float tolerance) const;

private:
    template <class Visit>
    void visit(const AABB& box, Visit&& visit_shape) const;

    struct Entry {
        int32_t shape;
        AABB box;
    };
    const World& world_;
    QueryFilter filter_;
    Entry entries_[capacity];
    int32_t count_ = 0;
    bool overflowed_ = false;
};

}  // namespace i2d
