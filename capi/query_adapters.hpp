// SPDX-License-Identifier: MIT
// The adapters between the core's queries, which report shape indices, and the C API's
// callbacks and arrays, which take public shape ids: one of each, for every query.
#pragma once

#include <cstdint>

#include <impulse2d/impulse2d.h>

#include "boundary.hpp"
#include "convert.hpp"

namespace i2d::capi {

/// A query's shapes to a user's overlap callback; the callback's answer stops it or not.
struct OverlapAdapter {
    const World* world;
    IdFields world_id;
    i2d_overlap_fn* fn;
    void* context;

    static bool visit(int32_t shape, void* self) {
        const auto* a = static_cast<const OverlapAdapter*>(self);
        return a->fn(make_shape_id(a->world_id, shape, a->world->shapes().generation(shape)), a->context);
    }
};

/// A cast's hits (rays and shapes) to a user's cast callback, whose answer clips, ignores
/// or stops.
struct CastAdapter {
    const World* world;
    IdFields world_id;
    i2d_cast_result_fn* fn;
    void* context;

    static float visit(int32_t shape, Vec2 point, Vec2 normal, float fraction, void* self) {
        const auto* a = static_cast<const CastAdapter*>(self);
        return a->fn(make_shape_id(a->world_id, shape, a->world->shapes().generation(shape)), to_public(point),
                     to_public(normal), fraction, a->context);
    }
};

/// Fills a caller's array of ids up to its capacity and counts every shape found.
struct IdCollector {
    const World* world;
    IdFields world_id;
    i2d_shape_id* out;
    int32_t capacity;
    int32_t total;

    static bool visit(int32_t shape, void* self) {
        auto* c = static_cast<IdCollector*>(self);
        if (c->total < c->capacity) {
            c->out[c->total] = make_shape_id(c->world_id, shape, c->world->shapes().generation(shape));
        }
        ++c->total;
        return true;
    }
};

}  // namespace i2d::capi
