// SPDX-License-Identifier: MIT
// i2d_chain_*: chains of one-sided segments, checked at the boundary.
#include <cfloat>
#include <vector>

#include "boundary.hpp"
#include "convert.hpp"
#include "limits.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

bool valid_points(Call& call, const i2d_chain_def& def) {
    if (!call.not_null(def.points, "chain def: points")) {
        return false;
    }
    const int32_t least = def.is_loop ? 3 : 4;
    if (def.count < least || def.count > max_chain_points) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "chain def: count is %d; %s chain needs %d to %d points%s", int(def.count),
                         def.is_loop ? "a looped" : "an open", int(least), int(max_chain_points),
                         def.is_loop ? "" : " (the first and last are ghost points)");
    }
    for (int32_t i = 0; i < def.count; ++i) {
        if (!call.coordinate(def.points[i], "chain def: points")) {
            return false;
        }
    }
    // Every pair of consecutive points, the wrap-around of a loop included, makes a
    // segment or a ghost edge: none may be degenerate.
    const int32_t pairs = def.is_loop ? def.count : def.count - 1;
    for (int32_t i = 0; i < pairs; ++i) {
        const i2d_vec2 a = def.points[i], b = def.points[(i + 1) % def.count];
        const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
        if (dx * dx + dy * dy < double(linear_slop) * linear_slop) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT,
                             "chain def: points %d and %d are closer than %g m; a chain's segments must have length",
                             int(i), int((i + 1) % def.count), double(linear_slop));
        }
    }
    return true;
}

bool valid_materials(Call& call, const i2d_chain_def& def) {
    const int32_t segments = chain_segment_count(def.count, def.is_loop);
    if (def.material_count != 0 && def.material_count != 1 && def.material_count != segments) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "chain def: material_count is %d; it must be 0, 1 or the segment count (%d)",
                         int(def.material_count), int(segments));
    }
    if (def.material_count > 0 && !call.not_null(def.materials, "chain def: materials")) {
        return false;
    }
    for (int32_t i = 0; i < def.material_count; ++i) {
        const i2d_surface_material& m = def.materials[i];
        if (!call.in_range(m.friction, 0.0f, FLT_MAX, "chain def: materials[].friction") ||
            !call.in_range(m.restitution, 0.0f, max_restitution, "chain def: materials[].restitution") ||
            !call.in_range(m.rolling_resistance, 0.0f, max_setting, "chain def: materials[].rolling_resistance") ||
            !call.in_range(m.tangent_speed, -max_speed_limit, max_speed_limit, "chain def: materials[].tangent_speed")) {
            return false;
        }
    }
    return true;
}

ChainDef to_core(const i2d_chain_def& def, std::vector<Vec2>& points, std::vector<SurfaceMaterial>& materials) {
    points.resize(std::size_t(def.count));
    for (int32_t i = 0; i < def.count; ++i) {
        points[std::size_t(i)] = capi::to_core(def.points[i]);
    }
    materials.resize(std::size_t(def.material_count));
    for (int32_t i = 0; i < def.material_count; ++i) {
        const i2d_surface_material& m = def.materials[i];
        materials[std::size_t(i)] = SurfaceMaterial{m.friction, m.restitution, m.rolling_resistance, m.tangent_speed};
    }
    ChainDef core;
    core.points = points.data();
    core.count = def.count;
    core.is_loop = def.is_loop;
    core.materials = materials.data();
    core.material_count = def.material_count;
    core.filter = capi::to_core(def.filter);
    core.enable_sensor_events = def.enable_sensor_events;
    core.user_data = def.user_data;
    return core;
}

}  // namespace

I2D_API i2d_chain_id i2d_chain_create(i2d_body_id body, const i2d_chain_def* def) {
    return guarded("i2d_chain_create", I2D_NULL_CHAIN_ID, [&](Call& call) -> i2d_chain_id {
        BodyRef b;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !call.not_null(def, "chain def") ||
            !call.cookie(def->internal_cookie, "chain_def") || !valid_points(call, *def) ||
            !valid_materials(call, *def)) {
            return I2D_NULL_CHAIN_ID;
        }
        if (b.body().type == BodyType::dynamic) {
            call.fail(I2D_ERR_INVALID_ARGUMENT,
                      "a chain belongs on a static or kinematic body: chains have no mass and collide on one side");
            return I2D_NULL_CHAIN_ID;
        }
        std::vector<Vec2> points;
        std::vector<SurfaceMaterial> materials;
        const int32_t index = b.world->create_chain(b.index, to_core(*def, points, materials));
        if (index == null_index) {
            call.fail(I2D_ERR_CAPACITY, "the world's shape or chain pool is full");
            return I2D_NULL_CHAIN_ID;
        }
        return make_chain_id(b.id, index, b.world->chains().generation(index));
    });
}

I2D_API i2d_status i2d_chain_destroy(i2d_chain_id id) {
    return guarded("i2d_chain_destroy", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ChainRef c;
        if (!call.chain(id, c) || !call.unlocked(*c.world)) {
            return last_status();
        }
        c.world->destroy_chain(c.index);
        return I2D_OK;
    });
}

I2D_API bool i2d_chain_is_valid(i2d_chain_id id) {
    return guarded("i2d_chain_is_valid", false, [&](Call& call) {
        ChainRef c;
        return call.chain(id, c);
    });
}

I2D_API int32_t i2d_chain_get_segments(i2d_chain_id id, i2d_shape_id* out, int32_t capacity) {
    return guarded("i2d_chain_get_segments", int32_t(-1), [&](Call& call) -> int32_t {
        ChainRef c;
        if (!call.chain(id, c)) {
            return -1;
        }
        if (capacity < 0 || (capacity > 0 && out == nullptr)) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", int(capacity));
            return -1;
        }
        const std::vector<int32_t>& shapes = c.world->chains()[c.index].shapes;
        for (int32_t i = 0; i < capacity && i < int32_t(shapes.size()); ++i) {
            const int32_t s = shapes[std::size_t(i)];
            out[i] = make_shape_id(c.id, s, c.world->shapes().generation(s));
        }
        return int32_t(shapes.size());
    });
}

I2D_API i2d_chain_id i2d_shape_get_chain(i2d_shape_id id) {
    return guarded("i2d_shape_get_chain", I2D_NULL_CHAIN_ID, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s) || s.shape().chain == null_index) {
            return I2D_NULL_CHAIN_ID;
        }
        const int32_t chain = s.shape().chain;
        return make_chain_id(s.id, chain, s.world->chains().generation(chain));
    });
}
