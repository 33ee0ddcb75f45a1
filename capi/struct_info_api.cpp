// SPDX-License-Identifier: MIT
// i2d_get_struct_infos: the size and alignment of every public struct, so that a binding
// that declares the structs itself can check them against the library it loaded.
#include "boundary.hpp"

namespace {

#define I2D_STRUCT_INFO(type) \
    i2d_struct_info { #type, static_cast<int32_t>(sizeof(type)), static_cast<int32_t>(alignof(type)) }

// Every typedef struct of include/impulse2d/*.h (tests/python checks that none is missing).
const i2d_struct_info struct_infos[] = {
    I2D_STRUCT_INFO(i2d_struct_info),
    I2D_STRUCT_INFO(i2d_world_id),
    I2D_STRUCT_INFO(i2d_body_id),
    I2D_STRUCT_INFO(i2d_shape_id),
    I2D_STRUCT_INFO(i2d_chain_id),
    I2D_STRUCT_INFO(i2d_vec2),
    I2D_STRUCT_INFO(i2d_rot),
    I2D_STRUCT_INFO(i2d_transform),
    I2D_STRUCT_INFO(i2d_aabb),
    I2D_STRUCT_INFO(i2d_filter),
    I2D_STRUCT_INFO(i2d_query_filter),
    I2D_STRUCT_INFO(i2d_world_def),
    I2D_STRUCT_INFO(i2d_body_def),
    I2D_STRUCT_INFO(i2d_shape_def),
    I2D_STRUCT_INFO(i2d_surface_material),
    I2D_STRUCT_INFO(i2d_chain_def),
    I2D_STRUCT_INFO(i2d_world_counters),
    I2D_STRUCT_INFO(i2d_profile),
    I2D_STRUCT_INFO(i2d_contact_begin_event),
    I2D_STRUCT_INFO(i2d_contact_end_event),
    I2D_STRUCT_INFO(i2d_contact_events),
    I2D_STRUCT_INFO(i2d_contact_hit_event),
    I2D_STRUCT_INFO(i2d_sensor_begin_event),
    I2D_STRUCT_INFO(i2d_sensor_end_event),
    I2D_STRUCT_INFO(i2d_sensor_events),
    I2D_STRUCT_INFO(i2d_body_move_event),
    I2D_STRUCT_INFO(i2d_body_quarantine_event),
    I2D_STRUCT_INFO(i2d_body_events),
    I2D_STRUCT_INFO(i2d_ray_result),
    I2D_STRUCT_INFO(i2d_circle),
    I2D_STRUCT_INFO(i2d_manifold_point),
    I2D_STRUCT_INFO(i2d_manifold),
    I2D_STRUCT_INFO(i2d_polygon),
    I2D_STRUCT_INFO(i2d_capsule),
    I2D_STRUCT_INFO(i2d_segment),
    I2D_STRUCT_INFO(i2d_mass_data),
    I2D_STRUCT_INFO(i2d_cast_output),
    I2D_STRUCT_INFO(i2d_joint_id),
    I2D_STRUCT_INFO(i2d_joint_base),
    I2D_STRUCT_INFO(i2d_revolute_joint_def),
    I2D_STRUCT_INFO(i2d_prismatic_joint_def),
    I2D_STRUCT_INFO(i2d_distance_joint_def),
    I2D_STRUCT_INFO(i2d_weld_joint_def),
    I2D_STRUCT_INFO(i2d_wheel_joint_def),
    I2D_STRUCT_INFO(i2d_motor_joint_def),
    I2D_STRUCT_INFO(i2d_mouse_joint_def),
    I2D_STRUCT_INFO(i2d_filter_joint_def),
    I2D_STRUCT_INFO(i2d_joint_event),
    I2D_STRUCT_INFO(i2d_joint_events),
    I2D_STRUCT_INFO(i2d_shape_proxy),
};

#undef I2D_STRUCT_INFO

}  // namespace

I2D_API int32_t i2d_get_struct_infos(const i2d_struct_info** out) {
    i2d::capi::set_ok();
    if (out != nullptr) {
        *out = struct_infos;
    }
    return static_cast<int32_t>(sizeof struct_infos / sizeof struct_infos[0]);
}
