// SPDX-License-Identifier: MIT
// i2d_shape_*: create circles and boxes (polygons), destroy, and read or change materials and filters.
#include <cfloat>

#include "boundary.hpp"
#include "collision/geometry.hpp"
#include "collision/hull.hpp"
#include "geometry_checks.hpp"
#include "convert.hpp"
#include "limits.hpp"
#include "loaded_values.hpp"
#include "shape_rules.hpp"
#include "dynamics/constants.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

bool validate_shape_def(Call& call, const i2d_shape_def* def) {
    return call.not_null(def, "shape def") && call.cookie(def->internal_cookie, "shape_def") &&
           checked_with_names("shape def", -1, [&](auto name) {
               return valid_material(
                   call, {def->density, def->friction, def->restitution, def->rolling_resistance, def->tangent_speed},
                   name);
           });
}

ShapeDef to_core(const i2d_shape_def& def) {
    ShapeDef core;
    core.density = def.density;
    core.friction = def.friction;
    core.restitution = def.restitution;
    core.rolling_resistance = def.rolling_resistance;
    core.tangent_speed = def.tangent_speed;
    core.is_sensor = def.is_sensor;
    core.enable_contact_events = def.enable_contact_events;
    core.enable_sensor_events = def.enable_sensor_events;
    core.enable_hit_events = def.enable_hit_events;
    core.enable_custom_filtering = def.enable_custom_filtering;
    core.enable_pre_solve_events = def.enable_pre_solve_events;
    core.filter = capi::to_core(def.filter);
    core.user_data = def.user_data;
    return core;
}

i2d_shape_id create_shape(Call& call, const BodyRef& b, const i2d_shape_def* def, const Geometry& geometry) {
    const int32_t index = b.world->create_shape(b.index, to_core(*def), geometry);
    if (index == null_index) {
        call.fail(I2D_ERR_CAPACITY, "the world holds %d shapes, the most it can", Pool<Shape>::max_slots);
        return I2D_NULL_SHAPE_ID;
    }
    return make_shape_id(b.id, index, b.world->shapes().generation(index));
}


}  // namespace

namespace i2d::capi {

namespace {

// A chain's points lie anywhere in the world (its body is static or kinematic), and each
// of its edges, ghost edges included, is longer than the slop, measured as a chain def is.
bool valid_chain_segment(Call& call, const ChainSegment& c, int32_t index, const char* name) {
    const Vec2 points[4] = {c.ghost1, c.point1, c.point2, c.ghost2};
    for (int32_t i = 0; i < 4; ++i) {
        if (!call.coordinate(to_public(points[i]), name)) {
            return false;
        }
    }
    for (int32_t i = 0; i < 3; ++i) {
        const double dx = double(points[i + 1].x) - points[i].x, dy = double(points[i + 1].y) - points[i].y;
        if (dx * dx + dy * dy < double(linear_slop) * linear_slop) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "shape %d: a chain segment's edge is shorter than %g m",
                             static_cast<int>(index), double(linear_slop));
        }
    }
    return true;
}

}  // namespace

// The geometry a create call would have taken, each kind under its own call's rules.
bool valid_geometry(Call& call, const Geometry& g, int32_t index, const char* name) {
    switch (g.type) {
        case ShapeType::circle:
            return call.local_point(to_public(g.circle.center), name) && call.extent(g.circle.radius, name);
        case ShapeType::capsule:
            return call.local_point(to_public(g.capsule.center1), name) &&
                   call.local_point(to_public(g.capsule.center2), name) && call.extent(g.capsule.radius, name) &&
                   valid_core_length(call, to_public(g.capsule.center1), to_public(g.capsule.center2), name);
        case ShapeType::segment:
            return call.local_point(to_public(g.segment.point1), name) &&
                   call.local_point(to_public(g.segment.point2), name) &&
                   valid_core_length(call, to_public(g.segment.point1), to_public(g.segment.point2), name);
        case ShapeType::polygon: {
            const i2d_polygon polygon = to_public(g.polygon);
            if (!valid_convex_polygon(call, &polygon, name, min_box_edge) ||
                !call.in_range(polygon.radius, 0.0f, max_shape_extent, name)) {
                return false;
            }
            for (int32_t i = 0; i < polygon.count; ++i) {
                if (!call.local_point(polygon.vertices[i], name)) {
                    return false;
                }
            }
            return true;
        }
        case ShapeType::chain_segment:
            return valid_chain_segment(call, g.chain_segment, index, name);
        default:
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "shape %d: its kind is unknown", static_cast<int>(index));
    }
}

bool valid_loaded_shape(Call& call, const World& world, int32_t index) {
    const Shape& s = world.shapes()[index];
    const Material material{s.density, s.friction, s.restitution, s.rolling_resistance, s.tangent_speed};
    if ((s.chain != null_index) != (s.geometry.type == ShapeType::chain_segment) ||
        (s.chain != null_index && world.bodies()[s.body].type == BodyType::dynamic)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "shape %d: a chain segment outside a chain or on a dynamic body, or a chain of other shapes",
                         static_cast<int>(index));
    }
    return checked_with_names("shape", index, [&](auto name) {
        return valid_material(call, material, name) && valid_geometry(call, s.geometry, index, name("geometry")) &&
               call.in_range(s.aabb_margin, 0.0f, world.tolerances().max_aabb_margin, name("aabb_margin"));
    });
}

bool valid_recorded_shape(Call& call, const ShapeDef& def, const Geometry& geometry) {
    if (geometry.type == ShapeType::chain_segment) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "shape: a chain segment made alone; chains are made whole");
    }
    const Material material{def.density, def.friction, def.restitution, def.rolling_resistance, def.tangent_speed};
    return checked_with_names("shape def", -1, [&](auto name) {
        return valid_material(call, material, name) && valid_geometry(call, geometry, -1, name("geometry"));
    });
}

}  // namespace i2d::capi

I2D_API i2d_shape_id i2d_shape_create_circle(i2d_body_id body, const i2d_shape_def* def, const i2d_circle* circle) {
    return guarded("i2d_shape_create_circle", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !call.not_null(circle, "circle") || !call.local_point(circle->center, "circle: center") ||
            !call.extent(circle->radius, "circle: radius")) {
            return I2D_NULL_SHAPE_ID;
        }
        Geometry g;
        g.type = ShapeType::circle;
        g.circle = {capi::to_core(circle->center), circle->radius};
        return create_shape(call, b, def, g);
    });
}

I2D_API i2d_shape_id i2d_shape_create_box(i2d_body_id body, const i2d_shape_def* def, float half_width,
                                          float half_height) {
    return guarded("i2d_shape_create_box", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !call.extent(half_width, "half_width") || !call.extent(half_height, "half_height")) {
            return I2D_NULL_SHAPE_ID;
        }
        Geometry g;
        g.type = ShapeType::polygon;
        g.polygon = make_box(half_width, half_height);
        return create_shape(call, b, def, g);
    });
}

namespace {

// A body's polygon is built from a hull so that its normals and centroid are consistent
// by construction.
bool hull_of(Call& call, const Vec2* points, int32_t count, Hull& hull) {
    const HullStatus status = compute_hull(points, count, hull);
    if (status != HullStatus::ok) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "polygon: %s", hull_status_message(status));
    }
    return true;
}

bool valid_points(Call& call, const i2d_vec2* points, int32_t count) {
    if (!call.not_null(points, "points")) {
        return false;
    }
    if (count < 3 || count > max_polygon_vertices) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "count is %d; a polygon takes 3 to %d points", count,
                         max_polygon_vertices);
    }
    for (int32_t i = 0; i < count; ++i) {
        if (!call.local_point(points[i], "points[i]")) {
            return false;
        }
    }
    return true;
}

Geometry polygon_geometry(const Polygon& polygon) {
    Geometry g;
    g.type = ShapeType::polygon;
    g.polygon = polygon;
    return g;
}

}  // namespace

I2D_API i2d_shape_id i2d_shape_create_offset_box(i2d_body_id body, const i2d_shape_def* def, float half_width,
                                                 float half_height, i2d_vec2 center, i2d_rot rotation) {
    return guarded("i2d_shape_create_offset_box", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !call.extent(half_width, "half_width") || !call.extent(half_height, "half_height") ||
            !call.local_point(center, "center") || !valid_transform(call, i2d_transform{center, rotation}, "offset")) {
            return I2D_NULL_SHAPE_ID;
        }
        const Rot q = normalize(capi::to_core(rotation));
        return create_shape(call, b, def,
                            polygon_geometry(make_offset_box(half_width, half_height, capi::to_core(center), q)));
    });
}

I2D_API i2d_shape_id i2d_shape_create_polygon(i2d_body_id body, const i2d_shape_def* def, const i2d_vec2* points,
                                              int32_t count) {
    return guarded("i2d_shape_create_polygon", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        Hull hull;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !valid_points(call, points, count)) {
            return I2D_NULL_SHAPE_ID;
        }
        Vec2 core_points[max_polygon_vertices];
        for (int32_t i = 0; i < count; ++i) {
            core_points[i] = capi::to_core(points[i]);
        }
        if (!hull_of(call, core_points, count, hull)) {
            return I2D_NULL_SHAPE_ID;
        }
        return create_shape(call, b, def, polygon_geometry(make_polygon(hull, 0.0f)));
    });
}

I2D_API i2d_shape_id i2d_shape_create_polygon_from(i2d_body_id body, const i2d_shape_def* def,
                                                   const i2d_polygon* polygon) {
    return guarded("i2d_shape_create_polygon_from", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        Geometry g;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !polygon_geometry_of(call, polygon, g)) {
            return I2D_NULL_SHAPE_ID;
        }
        return create_shape(call, b, def, g);
    });
}

namespace i2d::capi {

bool polygon_geometry_of(Call& call, const i2d_polygon* polygon, Geometry& out) {
    if (!valid_convex_polygon(call, polygon, "polygon") ||
        !call.in_range(polygon->radius, 0.0f, max_shape_extent, "polygon radius")) {
        return false;
    }
    for (int32_t i = 0; i < polygon->count; ++i) {
        if (!call.local_point(polygon->vertices[i], "polygon vertex")) {
            return false;
        }
    }
    const Polygon given = to_core(*polygon);
    Hull hull;
    if (!hull_of(call, given.vertices, given.count, hull)) {
        return false;
    }
    out = polygon_geometry(make_polygon(hull, given.radius));
    return true;
}

}  // namespace i2d::capi

I2D_API i2d_shape_id i2d_shape_create_capsule(i2d_body_id body, const i2d_shape_def* def, i2d_vec2 center1,
                                              i2d_vec2 center2, float radius) {
    return guarded("i2d_shape_create_capsule", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !call.local_point(center1, "center1") || !call.local_point(center2, "center2") ||
            !call.extent(radius, "radius") || !valid_core_length(call, center1, center2, "center1-center2")) {
            return I2D_NULL_SHAPE_ID;
        }
        Geometry g;
        g.type = ShapeType::capsule;
        g.capsule = {capi::to_core(center1), capi::to_core(center2), radius};
        return create_shape(call, b, def, g);
    });
}

I2D_API i2d_shape_id i2d_shape_create_segment(i2d_body_id body, const i2d_shape_def* def, i2d_vec2 point1,
                                              i2d_vec2 point2) {
    return guarded("i2d_shape_create_segment", I2D_NULL_SHAPE_ID, [&](Call& call) -> i2d_shape_id {
        BodyRef b;
        if (!call.body(body, b) || !call.unlocked(*b.world) || !validate_shape_def(call, def) ||
            !call.local_point(point1, "point1") || !call.local_point(point2, "point2") ||
            !valid_core_length(call, point1, point2, "segment")) {
            return I2D_NULL_SHAPE_ID;
        }
        Geometry g;
        g.type = ShapeType::segment;
        g.segment = {capi::to_core(point1), capi::to_core(point2)};
        return create_shape(call, b, def, g);
    });
}

I2D_API i2d_status i2d_shape_destroy(i2d_shape_id id) {
    return guarded("i2d_shape_destroy", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s)) {
            return last_status();
        }
        if (s.shape().chain != null_index) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT,
                             "the shape is a chain segment: destroy its chain (i2d_chain_destroy) instead"),
                   last_status();
        }
        s.world->destroy_shape(s.index);
        return I2D_OK;
    });
}

I2D_API bool i2d_shape_is_valid(i2d_shape_id id) {
    return guarded("i2d_shape_is_valid", false, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s);
    });
}

I2D_API i2d_body_id i2d_shape_get_body(i2d_shape_id id) {
    return guarded("i2d_shape_get_body", I2D_NULL_BODY_ID, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s)) {
            return I2D_NULL_BODY_ID;
        }
        const int32_t body = s.shape().body;
        return make_body_id(s.id, body, s.world->bodies().generation(body));
    });
}

I2D_API i2d_shape_type i2d_shape_get_type(i2d_shape_id id) {
    return guarded("i2d_shape_get_type", I2D_SHAPE_CIRCLE, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? static_cast<i2d_shape_type>(s.shape().geometry.type) : I2D_SHAPE_CIRCLE;
    });
}

I2D_API i2d_circle i2d_shape_get_circle(i2d_shape_id id) {
    return guarded("i2d_shape_get_circle", i2d_circle{}, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s)) {
            return i2d_circle{};
        }
        const Geometry& g = s.shape().geometry;
        if (g.type != ShapeType::circle) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "the shape is not a circle");
            return i2d_circle{};
        }
        return i2d_circle{to_public(g.circle.center), g.circle.radius};
    });
}

I2D_API i2d_polygon i2d_shape_get_polygon(i2d_shape_id id) {
    return guarded("i2d_shape_get_polygon", i2d_polygon{}, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s)) {
            return i2d_polygon{};
        }
        const Geometry& g = s.shape().geometry;
        if (g.type != ShapeType::polygon) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "the shape is not a polygon");
            return i2d_polygon{};
        }
        return to_public(g.polygon);
    });
}

I2D_API i2d_capsule i2d_shape_get_capsule(i2d_shape_id id) {
    return guarded("i2d_shape_get_capsule", i2d_capsule{}, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s)) {
            return i2d_capsule{};
        }
        const Geometry& g = s.shape().geometry;
        if (g.type != ShapeType::capsule) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "the shape is not a capsule");
            return i2d_capsule{};
        }
        return i2d_capsule{to_public(g.capsule.center1), to_public(g.capsule.center2), g.capsule.radius};
    });
}

I2D_API i2d_segment i2d_shape_get_segment(i2d_shape_id id) {
    return guarded("i2d_shape_get_segment", i2d_segment{}, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s)) {
            return i2d_segment{};
        }
        const Geometry& g = s.shape().geometry;
        if (g.type == ShapeType::chain_segment) {
            return i2d_segment{to_public(g.chain_segment.point1), to_public(g.chain_segment.point2)};
        }
        if (g.type != ShapeType::segment) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "the shape is not a segment");
            return i2d_segment{};
        }
        return i2d_segment{to_public(g.segment.point1), to_public(g.segment.point2)};
    });
}

I2D_API i2d_aabb i2d_shape_get_aabb(i2d_shape_id id) {
    return guarded("i2d_shape_get_aabb", i2d_aabb{}, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? to_public(s.shape().aabb) : i2d_aabb{};
    });
}

I2D_API float i2d_shape_get_density(i2d_shape_id id) {
    return guarded("i2d_shape_get_density", 0.0f, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? s.shape().density : 0.0f;
    });
}

I2D_API float i2d_shape_get_friction(i2d_shape_id id) {
    return guarded("i2d_shape_get_friction", 0.0f, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? s.shape().friction : 0.0f;
    });
}

I2D_API i2d_status i2d_shape_set_friction(i2d_shape_id id, float friction) {
    return guarded("i2d_shape_set_friction", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s) || !call.in_range(friction, 0.0f, FLT_MAX, "friction")) {
            return last_status();
        }
        s.world->set_friction(s.index, friction);
        return I2D_OK;
    });
}

I2D_API float i2d_shape_get_restitution(i2d_shape_id id) {
    return guarded("i2d_shape_get_restitution", 0.0f, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? s.shape().restitution : 0.0f;
    });
}

I2D_API i2d_status i2d_shape_set_restitution(i2d_shape_id id, float restitution) {
    return guarded("i2d_shape_set_restitution", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s) || !call.in_range(restitution, 0.0f, max_restitution, "restitution")) {
            return last_status();
        }
        s.world->set_restitution(s.index, restitution);
        return I2D_OK;
    });
}

I2D_API i2d_filter i2d_shape_get_filter(i2d_shape_id id) {
    return guarded("i2d_shape_get_filter", i2d_filter{}, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? to_public(s.shape().filter) : i2d_filter{};
    });
}

I2D_API i2d_status i2d_shape_set_filter(i2d_shape_id id, i2d_filter filter) {
    return guarded("i2d_shape_set_filter", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s)) {
            return last_status();
        }
        s.world->set_filter(s.index, capi::to_core(filter));
        return I2D_OK;
    });
}

I2D_API bool i2d_shape_is_sensor(i2d_shape_id id) {
    return guarded("i2d_shape_is_sensor", false, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) && s.shape().is_sensor;
    });
}

I2D_API void* i2d_shape_get_user_data(i2d_shape_id id) {
    return guarded("i2d_shape_get_user_data", static_cast<void*>(nullptr), [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? s.shape().user_data : nullptr;
    });
}

I2D_API i2d_status i2d_shape_set_user_data(i2d_shape_id id, void* user_data) {
    return guarded("i2d_shape_set_user_data", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s)) {
            return last_status();
        }
        s.world->set_shape_user_data(s.index, user_data);
        return I2D_OK;
    });
}
