// SPDX-License-Identifier: MIT
// World queries through the broadphase trees, with exact geometry on the leaves, and
// the contact set's record of what touches what.
//
// Trees are walked static, kinematic, dynamic, each in its traversal order: a fixed
// order for the same world. Fat boxes only narrow the search; every reported shape
// passed the exact test.
#include "collision/geometry.hpp"
#include "collision/toi.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

void World::overlap_aabb(const AABB& box, const QueryFilter& filter, ShapeVisitor visit, void* context) const {
    QueryLock lock(*this);
    bool go_on = true;
    for (int32_t k = 0; k < int32_t(ProxyKind::count) && go_on; ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).query(box, filter.mask_bits, [&](int32_t, int32_t shape) {
            const Shape& s = shapes_[shape];
            if (should_query(s.filter, filter) && overlaps(s.aabb, box) &&
                overlaps_aabb(s.geometry, bodies_[s.body].transform, box)) {
                go_on = visit(shape, context);
            }
            return go_on;
        });
    }
}

void World::overlap_point(Vec2 point, const QueryFilter& filter, ShapeVisitor visit, void* context) const {
    QueryLock lock(*this);
    const AABB box{point, point};
    bool go_on = true;
    for (int32_t k = 0; k < int32_t(ProxyKind::count) && go_on; ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).query(box, filter.mask_bits, [&](int32_t, int32_t shape) {
            const Shape& s = shapes_[shape];
            if (should_query(s.filter, filter) && contains_point(s.aabb, point) &&
                contains_point(s.geometry, bodies_[s.body].transform, point)) {
                go_on = visit(shape, context);
            }
            return go_on;
        });
    }
}

// One clip fraction shared by the three trees, so that a hit in one tree shortens the
// ray for the next.
void World::cast_ray(Vec2 origin, Vec2 translation, const QueryFilter& filter, RayVisitor visit,
                     void* context) const {
    QueryLock lock(*this);
    TreeRayInput input{origin, translation, 1.0f};
    bool stopped = false;
    for (int32_t k = 0; k < int32_t(ProxyKind::count) && !stopped; ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).ray_cast(
            input, filter.mask_bits, [&](const TreeRayInput& current, int32_t, int32_t shape) -> float {
                const Shape& s = shapes_[shape];
                if (!should_query(s.filter, filter)) {
                    return -1.0f;
                }
                const RayHit hit = ray_cast(s.geometry, bodies_[s.body].transform, current.origin,
                                            current.translation, current.max_fraction);
                if (!hit.hit) {
                    return -1.0f;
                }
                const float value = visit(shape, hit.point, hit.normal, hit.fraction, context);
                if (value == 0.0f) {
                    stopped = true;
                } else if (value > 0.0f && value < input.max_fraction) {
                    input.max_fraction = value;
                }
                return value;
            });
    }
}

namespace {

struct ClosestHit {
    RayResult result;
};

float keep_closest(int32_t shape, Vec2 point, Vec2 normal, float fraction, void* context) {
    auto* closest = static_cast<ClosestHit*>(context);
    closest->result = {shape, point, normal, fraction, true};
    return fraction;  // clip: only nearer hits can follow
}

}  // namespace

RayResult World::cast_ray_closest(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
    ClosestHit closest;
    cast_ray(origin, translation, filter, keep_closest, &closest);
    return closest.result;
}

// The trees are asked for the box the proxy sweeps; each candidate's fraction comes
// from the shape cast (time of impact on the exact distance). A clip shortens the cast
// for the shapes after it (the box stays: the trees are walked once).
void World::cast_shape(const ShapeProxy& proxy, Vec2 translation, const QueryFilter& filter, RayVisitor visit,
                       void* context) const {
    QueryLock lock(*this);
    const AABB start = proxy_aabb(proxy);
    const AABB swept = union_of(start, {start.lower + translation, start.upper + translation});
    const float slop = tolerances().linear_slop;  // the cast's tolerance is a quarter of it
    float max_fraction = 1.0f;
    bool stopped = false;
    for (int32_t k = 0; k < int32_t(ProxyKind::count) && !stopped; ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).query(swept, filter.mask_bits, [&](int32_t, int32_t shape) {
            const Shape& s = shapes_[shape];
            if (!should_query(s.filter, filter)) {
                return true;
            }
            const CastHit hit =
                shape_cast(make_shape_proxy(s.geometry), bodies_[s.body].transform, proxy, translation, max_fraction,
                           slop);
            if (!hit.hit) {
                return true;
            }
            const float value = visit(shape, hit.point, hit.normal, hit.fraction, context);
            if (value == 0.0f) {
                stopped = true;
            } else if (value > 0.0f && value < max_fraction) {
                max_fraction = value;
            }
            return !stopped;
        });
    }
}

RayResult World::cast_shape_closest(const ShapeProxy& proxy, Vec2 translation, const QueryFilter& filter) const {
    ClosestHit closest;
    cast_shape(proxy, translation, filter, keep_closest, &closest);
    return closest.result;
}

void World::overlap_shape(const ShapeProxy& proxy, const QueryFilter& filter, ShapeVisitor visit,
                          void* context) const {
    QueryLock lock(*this);
    const AABB box = proxy_aabb(proxy);
    bool go_on = true;
    for (int32_t k = 0; k < int32_t(ProxyKind::count) && go_on; ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).query(box, filter.mask_bits, [&](int32_t, int32_t shape) {
            const Shape& s = shapes_[shape];
            if (!should_query(s.filter, filter) || !overlaps(s.aabb, box)) {
                return true;
            }
            const ShapeProxy other = transformed(make_shape_proxy(s.geometry), bodies_[s.body].transform);
            if (core_distance(other, proxy).distance <= other.radius + proxy.radius) {
                go_on = visit(shape, context);
            }
            return go_on;
        });
    }
}

// Contact and sensor data come from the contact set, not the trees: what the last step
// found, not a fresh test. Unlike the queries they take no lock: their visitors (the C
// boundary's copying loops) run no user code.
void World::visit_touching_contacts(int32_t body, int32_t shape, FunctionRef<void(const ContactData&)> visit) const {
    stages_->contacts.visit_touching(body, shape, visit);
}

void World::visit_sensor_overlaps(int32_t sensor, FunctionRef<void(int32_t visitor)> visit) const {
    stages_->contacts.visit_sensor_visitors(sensor, visit);
}

void World::rebuild_static_tree() {
    RecordScope record(recorder_.get(), RecordedOp::rebuild_static_tree);
    stages_->broad_phase.tree(ProxyKind::static_proxy).rebuild();
}

}  // namespace i2d
