// SPDX-License-Identifier: MIT
// Tight and fat boxes of a body's shapes.
#include "dynamics/body/shape_bounds.hpp"

#include "collision/geometry.hpp"
#include "dynamics/constants.hpp"
#include "math/math.hpp"

namespace i2d {

ProxyKind proxy_kind_of(BodyType type) {
    switch (type) {
        case BodyType::static_body: return ProxyKind::static_proxy;
        case BodyType::kinematic: return ProxyKind::kinematic_proxy;
        default: return ProxyKind::dynamic_proxy;
    }
}

float aabb_margin_of(const Geometry& geometry, float max_margin) {
    const AABB local = compute_aabb(geometry, Transform{});
    const float half_diagonal = 0.5f * length(local.upper - local.lower);
    return min_of(max_margin, aabb_margin_fraction * half_diagonal);
}

ProxyBoxes fatten(const Shape& shape, const Body& body, Vec2 displacement, float reach) {
    const AABB& box = shape.aabb;
    if (body.type == BodyType::static_body) {
        return {box, box};
    }
    const Vec2 margin{shape.aabb_margin + reach, shape.aabb_margin + reach};
    const AABB ahead{min(box.lower, box.lower + displacement) - margin,
                     max(box.upper, box.upper + displacement) + margin};
    if (stretches_fat_box(body)) {
        return {ahead, ahead};
    }
    const Vec2 own_margin{shape.aabb_margin, shape.aabb_margin};
    return {{box.lower - own_margin, box.upper + own_margin}, ahead};
}

bool refit_shape_bounds(const Body& body, Pool<Shape>& shapes, Vec2 displacement, bool ahead, float reach) {
    bool any = false;
    const bool stretches = stretches_fat_box(body);
    const Vec2 turn{reach, reach};
    for (int32_t s = body.head_shape; s != null_index; s = shapes[s].next_in_body) {
        Shape& shape = shapes[s];
        shape.aabb = compute_aabb(shape.geometry, body.transform);
        const AABB needed = ahead ? union_of({shape.aabb.lower - turn, shape.aabb.upper + turn},
                                             {shape.aabb.lower + displacement, shape.aabb.upper + displacement})
                                  : shape.aabb;
        if (!contains(shape.fat_aabb, stretches ? needed : shape.aabb) || !contains(shape.ahead_aabb, needed)) {
            const ProxyBoxes boxes = fatten(shape, body, displacement, reach);
            shape.fat_aabb = boxes.fat;
            shape.ahead_aabb = boxes.ahead;
            shape.enlarged = true;
            any = true;
        }
    }
    return any;
}

void move_enlarged_proxies(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase) {
    take_enlarged_shapes(body, shapes, [&broad_phase](const Shape& shape) {
        broad_phase.move_proxy(shape.proxy_key, shape.fat_aabb, shape.ahead_aabb);
    });
}

void update_tight_boxes(const Body& body, Pool<Shape>& shapes) {
    for (int32_t s = body.head_shape; s != null_index; s = shapes[s].next_in_body) {
        shapes[s].aabb = compute_aabb(shapes[s].geometry, body.transform);
    }
}

void update_shape_bounds(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase, Vec2 displacement,
                         bool ahead, float reach) {
    if (refit_shape_bounds(body, shapes, displacement, ahead, reach)) {
        move_enlarged_proxies(body, shapes, broad_phase);
    }
}

}  // namespace i2d
