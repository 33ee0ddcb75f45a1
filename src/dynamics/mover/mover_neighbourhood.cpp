// SPDX-License-Identifier: MIT
// The shapes around a character move and its queries over them (mover_neighbourhood.hpp).
#include "dynamics/mover/mover_neighbourhood.hpp"

namespace i2d {

MoverNeighbourhood::MoverNeighbourhood(const World& world, const QueryFilter& filter, const AABB& box)
    : world_(world), filter_(filter) {
    world.visit_mover_shapes(box, filter, [&](int32_t shape) {
        if (count_ == capacity) {
            overflowed_ = true;
            return false;
        }
        entries_[count_++] = Entry{shape, world.shapes()[shape].aabb};
        return true;
    });
}

template <class Visit>
void MoverNeighbourhood::visit(const AABB& box, Visit&& visit_shape) const {
    if (overflowed_) {
        world_.visit_mover_shapes(box, filter_, visit_shape);
        return;
    }
    for (int32_t i = 0; i < count_; ++i) {
        if (overlaps(entries_[i].box, box) && !visit_shape(entries_[i].shape)) {
            return;
        }
    }
}

// When out is full a nearer plane replaces the farthest kept: a mover wedged among more
// shapes than it keeps still respects those that press on it.
int32_t MoverNeighbourhood::collide(const ShapeProxy& mover, float reach, Touch* out, int32_t out_capacity) const {
    int32_t count = 0;
    visit(grown(proxy_aabb(mover), reach), [&](int32_t shape) {
        const MoverContact contact = mover_contact(world_.placed_proxy(shape), mover);
        if (!(contact.separation <= reach)) {
            return true;
        }
        if (count < out_capacity) {
            out[count++] = Touch{shape, contact};
            return true;
        }
        int32_t farthest = 0;
        for (int32_t i = 1; i < count; ++i) {
            if (out[i].contact.separation > out[farthest].contact.separation) {
                farthest = i;
            }
        }
        if (count > 0 && contact.separation < out[farthest].contact.separation) {
            out[farthest] = Touch{shape, contact};
        }
        return true;
    });
    return count;
}

MoverNeighbourhood::Hit MoverNeighbourhood::cast(const ShapeProxy& mover, Vec2 translation, float target,
                                                 float tolerance) const {
    Hit hit;
    const AABB box = grown(swept(proxy_aabb(mover), translation), target + tolerance);
    visit(box, [&](int32_t shape) {
        const float fraction = mover_cast(world_.placed_proxy(shape), mover, translation, target, tolerance, hit.fraction);
        if (fraction < hit.fraction) {
            hit = Hit{fraction, shape};
        }
        return hit.fraction > 0.0f;
    });
    return hit;
}

}  // namespace i2d
