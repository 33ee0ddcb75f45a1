// SPDX-License-Identifier: MIT
// Shape: geometry attached to a body, with material, filter and cached world bounds.
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"
#include "core/pool.hpp"

namespace i2d {

struct Filter {
    uint64_t category_bits = 1;
    uint64_t mask_bits = ~uint64_t(0);
    int32_t group_index = 0;
};

struct QueryFilter {
    uint64_t category_bits = ~uint64_t(0);
    uint64_t mask_bits = ~uint64_t(0);
};

struct ShapeDef {
    float density = 1.0f;
    float friction = 0.6f;
    float restitution = 0.0f;
    float rolling_resistance = 0.0f;
    float tangent_speed = 0.0f;
    bool is_sensor = false;
    bool enable_contact_events = true;
    bool enable_sensor_events = true;
    bool enable_hit_events = false;
    bool enable_custom_filtering = false;
    bool enable_pre_solve_events = false;
    Filter filter;
    void* user_data = nullptr;
};

// Design note: what the narrowphase and the bounds update read every step comes first,
// in one cache line (body, proxy, boxes, flags); the material, read when a contact is
// made, and the geometry, hundreds of bytes for a polygon, follow. The proxy's boxes are
// kept here too so that neither step walks the tree to read them.
/// A shape's event flags that can change after creation.
enum class ShapeFlag : uint8_t { contact_events, sensor_events, hit_events, pre_solve_events, count };

struct Shape {
    int32_t body = null_index;
    int32_t proxy_key = null_index;  // in the broadphase
    AABB aabb;        // tight world bounds, current after every step and every move
    AABB fat_aabb;    // the proxy's box (as of the broadphase's next commit)
    AABB ahead_aabb;  // the fat box stretched over the coming step (shape_bounds.hpp)
    bool is_sensor = false;
    bool enable_contact_events = true;
    bool enable_sensor_events = true;
    bool enable_hit_events = false;
    bool enable_custom_filtering = false;  // pairs with it reach the custom filter hook
    bool enable_pre_solve_events = false;  // its touching pairs reach the pre-solve hook
    bool enlarged = false;  // the step gave it new boxes; its proxy moves at the step's end
    float aabb_margin = 0.0f;  // how far the fat box reaches beyond the tight box, m
    float friction = 0.0f, restitution = 0.0f;
    float rolling_resistance = 0.0f;  // coefficient, times the shape's radius at contacts
    float tangent_speed = 0.0f;       // m/s, counter-clockwise along the outline
    int32_t prev_in_body = null_index, next_in_body = null_index;
    int32_t chain = null_index;  // the chain this segment belongs to, if any
    float density = 0.0f;
    Filter filter;
    void* user_data = nullptr;
    Geometry geometry;
};

/// A shared positive group always collides, a shared negative group never does;
/// otherwise each shape's category must meet the other's mask.
inline bool should_collide(const Filter& a, const Filter& b) {
    if (a.group_index == b.group_index && a.group_index != 0) {
        return a.group_index > 0;
    }
    return (a.category_bits & b.mask_bits) != 0 && (b.category_bits & a.mask_bits) != 0;
}

inline bool should_query(const Filter& shape, const QueryFilter& query) {
    return (shape.category_bits & query.mask_bits) != 0 && (shape.mask_bits & query.category_bits) != 0;
}

}  // namespace i2d
