/* SPDX-License-Identifier: MIT */
/* Offsets and sizes of the public structs as this compiler lays them out, for the
 * JavaScript binding: it reads and writes defs, events and results in the module's
 * memory by name instead of by offsets copied by hand, so a struct that grows a field
 * cannot silently shift what the binding writes. Linked into the .wasm only. */
#include <stddef.h>

#include <impulse2d/impulse2d.h>

typedef struct i2d_js_layout_entry {
    const char* name;
    int32_t value;
} i2d_js_layout_entry;

#define I2D_JS_SIZE(type) {#type, (int32_t)sizeof(type)}
#define I2D_JS_FIELD(type, field) {#type "." #field, (int32_t)offsetof(type, field)}

static const i2d_js_layout_entry k_layout[] = {
    I2D_JS_SIZE(i2d_world_def),
    I2D_JS_FIELD(i2d_world_def, gravity),
    I2D_JS_FIELD(i2d_world_def, contact_hertz),
    I2D_JS_FIELD(i2d_world_def, restitution_threshold),
    I2D_JS_FIELD(i2d_world_def, enable_sleep),
    I2D_JS_SIZE(i2d_body_def),
    I2D_JS_FIELD(i2d_body_def, type),
    I2D_JS_FIELD(i2d_body_def, position),
    I2D_JS_FIELD(i2d_body_def, rotation),
    I2D_JS_FIELD(i2d_body_def, linear_velocity),
    I2D_JS_FIELD(i2d_body_def, angular_velocity),
    I2D_JS_FIELD(i2d_body_def, linear_damping),
    I2D_JS_FIELD(i2d_body_def, angular_damping),
    I2D_JS_FIELD(i2d_body_def, gravity_scale),
    I2D_JS_FIELD(i2d_body_def, fixed_rotation),
    I2D_JS_FIELD(i2d_body_def, enable_sleep),
    I2D_JS_FIELD(i2d_body_def, user_data),
    I2D_JS_SIZE(i2d_shape_def),
    I2D_JS_FIELD(i2d_shape_def, density),
    I2D_JS_FIELD(i2d_shape_def, friction),
    I2D_JS_FIELD(i2d_shape_def, restitution),
    I2D_JS_FIELD(i2d_shape_def, is_sensor),
    I2D_JS_FIELD(i2d_shape_def, enable_contact_events),
    I2D_JS_SIZE(i2d_body_move_event),
    I2D_JS_FIELD(i2d_body_move_event, transform),
    I2D_JS_FIELD(i2d_body_move_event, body),
    I2D_JS_FIELD(i2d_body_move_event, user_data),
    I2D_JS_FIELD(i2d_body_move_event, fell_asleep),
    I2D_JS_SIZE(i2d_body_events),
    I2D_JS_FIELD(i2d_body_events, move_events),
    I2D_JS_FIELD(i2d_body_events, move_count),
    I2D_JS_FIELD(i2d_body_events, quarantine_events),
    I2D_JS_FIELD(i2d_body_events, quarantine_count),
    I2D_JS_SIZE(i2d_contact_events),
    I2D_JS_FIELD(i2d_contact_events, begin_events),
    I2D_JS_FIELD(i2d_contact_events, begin_count),
    I2D_JS_FIELD(i2d_contact_events, end_events),
    I2D_JS_FIELD(i2d_contact_events, end_count),
    I2D_JS_SIZE(i2d_contact_begin_event),
    I2D_JS_SIZE(i2d_contact_end_event),
    I2D_JS_SIZE(i2d_ray_result),
    I2D_JS_FIELD(i2d_ray_result, shape),
    I2D_JS_FIELD(i2d_ray_result, point),
    I2D_JS_FIELD(i2d_ray_result, normal),
    I2D_JS_FIELD(i2d_ray_result, fraction),
    I2D_JS_FIELD(i2d_ray_result, hit),
    I2D_JS_SIZE(i2d_world_counters),
    I2D_JS_FIELD(i2d_world_counters, body_count),
    I2D_JS_FIELD(i2d_world_counters, shape_count),
    I2D_JS_FIELD(i2d_world_counters, contact_count),
    I2D_JS_FIELD(i2d_world_counters, awake_body_count),
    I2D_JS_SIZE(i2d_polygon),
    I2D_JS_FIELD(i2d_polygon, vertices),
    I2D_JS_FIELD(i2d_polygon, radius),
    I2D_JS_FIELD(i2d_polygon, count),
    I2D_JS_FIELD(i2d_capsule, radius),
    I2D_JS_FIELD(i2d_circle, radius),
    I2D_JS_SIZE(i2d_query_filter),
    I2D_JS_SIZE(i2d_aabb),
};

/* Points *out at the table and returns its length. */
__attribute__((used, visibility("default"))) int32_t i2d_js_struct_layout(const i2d_js_layout_entry** out) {
    *out = k_layout;
    return (int32_t)(sizeof k_layout / sizeof k_layout[0]);
}
