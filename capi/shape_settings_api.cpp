// SPDX-License-Identifier: MIT
// i2d_shape_*: a shape's settings after creation: geometry, density, material, event
// flags; and their getters.
#include <cfloat>

#include "boundary.hpp"
#include "convert.hpp"
#include "geometry_checks.hpp"
#include "limits.hpp"
#include "loaded_values.hpp"
#include "shape_rules.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// A getter's value from a live shape, or `none` (with the status set) for a bad id.
template <class T, class Read>
T read_shape(const char* function, i2d_shape_id id, T none, Read&& read) {
    return guarded(function, none, [&](Call& call) {
        ShapeRef s;
        return call.shape(id, s) ? read(s.shape()) : none;
    });
}

// A chain's segments share their ghost points with their neighbours: they change only
// with their chain.
bool not_in_chain(Call& call, const ShapeRef& s) {
    return s.shape().chain == null_index ||
           call.fail(I2D_ERR_INVALID_ARGUMENT, "the shape is a chain's segment; chains change whole (destroy and "
                                               "create the chain)");
}

// `make` turns the caller's geometry into the core's, checked, or fails.
template <class Make>
i2d_status set_geometry(const char* function, i2d_shape_id id, Make&& make) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        Geometry g;
        if (!mutable_shape(call, id, s) || !not_in_chain(call, s) || !make(call, g) ||
            !valid_geometry(call, g, -1, "geometry")) {
            return last_status();
        }
        s.world->set_geometry(s.index, g);
        return I2D_OK;
    });
}

i2d_status set_shape_flag(const char* function, i2d_shape_id id, ShapeFlag flag, bool value) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s)) {
            return last_status();
        }
        s.world->set_shape_flag(s.index, flag, value);
        return I2D_OK;
    });
}

}  // namespace

I2D_API i2d_status i2d_shape_set_circle(i2d_shape_id id, const i2d_circle* circle) {
    return set_geometry("i2d_shape_set_circle", id, [&](Call& call, Geometry& g) {
        if (!call.not_null(circle, "circle")) {
            return false;
        }
        g.type = ShapeType::circle;
        g.circle = {to_core(circle->center), circle->radius};
        return true;
    });
}

I2D_API i2d_status i2d_shape_set_capsule(i2d_shape_id id, const i2d_capsule* capsule) {
    return set_geometry("i2d_shape_set_capsule", id, [&](Call& call, Geometry& g) {
        if (!call.not_null(capsule, "capsule")) {
            return false;
        }
        g.type = ShapeType::capsule;
        g.capsule = {to_core(capsule->center1), to_core(capsule->center2), capsule->radius};
        return true;
    });
}

I2D_API i2d_status i2d_shape_set_segment(i2d_shape_id id, const i2d_segment* segment) {
    return set_geometry("i2d_shape_set_segment", id, [&](Call& call, Geometry& g) {
        if (!call.not_null(segment, "segment")) {
            return false;
        }
        g.type = ShapeType::segment;
        g.segment = {to_core(segment->point1), to_core(segment->point2)};
        return true;
    });
}

I2D_API i2d_status i2d_shape_set_polygon(i2d_shape_id id, const i2d_polygon* polygon) {
    return set_geometry("i2d_shape_set_polygon", id, [&](Call& call, Geometry& g) {
        return call.not_null(polygon, "polygon") && polygon_geometry_of(call, polygon, g);
    });
}

I2D_API i2d_status i2d_shape_set_density(i2d_shape_id id, float density, bool update_body_mass) {
    return guarded("i2d_shape_set_density", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s) || !call.in_range(density, 0.0f, max_density, "density")) {
            return last_status();
        }
        s.world->set_density(s.index, density, update_body_mass);
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_shape_set_material(i2d_shape_id id, i2d_surface_material material) {
    return guarded("i2d_shape_set_material", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        ShapeRef s;
        if (!mutable_shape(call, id, s)) {
            return last_status();
        }
        const Material m{s.shape().density, material.friction, material.restitution, material.rolling_resistance,
                         material.tangent_speed};
        if (!checked_with_names("material", -1, [&](auto name) { return valid_material(call, m, name); })) {
            return last_status();
        }
        s.world->set_material(s.index, SurfaceMaterial{material.friction, material.restitution,
                                                       material.rolling_resistance, material.tangent_speed});
        return I2D_OK;
    });
}

I2D_API i2d_surface_material i2d_shape_get_material(i2d_shape_id id) {
    return read_shape("i2d_shape_get_material", id, i2d_surface_material{}, [](const Shape& s) {
        return i2d_surface_material{s.friction, s.restitution, s.rolling_resistance, s.tangent_speed};
    });
}

I2D_API i2d_status i2d_shape_enable_sensor_events(i2d_shape_id id, bool flag) {
    return set_shape_flag("i2d_shape_enable_sensor_events", id, ShapeFlag::sensor_events, flag);
}

I2D_API bool i2d_shape_are_sensor_events_enabled(i2d_shape_id id) {
    return read_shape("i2d_shape_are_sensor_events_enabled", id, false,
                      [](const Shape& s) { return s.enable_sensor_events; });
}

I2D_API i2d_status i2d_shape_enable_contact_events(i2d_shape_id id, bool flag) {
    return set_shape_flag("i2d_shape_enable_contact_events", id, ShapeFlag::contact_events, flag);
}

I2D_API bool i2d_shape_are_contact_events_enabled(i2d_shape_id id) {
    return read_shape("i2d_shape_are_contact_events_enabled", id, false,
                      [](const Shape& s) { return s.enable_contact_events; });
}

I2D_API i2d_status i2d_shape_enable_hit_events(i2d_shape_id id, bool flag) {
    return set_shape_flag("i2d_shape_enable_hit_events", id, ShapeFlag::hit_events, flag);
}

I2D_API bool i2d_shape_are_hit_events_enabled(i2d_shape_id id) {
    return read_shape("i2d_shape_are_hit_events_enabled", id, false,
                      [](const Shape& s) { return s.enable_hit_events; });
}

I2D_API i2d_status i2d_shape_enable_pre_solve_events(i2d_shape_id id, bool flag) {
    return set_shape_flag("i2d_shape_enable_pre_solve_events", id, ShapeFlag::pre_solve_events, flag);
}

I2D_API bool i2d_shape_are_pre_solve_events_enabled(i2d_shape_id id) {
    return read_shape("i2d_shape_are_pre_solve_events_enabled", id, false,
                      [](const Shape& s) { return s.enable_pre_solve_events; });
}
