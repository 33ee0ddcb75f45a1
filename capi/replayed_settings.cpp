// SPDX-License-Identifier: MIT
// Replaying the runtime API's records: a body's, a shape's and the world's settings.
// Each goes through the call a program makes, whose checks refuse a record no call could
// have written; geometry and world settings, which those calls build on the way, go to
// the core as recorded, after the same checks.
#include "convert.hpp"
#include "dynamics/recording/recorded_fields.hpp"
#include "loaded_values.hpp"
#include "replayed.hpp"
#include "shape_rules.hpp"
#include "world_def.hpp"

namespace i2d::capi {

namespace {

i2d_status apply_body_setting(i2d_body_id body, BodySetting setting, float value) {
    switch (setting) {
        case BodySetting::gravity_scale: return i2d_body_set_gravity_scale(body, value);
        case BodySetting::linear_damping: return i2d_body_set_linear_damping(body, value);
        case BodySetting::angular_damping: return i2d_body_set_angular_damping(body, value);
        case BodySetting::sleep_threshold: return i2d_body_set_sleep_threshold(body, value);
        case BodySetting::count: break;
    }
    return I2D_ERR_INVALID_ARGUMENT;
}

i2d_status apply_body_flag(i2d_body_id body, BodyFlag flag, bool value) {
    switch (flag) {
        case BodyFlag::bullet: return i2d_body_set_bullet(body, value);
        case BodyFlag::enable_sleep: return i2d_body_enable_sleep(body, value);
        case BodyFlag::fixed_rotation: return i2d_body_set_fixed_rotation(body, value);
        case BodyFlag::count: break;
    }
    return I2D_ERR_INVALID_ARGUMENT;
}

i2d_status apply_shape_flag(i2d_shape_id shape, ShapeFlag flag, bool value) {
    switch (flag) {
        case ShapeFlag::contact_events: return i2d_shape_enable_contact_events(shape, value);
        case ShapeFlag::sensor_events: return i2d_shape_enable_sensor_events(shape, value);
        case ShapeFlag::hit_events: return i2d_shape_enable_hit_events(shape, value);
        case ShapeFlag::pre_solve_events: return i2d_shape_enable_pre_solve_events(shape, value);
        case ShapeFlag::count: break;
    }
    return I2D_ERR_INVALID_ARGUMENT;
}

}  // namespace

bool Replayed::settings_call(RecordedOp op) const {
    int32_t index = 0;
    switch (op) {
        case RecordedOp::set_mass_data: {
            MassOverride mass;
            io(index), io(mass.overridden), io(mass.mass), io(mass.local_center), io(mass.inertia);
            if (!read_whole(in)) {
                return malformed(call);
            }
            return passed(mass.overridden ? i2d_body_set_mass_data(body(index), i2d_mass_data{mass.mass,
                                                                                    to_public(mass.local_center),
                                                                                    mass.inertia})
                                          : i2d_body_apply_mass_from_shapes(body(index)));
        }
        case RecordedOp::set_body_setting: {
            BodySetting setting = BodySetting::count;
            float value = 0.0f;
            io(index), io(setting), io(value);
            return read_whole(in) ? passed(apply_body_setting(body(index), setting, value)) : malformed(call);
        }
        case RecordedOp::set_body_flag: {
            BodyFlag flag = BodyFlag::count;
            bool value = false;
            io(index), io(flag), io(value);
            return read_whole(in) ? passed(apply_body_flag(body(index), flag, value)) : malformed(call);
        }
        case RecordedOp::set_shape_geometry: {
            Geometry geometry;
            io(index);
            geometry_fields(io, geometry);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.shapes().is_live(index), "shape") ||
                (world.shapes()[index].chain != null_index || geometry.type == ShapeType::chain_segment
                     ? call.fail(I2D_ERR_INVALID_SNAPSHOT, "a record changes a chain segment's geometry")
                     : !valid_geometry(call, geometry, index, "geometry"))) {
                return false;
            }
            world.set_geometry(index, geometry);
            return true;
        }
        case RecordedOp::set_shape_density: {
            float density = 0.0f;
            bool update_body_mass = false;
            io(index), io(density), io(update_body_mass);
            return read_whole(in) ? passed(i2d_shape_set_density(shape(index), density, update_body_mass))
                                  : malformed(call);
        }
        case RecordedOp::set_shape_material: {
            SurfaceMaterial m;
            io(index);
            surface_material_fields(io, m);
            return read_whole(in) ? passed(i2d_shape_set_material(shape(index), i2d_surface_material{m.friction,
                                                                                   m.restitution,
                                                                                   m.rolling_resistance,
                                                                                   m.tangent_speed}))
                                  : malformed(call);
        }
        case RecordedOp::set_shape_flag: {
            ShapeFlag flag = ShapeFlag::count;
            bool value = false;
            io(index), io(flag), io(value);
            return read_whole(in) ? passed(apply_shape_flag(shape(index), flag, value)) : malformed(call);
        }
        case RecordedOp::set_world_settings: {
            WorldDef settings = world.settings();  // the host's wiring as it is
            settings_fields(io, settings, recording_settings_versions);
            if (!read_whole(in)) {
                return malformed(call);
            }
            settings.length_units_per_meter = world.settings().length_units_per_meter;  // fixed at creation
            const i2d_world_def def = to_public(settings);
            if (!validate_world_def(call, &def)) {
                return false;
            }
            world.set_settings(settings);
            return true;
        }
        default:
            return unknown();
    }
}

}  // namespace i2d::capi
