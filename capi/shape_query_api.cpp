// SPDX-License-Identifier: MIT
// i2d_make_proxy, i2d_world_cast_shape(_closest), i2d_world_overlap_shape(_ids): queries
// with a convex proxy, checked at the boundary.
#include <cmath>

#include "boundary.hpp"
#include "convert.hpp"
#include "geometry_checks.hpp"
#include "limits.hpp"
#include "query_adapters.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// A sweep must go somewhere (a zero one is an overlap query) and stay in range.
bool valid_translation(Call& call, i2d_vec2 translation) {
    if (!call.cast_translation(translation, "translation")) {
        return false;
    }
    if (translation.x == 0.0f && translation.y == 0.0f) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "translation is zero: a shape cast must move; use i2d_world_overlap_shape for overlap");
    }
    return true;
}

bool valid_ids_out(Call& call, const i2d_shape_id* out, int32_t capacity) {
    if (capacity < 0 || (capacity > 0 && out == nullptr)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", int(capacity));
    }
    return true;
}

}  // namespace

I2D_API i2d_shape_proxy i2d_make_proxy(const i2d_vec2* points, int32_t count, float radius) {
    return guarded("i2d_make_proxy", i2d_shape_proxy{}, [&](Call& call) {
        if (!valid_proxy_input(call, points, count, radius, "points")) {
            return i2d_shape_proxy{};
        }
        Vec2 core_points[max_polygon_vertices];
        for (int32_t i = 0; i < count; ++i) {
            core_points[i] = to_core(points[i]);
        }
        const ShapeProxy p = make_query_proxy(core_points, count, radius);
        i2d_shape_proxy out{};
        for (int32_t i = 0; i < p.count; ++i) {
            out.points[i] = to_public(p.points[i]);
        }
        out.count = p.count;
        out.radius = p.radius;
        return out;
    });
}

I2D_API i2d_status i2d_world_cast_shape(i2d_world_id world, const i2d_shape_proxy* proxy, i2d_vec2 translation,
                                        i2d_query_filter filter, i2d_cast_result_fn* fn, void* context) {
    return guarded("i2d_world_cast_shape", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        ShapeProxy core;
        if (!call.world(world, w) || !core_proxy(call, proxy, core) || !valid_translation(call, translation) ||
            !call.not_null(reinterpret_cast<void*>(fn), "fn")) {
            return last_status();
        }
        CastAdapter adapter{w.world, w.id, fn, context};
        w.world->cast_shape(core, to_core(translation), to_core(filter), &CastAdapter::visit, &adapter);
        set_ok();  // the callbacks may have made calls of their own
        return I2D_OK;
    });
}

I2D_API i2d_ray_result i2d_world_cast_shape_closest(i2d_world_id world, const i2d_shape_proxy* proxy,
                                                    i2d_vec2 translation, i2d_query_filter filter) {
    return guarded("i2d_world_cast_shape_closest", i2d_ray_result{}, [&](Call& call) {
        WorldRef w;
        ShapeProxy core;
        if (!call.world(world, w) || !core_proxy(call, proxy, core) || !valid_translation(call, translation)) {
            return i2d_ray_result{};
        }
        const RayResult r = w.world->cast_shape_closest(core, to_core(translation), to_core(filter));
        i2d_ray_result out{};
        if (r.hit) {
            out.shape = make_shape_id(w.id, r.shape, w.world->shapes().generation(r.shape));
            out.point = to_public(r.point);
            out.normal = to_public(r.normal);
            out.fraction = r.fraction;
            out.hit = true;
        }
        return out;
    });
}

I2D_API i2d_status i2d_world_overlap_shape(i2d_world_id world, const i2d_shape_proxy* proxy, i2d_query_filter filter,
                                           i2d_overlap_fn* fn, void* context) {
    return guarded("i2d_world_overlap_shape", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        ShapeProxy core;
        if (!call.world(world, w) || !core_proxy(call, proxy, core) ||
            !call.not_null(reinterpret_cast<void*>(fn), "fn")) {
            return last_status();
        }
        OverlapAdapter adapter{w.world, w.id, fn, context};
        w.world->overlap_shape(core, to_core(filter), &OverlapAdapter::visit, &adapter);
        set_ok();
        return I2D_OK;
    });
}

I2D_API int32_t i2d_world_overlap_shape_ids(i2d_world_id world, const i2d_shape_proxy* proxy,
                                            i2d_query_filter filter, i2d_shape_id* out, int32_t capacity) {
    return guarded("i2d_world_overlap_shape_ids", int32_t(-1), [&](Call& call) -> int32_t {
        WorldRef w;
        ShapeProxy core;
        if (!call.world(world, w) || !core_proxy(call, proxy, core) || !valid_ids_out(call, out, capacity)) {
            return -1;
        }
        IdCollector collector{w.world, w.id, out, capacity, 0};
        w.world->overlap_shape(core, to_core(filter), &IdCollector::visit, &collector);
        return collector.total;
    });
}
