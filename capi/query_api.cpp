// SPDX-License-Identifier: MIT
// i2d_world_overlap_*, i2d_world_cast_ray_closest: queries with exact geometry.
#include <algorithm>
#include <vector>

#include "boundary.hpp"
#include "convert.hpp"
#include "geometry_checks.hpp"
#include "query_adapters.hpp"

using namespace i2d;
using namespace i2d::capi;

I2D_API i2d_status i2d_world_overlap_aabb(i2d_world_id world, i2d_aabb aabb, i2d_query_filter filter,
                                          i2d_overlap_fn* fn, void* context) {
    return guarded("i2d_world_overlap_aabb", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !valid_aabb(call, aabb, "aabb") || !call.not_null(reinterpret_cast<void*>(fn), "fn")) {
            return last_status();
        }
        OverlapAdapter adapter{w.world, w.id, fn, context};
        w.world->overlap_aabb(capi::to_core(aabb), capi::to_core(filter), &OverlapAdapter::visit, &adapter);
        set_ok();  // the callbacks may have made calls of their own
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_overlap_point(i2d_world_id world, i2d_vec2 point, i2d_query_filter filter,
                                           i2d_overlap_fn* fn, void* context) {
    return guarded("i2d_world_overlap_point", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.finite(point, "point") ||
            !call.not_null(reinterpret_cast<void*>(fn), "fn")) {
            return last_status();
        }
        OverlapAdapter adapter{w.world, w.id, fn, context};
        w.world->overlap_point(capi::to_core(point), capi::to_core(filter), &OverlapAdapter::visit, &adapter);
        set_ok();
        return I2D_OK;
    });
}

I2D_API int32_t i2d_world_overlap_aabb_ids(i2d_world_id world, i2d_aabb aabb, i2d_query_filter filter,
                                           i2d_shape_id* out, int32_t capacity) {
    return guarded("i2d_world_overlap_aabb_ids", int32_t(-1), [&](Call& call) -> int32_t {
        WorldRef w;
        if (!call.world(world, w) || !valid_aabb(call, aabb, "aabb")) {
            return -1;
        }
        if (capacity < 0 || (capacity > 0 && out == nullptr)) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", capacity);
            return -1;
        }
        IdCollector collector{w.world, w.id, out, capacity, 0};
        w.world->overlap_aabb(capi::to_core(aabb), capi::to_core(filter), &IdCollector::visit, &collector);
        return collector.total;
    });
}

I2D_API i2d_status i2d_world_cast_ray(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation,
                                      i2d_query_filter filter, i2d_cast_result_fn* fn, void* context) {
    return guarded("i2d_world_cast_ray", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.coordinate(origin, "origin") ||
            !call.cast_translation(translation, "translation") || !call.not_null(reinterpret_cast<void*>(fn), "fn")) {
            return last_status();
        }
        CastAdapter adapter{w.world, w.id, fn, context};
        w.world->cast_ray(capi::to_core(origin), capi::to_core(translation), capi::to_core(filter),
                          &CastAdapter::visit, &adapter);
        set_ok();  // the callbacks may have made calls of their own
        return I2D_OK;
    });
}

I2D_API i2d_ray_result i2d_world_cast_ray_closest(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation,
                                                  i2d_query_filter filter) {
    return guarded("i2d_world_cast_ray_closest", i2d_ray_result{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.coordinate(origin, "origin") ||
            !call.cast_translation(translation, "translation")) {
            return i2d_ray_result{};
        }
        const RayResult r = w.world->cast_ray_closest(capi::to_core(origin), capi::to_core(translation),
                                                      capi::to_core(filter));
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

I2D_API int32_t i2d_world_overlap_point_ids(i2d_world_id world, i2d_vec2 point, i2d_query_filter filter,
                                            i2d_shape_id* out, int32_t capacity) {
    return guarded("i2d_world_overlap_point_ids", int32_t(-1), [&](Call& call) -> int32_t {
        WorldRef w;
        if (!call.world(world, w) || !call.finite(point, "point")) {
            return -1;
        }
        if (capacity < 0 || (capacity > 0 && out == nullptr)) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", capacity);
            return -1;
        }
        IdCollector collector{w.world, w.id, out, capacity, 0};
        w.world->overlap_point(capi::to_core(point), capi::to_core(filter), &IdCollector::visit, &collector);
        return collector.total;
    });
}

namespace {

// Every hit of a ray, unclipped; sorted afterwards.
struct AllHits {
    std::vector<RayResult> hits;

    static float visit(int32_t shape, Vec2 point, Vec2 normal, float fraction, void* self) {
        static_cast<AllHits*>(self)->hits.push_back({shape, point, normal, fraction, true});
        return 1.0f;
    }
};

}  // namespace

I2D_API int32_t i2d_world_cast_ray_all(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation,
                                       i2d_query_filter filter, i2d_ray_result* out, int32_t capacity) {
    return guarded("i2d_world_cast_ray_all", int32_t(-1), [&](Call& call) -> int32_t {
        WorldRef w;
        if (!call.world(world, w) || !call.coordinate(origin, "origin") ||
            !call.cast_translation(translation, "translation")) {
            return -1;
        }
        if (capacity < 0 || (capacity > 0 && out == nullptr)) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", capacity);
            return -1;
        }
        AllHits all;
        w.world->cast_ray(capi::to_core(origin), capi::to_core(translation), capi::to_core(filter), &AllHits::visit,
                          &all);
        // Nearest first; equal fractions in shape order, so the order is the same every run.
        std::sort(all.hits.begin(), all.hits.end(), [](const RayResult& a, const RayResult& b) {
            return a.fraction < b.fraction || (a.fraction == b.fraction && a.shape < b.shape);
        });
        const int32_t total = int32_t(all.hits.size());
        for (int32_t i = 0; i < total && i < capacity; ++i) {
            const RayResult& r = all.hits[std::size_t(i)];
            out[i] = i2d_ray_result{make_shape_id(w.id, r.shape, w.world->shapes().generation(r.shape)), to_public(r.point),
                                    to_public(r.normal), r.fraction, true};
        }
        return total;
    });
}
