// SPDX-License-Identifier: MIT
// World queries: shapes overlapping a box or a point, and the closest ray hit.
//
// Each query walks the shape pool in index order (a fixed order) and tests the cached
// bounds before the exact geometry. The broadphase issue replaces the walk with tree
// queries; the exact tests stay.
#include "collision/geometry.hpp"
#include "dynamics/world.hpp"

namespace i2d {

void World::overlap_aabb(const AABB& box, const QueryFilter& filter, ShapeVisitor visit, void* context) const {
    QueryLock lock(*this);
    for (int32_t i = 0; i < shapes.capacity(); ++i) {
        if (!shapes.is_live(i)) {
            continue;
        }
        const Shape& s = shapes[i];
        if (!should_query(s.filter, filter) || !overlaps(s.aabb, box)) {
            continue;
        }
        if (overlaps_aabb(s.geometry, bodies[s.body].transform, box) && !visit(i, context)) {
            return;
        }
    }
}

void World::overlap_point(Vec2 point, const QueryFilter& filter, ShapeVisitor visit, void* context) const {
    QueryLock lock(*this);
    for (int32_t i = 0; i < shapes.capacity(); ++i) {
        if (!shapes.is_live(i)) {
            continue;
        }
        const Shape& s = shapes[i];
        if (!should_query(s.filter, filter) || !contains_point(s.aabb, point)) {
            continue;
        }
        if (contains_point(s.geometry, bodies[s.body].transform, point) && !visit(i, context)) {
            return;
        }
    }
}

RayResult World::cast_ray_closest(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
    RayResult best;
    float max_fraction = 1.0f;
    for (int32_t i = 0; i < shapes.capacity(); ++i) {
        if (!shapes.is_live(i) || !should_query(shapes[i].filter, filter)) {
            continue;
        }
        const Shape& s = shapes[i];
        const RayHit hit = ray_cast(s.geometry, bodies[s.body].transform, origin, translation, max_fraction);
        // Strictly closer only: on equal fractions the lower index wins, a fixed answer.
        if (hit.hit && (!best.hit || hit.fraction < max_fraction)) {
            best = {i, hit.point, hit.normal, hit.fraction, true};
            max_fraction = hit.fraction;
        }
    }
    return best;
}

}  // namespace i2d
