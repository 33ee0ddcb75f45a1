// SPDX-License-Identifier: MIT
// World::explode: a blast that pushes every dynamic body's shapes near it.
//
// Design note: each shape in reach gets one impulse at its point closest to the blast,
// along the line from the blast to that point, of impulse_per_length times the width the
// shape shows the blast (its outline projected across that line: 2r for a disc) times
// the falloff's scale. Measuring to the closest point rather than the centre makes a long
// plank lying by the blast feel it as a wall would; the projected width makes a body's
// push grow with the side it turns to the blast, as a pressure wave's would. The impulses
// go through apply_linear_impulse, one per shape, so a recording replays an explosion
// exactly and a body with several shapes gets each one's share. They are gathered first
// and applied after the tree query, in its order: waking bodies never runs under a query.
#include <cmath>
#include <vector>

#include "collision/shape_proxy.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// Closer than this (m, squared) the blast is inside the shape: the push goes from the
// blast toward the body's centre of mass instead.
constexpr float inside_distance_squared = 1e-12f;

// The width the proxy (placed by xf) shows to a blast coming along `direction` (unit).
float projected_width(const ShapeProxy& proxy, const Transform& xf, Vec2 direction) {
    const Vec2 across = left_perp(direction);
    float lowest = INFINITY, highest = -INFINITY;
    for (int32_t i = 0; i < proxy.count; ++i) {
        const float along = dot(transform_point(xf, proxy.points[i]), across);
        lowest = min_of(lowest, along);
        highest = max_of(highest, along);
    }
    return highest - lowest + 2.0f * proxy.radius;
}

// 1 within the radius, falling linearly to 0 at radius + falloff.
float falloff_scale(const ExplosionDef& def, float distance) {
    if (distance <= def.radius) {
        return 1.0f;
    }
    return def.falloff > 0.0f ? max_of(0.0f, 1.0f - (distance - def.radius) / def.falloff) : 0.0f;
}

struct BlastPush {
    int32_t body;
    Vec2 impulse, point;
};

}  // namespace

void World::explode(const ExplosionDef& def) {
    const float reach = def.radius + def.falloff;
    const AABB box{def.position - Vec2{reach, reach}, def.position + Vec2{reach, reach}};
    std::vector<BlastPush> pushes;
    stages_->broad_phase.tree(ProxyKind::dynamic_proxy).query(box, def.mask_bits, [&](int32_t, int32_t shape) {
        const Shape& s = shapes_[shape];
        const Body& b = bodies_[s.body];
        if (s.is_sensor || b.type != BodyType::dynamic || (s.filter.category_bits & def.mask_bits) == 0) {
            return true;
        }
        const ShapeProxy proxy = make_shape_proxy(s.geometry);
        const Vec2 point = closest_point(proxy, b.transform, def.position);
        Vec2 direction = point - def.position;
        const float distance = length(direction);
        const float scale = falloff_scale(def, distance);
        if (scale <= 0.0f) {
            return true;
        }
        if (distance * distance <= inside_distance_squared) {
            direction = b.center - def.position;
        }
        direction = length_squared(direction) > inside_distance_squared ? normalize(direction) : Vec2{1.0f, 0.0f};
        const float magnitude = def.impulse_per_length * projected_width(proxy, b.transform, direction) * scale;
        pushes.push_back({s.body, magnitude * direction, point});
        return true;
    });
    for (const BlastPush& push : pushes) {
        apply_linear_impulse(push.body, push.impulse, push.point, true);
    }
}

}  // namespace i2d
