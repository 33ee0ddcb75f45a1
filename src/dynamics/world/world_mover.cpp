// SPDX-License-Identifier: MIT
// The character mover's world queries: a capsule cast and collided against the shapes in
// the broadphase trees (the per-shape geometry is collision/mover_contact.hpp).
//
// Like the other queries they walk the trees static, kinematic, dynamic, each in its
// traversal order, so the same world gives the same answers; unlike them they take no
// query lock, since they call no user code.
#include "collision/mover_contact.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"
#include "math/math.hpp"

namespace i2d {

float World::mover_slop() const { return max_of(settings_.contact_slop, tolerances().linear_slop); }

ShapeProxy World::placed_proxy(int32_t shape) const {
    const Shape& s = shapes_[shape];
    return transformed(make_shape_proxy(s.geometry), bodies_[s.body].transform);
}

void World::visit_mover_shapes(const AABB& box, const QueryFilter& filter,
                               FunctionRef<bool(int32_t shape)> visit) const {
    bool go_on = true;
    for (int32_t k = 0; k < int32_t(ProxyKind::count) && go_on; ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).query(box, filter.mask_bits, [&](int32_t, int32_t shape) {
            const Shape& s = shapes_[shape];
            if (!s.is_sensor && should_query(s.filter, filter) && overlaps(s.aabb, box)) {
                go_on = visit(shape);
            }
            return go_on;
        });
    }
}

// One fraction for all trees: a nearer hit shortens the cast for the shapes after it.
float World::cast_mover(const Capsule& mover, Vec2 translation, const QueryFilter& filter) const {
    const ShapeProxy proxy = capsule_proxy(mover);
    const float slop = mover_slop();
    const float target = mover_stop_share * slop, tolerance = mover_stop_tolerance_share * slop;
    const AABB box = grown(swept(proxy_aabb(proxy), translation), target + tolerance);
    float fraction = 1.0f;
    visit_mover_shapes(box, filter, [&](int32_t shape) {
        fraction = mover_cast(placed_proxy(shape), proxy, translation, target, tolerance, fraction);
        return fraction > 0.0f;
    });
    return fraction;
}

void World::collide_mover(const Capsule& mover, const QueryFilter& filter,
                          FunctionRef<void(int32_t shape, const MoverContact& contact)> visit) const {
    const ShapeProxy proxy = capsule_proxy(mover);
    const float slop = mover_slop();
    visit_mover_shapes(grown(proxy_aabb(proxy), slop), filter, [&](int32_t shape) {
        const MoverContact contact = mover_contact(placed_proxy(shape), proxy);
        if (contact.separation <= slop) {
            visit(shape, contact);
        }
        return true;
    });
}

}  // namespace i2d
