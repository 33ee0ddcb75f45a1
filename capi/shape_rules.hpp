// SPDX-License-Identifier: MIT
// The C API's rules for a shape's values, shared by its create calls, its setters and the
// checks of shapes a snapshot or a recording brings in.
#pragma once

#include <cfloat>
#include <cstdint>

#include "boundary.hpp"
#include "limits.hpp"

namespace i2d::capi {

/// What a shape is made of, as a def gives it and a shape keeps it.
struct Material {
    float density, friction, restitution, rolling_resistance, tangent_speed;
};

/// name(field) spells each field in messages (loaded_values.hpp).
template <class Name>
bool valid_material(Call& call, const Material& m, Name name) {
    return call.in_range(m.density, 0.0f, max_density, name("density")) &&
           call.in_range(m.friction, 0.0f, FLT_MAX, name("friction")) &&
           call.in_range(m.restitution, 0.0f, max_restitution, name("restitution")) &&
           call.in_range(m.rolling_resistance, 0.0f, max_setting, name("rolling_resistance")) &&
           call.in_range(m.tangent_speed, -max_speed_limit, max_speed_limit, name("tangent_speed"));
}

/// The geometry a create call would have taken, each kind under its own call's rules;
/// `index` names the shape in messages (-1: none).
bool valid_geometry(Call& call, const Geometry& geometry, int32_t index, const char* name);

/// A caller's polygon made a shape's: checked as i2d_shape_create_polygon_from checks
/// it, its normals and centroid made again from its hull.
bool polygon_geometry_of(Call& call, const i2d_polygon* polygon, Geometry& out);

}  // namespace i2d::capi
