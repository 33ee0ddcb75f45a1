/* SPDX-License-Identifier: MIT */
/* C API bad input, part 1: world, body and shape defs, shape geometry of every kind, and
 * getters of the wrong kind. Every refusal of capi.md answers its status with a message
 * and leaves the world as it was. Also defines the fixture and snapshots shared with
 * test_api_errors_calls.c (test_api_errors.h). */
#include "test_api_errors.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* ---- Shared definitions (declared in test_api_errors.h) ----------------------------- */

const float k_non_finite[NON_FINITE_COUNT] = {NAN, INFINITY, -INFINITY};

const named_rot k_bad_rotations[] = {
    {"(2, 0)", 2.0f, 0.0f},
    {"zero (0, 0)", 0.0f, 0.0f},
    {"(0.5, 0.5)", 0.5f, 0.5f},
    {"(1, 0.1)", 1.0f, 0.1f},
    {"(1.0006, 0): c^2 + s^2 - 1 = 1.2e-3", 1.0006f, 0.0f},
    {"(0, 0.9994): c^2 + s^2 - 1 = -1.2e-3", 0.0f, 0.9994f},
    {"(-0.7, -0.8)", -0.7f, -0.8f},
    {"(-1, -1)", -1.0f, -1.0f},
    {"tiny (1e-20, 0)", 1e-20f, 0.0f},
    {"huge (1e20, 1e20)", 1e20f, 1e20f},
};

const named_rot k_unit_rotations[] = {
    {"identity", 1.0f, 0.0f},
    {"identity with s = -0", 1.0f, -0.0f},
    {"quarter turn (0, 1)", 0.0f, 1.0f},
    {"half turn (-1, 0)", -1.0f, 0.0f},
    {"three quarters (0, -1)", 0.0f, -1.0f},
    {"1e-3 rad", 0.9999995f, 0.001f},
    {"1e-5 rad", 1.0f, 1e-5f},
    {"(0.6, 0.8)", 0.6f, 0.8f},
    {"(1.0004, 0): c^2 + s^2 - 1 = 8e-4", 1.0004f, 0.0f},
    {"(0, -0.9996): c^2 + s^2 - 1 = -8e-4", 0.0f, -0.9996f},
    {"(0.6, 0.8) x 1.0004", 0.60024f, 0.80032f},
};
const int k_bad_rotation_count = (int)(sizeof k_bad_rotations / sizeof k_bad_rotations[0]);
const int k_unit_rotation_count = (int)(sizeof k_unit_rotations / sizeof k_unit_rotations[0]);

void check_accepted_at(const char* file, int line, const char* what, i2d_status returned) {
    i2d_status last = i2d_last_status();
    const char* message = i2d_last_error_message();
    char copy[256];
    copy_message(copy, sizeof copy, message);
    if (returned != I2D_OK || last != I2D_OK || message == NULL || message[0] != '\0') {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: returned %s, last status %s, message \"%s\"; expected I2D_OK, no message\n", file,
                line, what, i2d_status_string(returned), i2d_status_string(last), copy);
    }
}

/* Addresses used as user data; the same in both twins. */
static int k_tags[FIX_BODIES + FIX_SHAPES];

const float k_ball_y = 0.45f;

bool fixture_create(fixture* f) {
    memset(f, 0, sizeof *f);
    i2d_world_def world_def = i2d_default_world_def();
    f->world = i2d_world_create(&world_def);
    if (I2D_IS_NULL(f->world)) {
        return false;
    }

    i2d_body_def ground_def = i2d_default_body_def();
    ground_def.position = v2(0.0f, -1.0f);
    ground_def.user_data = &k_tags[0];
    f->body[FIX_GROUND] = i2d_body_create(f->world, &ground_def);

    i2d_body_def ball_def = i2d_default_body_def();
    ball_def.type = I2D_BODY_DYNAMIC;
    ball_def.position = v2(0.0f, k_ball_y);
    ball_def.linear_velocity = v2(1.0f, 0.0f);
    ball_def.user_data = &k_tags[1];
    f->body[FIX_BALL] = i2d_body_create(f->world, &ball_def);

    i2d_body_def mover_def = i2d_default_body_def();
    mover_def.type = I2D_BODY_KINEMATIC;
    mover_def.position = v2(-5.0f, 3.0f);
    mover_def.rotation = i2d_make_rot(0.25f);
    mover_def.linear_velocity = v2(0.5f, 0.0f);
    mover_def.angular_velocity = 0.5f;
    mover_def.user_data = &k_tags[2];
    f->body[FIX_MOVER] = i2d_body_create(f->world, &mover_def);

    i2d_shape_def shape_def = i2d_default_shape_def();
    shape_def.user_data = &k_tags[3];
    f->shape[FIX_GROUND_BOX] = i2d_shape_create_box(f->body[FIX_GROUND], &shape_def, 20.0f, 1.0f);

    i2d_circle ball_circle = {{0.3f, 0.0f}, 0.5f};
    shape_def.user_data = &k_tags[4];
    shape_def.restitution = 0.1f;
    f->shape[FIX_BALL_CIRCLE] = i2d_shape_create_circle(f->body[FIX_BALL], &shape_def, &ball_circle);

    shape_def.user_data = &k_tags[5];
    shape_def.density = 2.0f;
    shape_def.friction = 0.3f;
    shape_def.filter.category_bits = 2;
    shape_def.filter.group_index = 3;
    f->shape[FIX_BALL_BOX] = i2d_shape_create_box(f->body[FIX_BALL], &shape_def, 0.4f, 0.4f);

    i2d_circle mover_circle = {{0.0f, 0.0f}, 0.25f};
    shape_def = i2d_default_shape_def();
    shape_def.user_data = &k_tags[6];
    f->shape[FIX_MOVER_CIRCLE] = i2d_shape_create_circle(f->body[FIX_MOVER], &shape_def, &mover_circle);

    /* A segment high above the ground's left end, and a capsule on the mover: every
     * kind of shape, away from the ball and from the points the queries probe. */
    shape_def.user_data = &k_tags[7];
    f->shape[FIX_GROUND_SEGMENT] =
        i2d_shape_create_segment(f->body[FIX_GROUND], &shape_def, v2(-19.0f, 3.0f), v2(-17.0f, 3.0f));
    shape_def.user_data = &k_tags[8];
    f->shape[FIX_MOVER_CAPSULE] =
        i2d_shape_create_capsule(f->body[FIX_MOVER], &shape_def, v2(0.5f, 0.0f), v2(1.5f, 0.0f), 0.2f);

    for (int i = 0; i < FIX_BODIES; ++i) {
        if (I2D_IS_NULL(f->body[i])) {
            return false;
        }
    }
    for (int i = 0; i < FIX_SHAPES; ++i) {
        if (I2D_IS_NULL(f->shape[i])) {
            return false;
        }
    }
    return true;
}

void fixture_destroy(fixture* f) {
    if (!I2D_IS_NULL(f->world)) {
        i2d_world_destroy(f->world);
    }
    memset(f, 0, sizeof *f);
}

void run_on_fixture(fixture_test_body test_body) {
    fixture f;
    if (fixture_create(&f)) {
        test_body(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

void run_on_twins(twins_test_body test_body) {
    fixture a, b;
    bool built_a = fixture_create(&a);
    bool built_b = fixture_create(&b);
    if (built_a && built_b) {
        test_body(&a, &b);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&a);
    fixture_destroy(&b);
}

static void snap_put(snapshot* s, int object, const char* field, uint64_t value) {
    if (s->count >= SNAP_MAX) {
        ++i2d_check_failures;
        fprintf(stderr, "%s: snapshot too small for %s\n", __FILE__, field);
        return;
    }
    s->value[s->count] = value;
    s->field[s->count] = field;
    s->object[s->count] = object;
    ++s->count;
}

static void snap_float(snapshot* s, int object, const char* field, float f) {
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    snap_put(s, object, field, bits);
}

static void snap_vec2(snapshot* s, int object, const char* field_x, const char* field_y, i2d_vec2 v) {
    snap_float(s, object, field_x, v.x);
    snap_float(s, object, field_y, v.y);
}

static void snap_pointer(snapshot* s, int object, const char* field, const void* p) {
    snap_put(s, object, field, (uint64_t)(uintptr_t)p);
}

static void snap_body(snapshot* s, const fixture* f, int i) {
    i2d_body_id b = f->body[i];
    snap_put(s, i, "body.is_valid", i2d_body_is_valid(b));
    snap_put(s, i, "body.world", I2D_ID_EQUALS(i2d_body_get_world(b), f->world));
    snap_put(s, i, "body.type", (uint64_t)i2d_body_get_type(b));
    snap_vec2(s, i, "body.position.x", "body.position.y", i2d_body_get_position(b));
    i2d_rot q = i2d_body_get_rotation(b);
    snap_float(s, i, "body.rotation.c", q.c);
    snap_float(s, i, "body.rotation.s", q.s);
    i2d_transform t = i2d_body_get_transform(b);
    snap_vec2(s, i, "body.transform.p.x", "body.transform.p.y", t.p);
    snap_float(s, i, "body.transform.q.c", t.q.c);
    snap_float(s, i, "body.transform.q.s", t.q.s);
    snap_vec2(s, i, "body.linear_velocity.x", "body.linear_velocity.y", i2d_body_get_linear_velocity(b));
    snap_float(s, i, "body.angular_velocity", i2d_body_get_angular_velocity(b));
    snap_float(s, i, "body.mass", i2d_body_get_mass(b));
    snap_float(s, i, "body.rotational_inertia", i2d_body_get_rotational_inertia(b));
    snap_vec2(s, i, "body.center_of_mass.x", "body.center_of_mass.y", i2d_body_get_world_center_of_mass(b));
    snap_vec2(s, i, "body.local_center_of_mass.x", "body.local_center_of_mass.y",
              i2d_body_get_local_center_of_mass(b));
    snap_put(s, i, "body.is_awake", i2d_body_is_awake(b));
    snap_pointer(s, i, "body.user_data", i2d_body_get_user_data(b));
    i2d_mass_data mass = i2d_body_get_mass_data(b);
    snap_float(s, i, "body.mass_data.mass", mass.mass);
    snap_vec2(s, i, "body.mass_data.center.x", "body.mass_data.center.y", mass.center);
    snap_float(s, i, "body.mass_data.rotational_inertia", mass.rotational_inertia);
    snap_float(s, i, "body.gravity_scale", i2d_body_get_gravity_scale(b));
    snap_float(s, i, "body.linear_damping", i2d_body_get_linear_damping(b));
    snap_float(s, i, "body.angular_damping", i2d_body_get_angular_damping(b));
    snap_float(s, i, "body.sleep_threshold", i2d_body_get_sleep_threshold(b));
    snap_put(s, i, "body.is_bullet", i2d_body_is_bullet(b));
    snap_put(s, i, "body.is_sleep_enabled", i2d_body_is_sleep_enabled(b));
    snap_put(s, i, "body.is_fixed_rotation", i2d_body_is_fixed_rotation(b));
    snap_put(s, i, "body.shape_count", (uint64_t)(int64_t)i2d_body_get_shape_count(b));

    /* The shape list, as indices into the fixture (ids differ between twins). */
    i2d_shape_id shapes[8];
    int32_t n = i2d_body_get_shapes(b, shapes, 8);
    snap_put(s, i, "body.get_shapes count", (uint64_t)(int64_t)n);
    for (int32_t k = 0; k < n && k < 8; ++k) {
        uint64_t index = 99;
        for (int j = 0; j < FIX_SHAPES; ++j) {
            if (I2D_ID_EQUALS(shapes[k], f->shape[j])) {
                index = (uint64_t)j;
            }
        }
        snap_put(s, i, "body.get_shapes entry", index);
    }
}

/* The shape's geometry in its body frame, through the getter of its kind. */
static void snap_geometry(snapshot* s, int object, i2d_shape_id sh, i2d_shape_type type) {
    if (type == I2D_SHAPE_CIRCLE) {
        i2d_circle c = i2d_shape_get_circle(sh);
        snap_vec2(s, object, "shape.circle.center.x", "shape.circle.center.y", c.center);
        snap_float(s, object, "shape.circle.radius", c.radius);
    } else if (type == I2D_SHAPE_CAPSULE) {
        i2d_capsule c = i2d_shape_get_capsule(sh);
        snap_vec2(s, object, "shape.capsule.center1.x", "shape.capsule.center1.y", c.center1);
        snap_vec2(s, object, "shape.capsule.center2.x", "shape.capsule.center2.y", c.center2);
        snap_float(s, object, "shape.capsule.radius", c.radius);
    } else if (type == I2D_SHAPE_SEGMENT) {
        i2d_segment g = i2d_shape_get_segment(sh);
        snap_vec2(s, object, "shape.segment.point1.x", "shape.segment.point1.y", g.point1);
        snap_vec2(s, object, "shape.segment.point2.x", "shape.segment.point2.y", g.point2);
    } else {
        i2d_polygon p = i2d_shape_get_polygon(sh);
        snap_put(s, object, "shape.polygon.count", (uint64_t)(int64_t)p.count);
        for (int k = 0; k < I2D_MAX_POLYGON_VERTICES; ++k) {
            snap_vec2(s, object, "shape.polygon.vertex.x", "shape.polygon.vertex.y", p.vertices[k]);
            snap_vec2(s, object, "shape.polygon.normal.x", "shape.polygon.normal.y", p.normals[k]);
        }
        snap_vec2(s, object, "shape.polygon.centroid.x", "shape.polygon.centroid.y", p.centroid);
        snap_float(s, object, "shape.polygon.radius", p.radius);
    }
}

static void snap_shape(snapshot* s, const fixture* f, int j) {
    i2d_shape_id sh = f->shape[j];
    int object = 100 + j;
    snap_put(s, object, "shape.is_valid", i2d_shape_is_valid(sh));
    uint64_t body_index = 99;
    i2d_body_id owner = i2d_shape_get_body(sh);
    for (int i = 0; i < FIX_BODIES; ++i) {
        if (I2D_ID_EQUALS(owner, f->body[i])) {
            body_index = (uint64_t)i;
        }
    }
    snap_put(s, object, "shape.body", body_index);
    i2d_shape_type type = i2d_shape_get_type(sh);
    snap_put(s, object, "shape.type", (uint64_t)type);
    snap_geometry(s, object, sh, type);
    i2d_aabb bounds = i2d_shape_get_aabb(sh);
    snap_vec2(s, object, "shape.aabb.min.x", "shape.aabb.min.y", bounds.min);
    snap_vec2(s, object, "shape.aabb.max.x", "shape.aabb.max.y", bounds.max);
    snap_float(s, object, "shape.density", i2d_shape_get_density(sh));
    snap_float(s, object, "shape.friction", i2d_shape_get_friction(sh));
    snap_float(s, object, "shape.restitution", i2d_shape_get_restitution(sh));
    i2d_filter filter = i2d_shape_get_filter(sh);
    snap_put(s, object, "shape.filter.category_bits", filter.category_bits);
    snap_put(s, object, "shape.filter.mask_bits", filter.mask_bits);
    snap_put(s, object, "shape.filter.group_index", (uint64_t)(int64_t)filter.group_index);
    snap_put(s, object, "shape.is_sensor", i2d_shape_is_sensor(sh));
    i2d_surface_material material = i2d_shape_get_material(sh);
    snap_float(s, object, "shape.material.rolling_resistance", material.rolling_resistance);
    snap_float(s, object, "shape.material.tangent_speed", material.tangent_speed);
    snap_put(s, object, "shape.sensor_events", i2d_shape_are_sensor_events_enabled(sh));
    snap_put(s, object, "shape.contact_events", i2d_shape_are_contact_events_enabled(sh));
    snap_put(s, object, "shape.hit_events", i2d_shape_are_hit_events_enabled(sh));
    snap_pointer(s, object, "shape.user_data", i2d_shape_get_user_data(sh));
}

void snapshot_take(const fixture* f, snapshot* s) {
    s->count = 0;
    snap_vec2(s, -1, "world.gravity.x", "world.gravity.y", i2d_world_get_gravity(f->world));
    i2d_world_counters counters = i2d_world_get_counters(f->world);
    snap_put(s, -1, "world.body_count", (uint64_t)(int64_t)counters.body_count);
    snap_put(s, -1, "world.shape_count", (uint64_t)(int64_t)counters.shape_count);
    snap_put(s, -1, "world.contact_count", (uint64_t)(int64_t)counters.contact_count);
    snap_put(s, -1, "world.pair_count", (uint64_t)(int64_t)counters.pair_count);
    snap_put(s, -1, "world.state_hash", i2d_world_get_state_hash(f->world));
    i2d_world_def settings = i2d_world_get_settings(f->world);
    snap_put(s, -1, "world.enable_sleep", settings.enable_sleep);
    snap_put(s, -1, "world.enable_continuous", settings.enable_continuous);
    snap_float(s, -1, "world.contact_hertz", settings.contact_hertz);
    snap_float(s, -1, "world.contact_damping_ratio", settings.contact_damping_ratio);
    snap_float(s, -1, "world.contact_push_max_speed", settings.contact_push_max_speed);
    snap_float(s, -1, "world.joint_hertz", settings.joint_hertz);
    snap_float(s, -1, "world.joint_damping_ratio", settings.joint_damping_ratio);
    snap_float(s, -1, "world.restitution_threshold", settings.restitution_threshold);
    snap_float(s, -1, "world.hit_event_threshold", settings.hit_event_threshold);
    snap_pointer(s, -1, "world.user_data", i2d_world_get_user_data(f->world));
    for (int i = 0; i < FIX_BODIES; ++i) {
        snap_body(s, f, i);
    }
    for (int j = 0; j < FIX_SHAPES; ++j) {
        snap_shape(s, f, j);
    }
}

void check_same_snapshot_at(const char* file, int line, const char* what, const snapshot* expected,
                            const snapshot* actual) {
    if (expected->count != actual->count) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: after %s: snapshot has %d values, expected %d\n", file, line, what, actual->count,
                expected->count);
        return;
    }
    for (int k = 0; k < expected->count; ++k) {
        if (expected->value[k] != actual->value[k]) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: after %s: %s of object %d changed (bits 0x%llx, expected 0x%llx)\n", file, line,
                    what, expected->field[k], expected->object[k], (unsigned long long)actual->value[k],
                    (unsigned long long)expected->value[k]);
            return;
        }
    }
}

void check_unchanged_at(const char* file, int line, const char* what, const fixture* f, const snapshot* before) {
    static snapshot now; /* static: large, and tests run one at a time */
    snapshot_take(f, &now);
    check_same_snapshot_at(file, line, what, before, &now);
}

void check_twins_agree_after_steps(const fixture* a, const fixture* b) {
    static snapshot sa, sb;
    for (int i = 0; i < 10; ++i) {
        I2D_CHECK_STATUS(i2d_world_step(a->world, 1.0f / 60.0f, 4), I2D_OK);
        I2D_CHECK_STATUS(i2d_world_step(b->world, 1.0f / 60.0f, 4), I2D_OK);
    }
    snapshot_take(a, &sa);
    snapshot_take(b, &sb);
    CHECK_SAME_SNAPSHOT("stepping both twins 10 times", &sb, &sa);
}

void set_float_at(void* object, size_t offset, float value) { memcpy((char*)object + offset, &value, sizeof value); }

void bad_aabbs(i2d_aabb* out, int* count) {
    int n = 0;
    for (int field = 0; field < 4; ++field) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_aabb b = box(-1.0f, -1.0f, 1.0f, 1.0f);
            float* corner[4] = {&b.min.x, &b.min.y, &b.max.x, &b.max.y};
            *corner[field] = k_non_finite[k];
            out[n++] = b;
        }
    }
    out[n++] = box(1.0f, -1.0f, -1.0f, 1.0f);  /* min.x > max.x */
    out[n++] = box(-1.0f, 1.0f, 1.0f, -1.0f);  /* min.y > max.y */
    out[n++] = box(0.5f, 0.5f, 0.49f, 0.49f); /* both */
    *count = n;
}

void check_stored_rotation_at(const char* file, int line, const char* what, i2d_rot stored, float c, float s) {
    double length = sqrt((double)c * c + (double)s * s);
    double ec = c / length, es = s / length;
    double norm = (double)stored.c * stored.c + (double)stored.s * stored.s;
    if (!(fabs(norm - 1.0) <= 1e-6 && fabs(stored.c - ec) <= 1e-6 && fabs(stored.s - es) <= 1e-6)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: stored rotation (%.9g, %.9g), expected (%.9g, %.9g) normalised\n", file, line, what,
                stored.c, stored.s, ec, es);
    }
}

/* ---- World defs ------------------------------------------------------------------- */

static const float_field k_world_def_floats[] = {
    {"gravity.x", offsetof(i2d_world_def, gravity.x)},
    {"gravity.y", offsetof(i2d_world_def, gravity.y)},
    {"contact_slop", offsetof(i2d_world_def, contact_slop)},
    {"contact_hertz", offsetof(i2d_world_def, contact_hertz)},
    {"contact_damping_ratio", offsetof(i2d_world_def, contact_damping_ratio)},
    {"contact_push_max_speed", offsetof(i2d_world_def, contact_push_max_speed)},
    {"restitution_threshold", offsetof(i2d_world_def, restitution_threshold)},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed)},
    {"sleep_speed_threshold", offsetof(i2d_world_def, sleep_speed_threshold)},
    {"time_to_sleep", offsetof(i2d_world_def, time_to_sleep)},
    {"joint_hertz", offsetof(i2d_world_def, joint_hertz)},
    {"joint_damping_ratio", offsetof(i2d_world_def, joint_damping_ratio)},
    {"hit_event_threshold", offsetof(i2d_world_def, hit_event_threshold)},
};

/* Finite values outside the documented ranges. */
static const float_field_value k_world_def_out_of_range[] = {
    {"contact_slop", offsetof(i2d_world_def, contact_slop), -0.001f},
    {"contact_slop", offsetof(i2d_world_def, contact_slop), 1.5f},
    {"contact_hertz", offsetof(i2d_world_def, contact_hertz), 0.0f},
    {"contact_hertz", offsetof(i2d_world_def, contact_hertz), -30.0f},
    {"contact_hertz", offsetof(i2d_world_def, contact_hertz), 2e5f},
    {"contact_damping_ratio", offsetof(i2d_world_def, contact_damping_ratio), -0.1f},
    {"contact_damping_ratio", offsetof(i2d_world_def, contact_damping_ratio), 2e5f},
    {"joint_hertz", offsetof(i2d_world_def, joint_hertz), 0.0f},
    {"joint_hertz", offsetof(i2d_world_def, joint_hertz), -30.0f},
    {"joint_hertz", offsetof(i2d_world_def, joint_hertz), 2e5f},
    {"joint_damping_ratio", offsetof(i2d_world_def, joint_damping_ratio), -0.1f},
    {"joint_damping_ratio", offsetof(i2d_world_def, joint_damping_ratio), 2e5f},
    {"contact_push_max_speed", offsetof(i2d_world_def, contact_push_max_speed), -1.0f},
    {"contact_push_max_speed", offsetof(i2d_world_def, contact_push_max_speed), 2e5f},
    {"sleep_speed_threshold", offsetof(i2d_world_def, sleep_speed_threshold), -0.01f},
    {"time_to_sleep", offsetof(i2d_world_def, time_to_sleep), -1.0f},
    {"time_to_sleep", offsetof(i2d_world_def, time_to_sleep), 2e5f},
    {"restitution_threshold", offsetof(i2d_world_def, restitution_threshold), -1.0f},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed), 0.0f},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed), -1.0f},
    {"hit_event_threshold", offsetof(i2d_world_def, hit_event_threshold), -0.5f},
    {"hit_event_threshold", offsetof(i2d_world_def, hit_event_threshold), 2e5f},
};

/* The edges of the same ranges, which must be accepted. */
static const float_field_value k_world_def_in_range[] = {
    {"gravity.x", offsetof(i2d_world_def, gravity.x), -1e6f},
    {"gravity.y", offsetof(i2d_world_def, gravity.y), 1e6f},
    {"contact_slop", offsetof(i2d_world_def, contact_slop), 0.0f},
    {"contact_slop", offsetof(i2d_world_def, contact_slop), 1.0f},
    {"contact_hertz", offsetof(i2d_world_def, contact_hertz), 0.001f},
    {"contact_hertz", offsetof(i2d_world_def, contact_hertz), 1e5f},
    {"contact_damping_ratio", offsetof(i2d_world_def, contact_damping_ratio), 0.0f},
    {"joint_hertz", offsetof(i2d_world_def, joint_hertz), 0.001f},
    {"joint_hertz", offsetof(i2d_world_def, joint_hertz), 1e5f},
    {"joint_damping_ratio", offsetof(i2d_world_def, joint_damping_ratio), 0.0f},
    {"contact_push_max_speed", offsetof(i2d_world_def, contact_push_max_speed), 0.0f},
    {"sleep_speed_threshold", offsetof(i2d_world_def, sleep_speed_threshold), 0.0f},
    {"time_to_sleep", offsetof(i2d_world_def, time_to_sleep), 0.0f},
    {"restitution_threshold", offsetof(i2d_world_def, restitution_threshold), 0.0f},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed), 0.001f},
    {"hit_event_threshold", offsetof(i2d_world_def, hit_event_threshold), 0.0f},
    {"hit_event_threshold", offsetof(i2d_world_def, hit_event_threshold), 1e5f},
};

static void check_world_def_refused_at(int line, const char* what, const i2d_world_def* def) {
    i2d_world_id world = i2d_world_create(def);
    check_refused_at(__FILE__, line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(world)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a world was created\n", __FILE__, line, what);
        i2d_world_destroy(world);
    }
}

static void check_world_def_accepted_at(int line, const char* what, const i2d_world_def* def) {
    i2d_world_id world = i2d_world_create(def);
    check_accepted_at(__FILE__, line, what, i2d_last_status());
    if (I2D_IS_NULL(world)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: no world was created\n", __FILE__, line, what);
    } else {
        i2d_world_destroy(world);
    }
}

I2D_TEST(api_errors_world_def_bad_values) {
    char what[128];
    for (size_t i = 0; i < sizeof k_world_def_floats / sizeof k_world_def_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_world_def def = i2d_default_world_def();
            set_float_at(&def, k_world_def_floats[i].offset, k_non_finite[k]);
            snprintf(what, sizeof what, "world def %s = %g", k_world_def_floats[i].name, k_non_finite[k]);
            check_world_def_refused_at(__LINE__, what, &def);
        }
    }
    for (size_t i = 0; i < sizeof k_world_def_out_of_range / sizeof k_world_def_out_of_range[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        set_float_at(&def, k_world_def_out_of_range[i].offset, k_world_def_out_of_range[i].value);
        snprintf(what, sizeof what, "world def %s = %g", k_world_def_out_of_range[i].name,
                 k_world_def_out_of_range[i].value);
        check_world_def_refused_at(__LINE__, what, &def);
    }
    /* Enum fields holding values no i2d_mixing_rule has (a C caller can store any int). */
    static const int bad_rules[] = {-1, 5, 1000, INT32_MIN};
    for (size_t i = 0; i < sizeof bad_rules / sizeof bad_rules[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        def.friction_mixing = (i2d_mixing_rule)bad_rules[i];
        snprintf(what, sizeof what, "world def friction_mixing = %d", bad_rules[i]);
        check_world_def_refused_at(__LINE__, what, &def);
        def = i2d_default_world_def();
        def.restitution_mixing = (i2d_mixing_rule)bad_rules[i];
        snprintf(what, sizeof what, "world def restitution_mixing = %d", bad_rules[i]);
        check_world_def_refused_at(__LINE__, what, &def);
    }
    static const int bad_paths[] = {-1, 6, 1000, INT32_MIN};
    for (size_t i = 0; i < sizeof bad_paths / sizeof bad_paths[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        def.simd_path = (i2d_simd_path)bad_paths[i];
        snprintf(what, sizeof what, "world def simd_path = %d", bad_paths[i]);
        check_world_def_refused_at(__LINE__, what, &def);
        I2D_CHECK(!i2d_simd_path_supported((i2d_simd_path)bad_paths[i]));
    }

    /* The edges of every range are accepted, so the refusals above are about the values. */
    for (size_t i = 0; i < sizeof k_world_def_in_range / sizeof k_world_def_in_range[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        set_float_at(&def, k_world_def_in_range[i].offset, k_world_def_in_range[i].value);
        snprintf(what, sizeof what, "world def %s = %g", k_world_def_in_range[i].name, k_world_def_in_range[i].value);
        check_world_def_accepted_at(__LINE__, what, &def);
    }
    static const i2d_mixing_rule good_rules[] = {I2D_MIX_GEOMETRIC_MEAN, I2D_MIX_MINIMUM, I2D_MIX_MAXIMUM,
                                                 I2D_MIX_AVERAGE, I2D_MIX_MULTIPLY};
    for (size_t i = 0; i < sizeof good_rules / sizeof good_rules[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        def.friction_mixing = good_rules[i];
        def.restitution_mixing = good_rules[i];
        snprintf(what, sizeof what, "world def mixing rules = %d", (int)good_rules[i]);
        check_world_def_accepted_at(__LINE__, what, &def);
    }
    /* Every path this machine supports is accepted; one it does not is refused. */
    static const i2d_simd_path paths[] = {I2D_SIMD_AUTOMATIC, I2D_SIMD_SCALAR, I2D_SIMD_SSE2, I2D_SIMD_AVX2,
                                          I2D_SIMD_AVX512,    I2D_SIMD_NEON, I2D_SIMD_WASM128};
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        def.simd_path = paths[i];
        snprintf(what, sizeof what, "world def simd_path = %d", (int)paths[i]);
        if (i2d_simd_path_supported(paths[i])) {
            check_world_def_accepted_at(__LINE__, what, &def);
        } else {
            check_world_def_refused_at(__LINE__, what, &def);
        }
    }
    I2D_CHECK(i2d_simd_path_supported(I2D_SIMD_AUTOMATIC) && i2d_simd_path_supported(I2D_SIMD_SCALAR));
}

I2D_TEST(api_errors_world_def_not_from_default) {
    check_world_def_refused_at(__LINE__, "i2d_world_create(NULL)", NULL);

    i2d_world_def zeroed;
    memset(&zeroed, 0, sizeof zeroed);
    check_world_def_refused_at(__LINE__, "world def zeroed with memset", &zeroed);

    /* A def whose fields are all valid but whose cookie is wrong: only the cookie refuses it. */
    i2d_world_def def = i2d_default_world_def();
    I2D_CHECK(def.internal_cookie != 0);
    def.internal_cookie ^= 1u;
    check_world_def_refused_at(__LINE__, "world def cookie ^ 1", &def);
    def.internal_cookie = 0;
    check_world_def_refused_at(__LINE__, "world def cookie 0", &def);
    def.internal_cookie = i2d_default_world_def().internal_cookie + 0x10000u;
    check_world_def_refused_at(__LINE__, "world def cookie + 0x10000", &def);
}

/* ---- Body defs -------------------------------------------------------------------- */

static const float_field k_body_def_floats[] = {
    {"position.x", offsetof(i2d_body_def, position.x)},
    {"position.y", offsetof(i2d_body_def, position.y)},
    {"rotation.c", offsetof(i2d_body_def, rotation.c)},
    {"rotation.s", offsetof(i2d_body_def, rotation.s)},
    {"linear_velocity.x", offsetof(i2d_body_def, linear_velocity.x)},
    {"linear_velocity.y", offsetof(i2d_body_def, linear_velocity.y)},
    {"angular_velocity", offsetof(i2d_body_def, angular_velocity)},
    {"linear_damping", offsetof(i2d_body_def, linear_damping)},
    {"angular_damping", offsetof(i2d_body_def, angular_damping)},
    {"gravity_scale", offsetof(i2d_body_def, gravity_scale)},
};

/* Finite values outside the documented ranges. Any finite angular velocity is fine. */
static const float_field_value k_body_def_out_of_range[] = {
    {"linear_damping", offsetof(i2d_body_def, linear_damping), -0.1f},
    {"angular_damping", offsetof(i2d_body_def, angular_damping), -1.0f},
    {"angular_damping", offsetof(i2d_body_def, angular_damping), -1e-30f},
    {"position.x", offsetof(i2d_body_def, position.x), 2e9f},
    {"position.y", offsetof(i2d_body_def, position.y), -2e9f},
};

/* A body def refused by i2d_body_create leaves the fixture exactly as it was. */
static void check_body_def_refused_at(int line, const char* what, const fixture* f, const i2d_body_def* def,
                                      const snapshot* before) {
    i2d_body_id body = i2d_body_create(f->world, def);
    check_refused_at(__FILE__, line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(body)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a body was created\n", __FILE__, line, what);
        i2d_body_destroy(body);
        return;
    }
    check_unchanged_at(__FILE__, line, what, f, before);
}

static void run_body_def_bad_values(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    char what[128];
    for (size_t i = 0; i < sizeof k_body_def_floats / sizeof k_body_def_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_body_def def = i2d_default_body_def();
            def.type = I2D_BODY_DYNAMIC;
            set_float_at(&def, k_body_def_floats[i].offset, k_non_finite[k]);
            snprintf(what, sizeof what, "body def %s = %g", k_body_def_floats[i].name, k_non_finite[k]);
            check_body_def_refused_at(__LINE__, what, f, &def, &before);
        }
    }
    for (size_t i = 0; i < sizeof k_body_def_out_of_range / sizeof k_body_def_out_of_range[0]; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        set_float_at(&def, k_body_def_out_of_range[i].offset, k_body_def_out_of_range[i].value);
        snprintf(what, sizeof what, "body def %s = %g", k_body_def_out_of_range[i].name,
                 k_body_def_out_of_range[i].value);
        check_body_def_refused_at(__LINE__, what, f, &def, &before);
    }
    /* Rotations that are not unit length within 1e-3, on every body type. */
    static const i2d_body_type types[] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    for (int i = 0; i < k_bad_rotation_count; ++i) {
        for (size_t t = 0; t < 3; ++t) {
            i2d_body_def def = i2d_default_body_def();
            def.type = types[t];
            def.rotation = rot(k_bad_rotations[i].c, k_bad_rotations[i].s);
            snprintf(what, sizeof what, "body def (type %d) rotation %s", (int)types[t], k_bad_rotations[i].name);
            check_body_def_refused_at(__LINE__, what, f, &def, &before);
        }
    }
    /* A bad rotation is refused even with a valid angle's worth of spin and vice versa. */
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_KINEMATIC;
    def.rotation = i2d_make_rot(0.3f);
    def.angular_velocity = NAN;
    check_body_def_refused_at(__LINE__, "body def make_rot(0.3), angular_velocity NaN", f, &def, &before);
    def.angular_velocity = 2.0f;
    def.rotation.c *= 1.01f; /* c^2 + s^2 about 1.02 */
    check_body_def_refused_at(__LINE__, "body def rotation make_rot(0.3) with c x 1.01", f, &def, &before);
    /* Enum values that name no body type. */
    static const int bad_types[] = {3, 7, -1};
    for (size_t i = 0; i < sizeof bad_types / sizeof bad_types[0]; ++i) {
        def = i2d_default_body_def();
        def.type = (i2d_body_type)bad_types[i];
        snprintf(what, sizeof what, "body def type = %d", bad_types[i]);
        check_body_def_refused_at(__LINE__, what, f, &def, &before);
    }
}

I2D_TEST(api_errors_body_def_bad_values) { run_on_fixture(run_body_def_bad_values); }

/* Any finite angular velocity is accepted. */
static const float k_angular_velocities[] = {-0.0f, 1.0f, -1e-3f, 100.0f, -1e6f, FLT_MAX, -FLT_MAX};
enum { ANGULAR_VELOCITY_COUNT = sizeof k_angular_velocities / sizeof k_angular_velocities[0] };

/* Values at the edges of the body def ranges: each creates a body. */
static void run_body_def_accepted(i2d_world_id world) {
    char what[128];
    int created = 0;
    for (int i = 0; i < k_unit_rotation_count; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        def.rotation = rot(k_unit_rotations[i].c, k_unit_rotations[i].s);
        i2d_body_id body = i2d_body_create(world, &def);
        snprintf(what, sizeof what, "body def rotation %s", k_unit_rotations[i].name);
        check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
        I2D_CHECK(!I2D_IS_NULL(body));
        created += I2D_IS_NULL(body) ? 0 : 1;
        check_stored_rotation_at(__FILE__, __LINE__, what, i2d_body_get_rotation(body), k_unit_rotations[i].c,
                                 k_unit_rotations[i].s);
    }
    /* A rotation built by i2d_make_rot, on a static body. */
    i2d_body_def def = i2d_default_body_def();
    def.rotation = i2d_make_rot(0.3f);
    i2d_body_id body = i2d_body_create(world, &def);
    CHECK_ACCEPTED("body def rotation i2d_make_rot(0.3)", i2d_last_status());
    created += I2D_IS_NULL(body) ? 0 : 1;
    i2d_rot q = i2d_body_get_rotation(body);
    I2D_CHECK_NEAR(q.c, cos(0.3), 1e-6);
    I2D_CHECK_NEAR(q.s, sin(0.3), 1e-6);

    /* Any finite angular velocity is accepted; beyond 1e5 rad/s it is clamped to that
     * at creation (a finite 1e30 once became NaN within a step). */
    for (int i = 0; i < ANGULAR_VELOCITY_COUNT; ++i) {
        def = i2d_default_body_def();
        def.type = I2D_BODY_KINEMATIC;
        def.angular_velocity = k_angular_velocities[i];
        body = i2d_body_create(world, &def);
        snprintf(what, sizeof what, "kinematic body def angular_velocity %g", k_angular_velocities[i]);
        check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
        created += I2D_IS_NULL(body) ? 0 : 1;
        I2D_CHECK(i2d_body_get_angular_velocity(body) == (k_angular_velocities[i] > 1e5f    ? 1e5f
                                                          : k_angular_velocities[i] < -1e5f ? -1e5f
                                                                                            : k_angular_velocities[i]));
        def.type = I2D_BODY_DYNAMIC;
        body = i2d_body_create(world, &def);
        snprintf(what, sizeof what, "dynamic body def angular_velocity %g", k_angular_velocities[i]);
        check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
        created += I2D_IS_NULL(body) ? 0 : 1;
    }
    /* The spin of a dynamic body's def is its spin once its shapes let it turn: bodies are
     * created before their shapes, so a def's angular velocity must survive them. */
    def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.angular_velocity = 2.0f;
    body = i2d_body_create(world, &def);
    created += I2D_IS_NULL(body) ? 0 : 1;
    i2d_shape_def shape_def = i2d_default_shape_def();
    I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_box(body, &shape_def, 0.5f, 0.5f)));
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 2.0f);
    /* A static body never moves, whatever its def says. */
    def = i2d_default_body_def();
    def.angular_velocity = 3.0f;
    body = i2d_body_create(world, &def);
    CHECK_ACCEPTED("static body def angular_velocity 3", i2d_last_status());
    created += I2D_IS_NULL(body) ? 0 : 1;
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 0.0f);

    def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.angular_velocity = -0.0f;
    def.gravity_scale = -2.0f; /* documented: may be negative */
    def.linear_damping = 0.0f;
    def.angular_damping = 5.0f;
    def.position = v2(1e9f, -1e9f); /* the edge of the world */
    def.fixed_rotation = true;
    body = i2d_body_create(world, &def);
    CHECK_ACCEPTED("body def position (1e9, -1e9), gravity_scale -2, angular_damping 5, fixed rotation",
                   i2d_last_status());
    created += I2D_IS_NULL(body) ? 0 : 1;
    static const i2d_body_type types[] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    for (size_t i = 0; i < 3; ++i) {
        def = i2d_default_body_def();
        def.type = types[i];
        body = i2d_body_create(world, &def);
        CHECK_ACCEPTED("body def with each valid type", i2d_last_status());
        created += I2D_IS_NULL(body) ? 0 : 1;
        I2D_CHECK(i2d_body_get_type(body) == types[i]);
    }
    I2D_CHECK(created == k_unit_rotation_count + 1 + 2 * ANGULAR_VELOCITY_COUNT + 2 + 1 + 3);
    I2D_CHECK(i2d_world_get_counters(world).body_count == created);
}

I2D_TEST(api_errors_body_def_edges_accepted) { run_in_default_world(run_body_def_accepted); }

static void run_body_def_not_from_default(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    check_body_def_refused_at(__LINE__, "i2d_body_create(world, NULL)", f, NULL, &before);

    i2d_body_def zeroed;
    memset(&zeroed, 0, sizeof zeroed);
    check_body_def_refused_at(__LINE__, "body def zeroed with memset", f, &zeroed, &before);

    i2d_body_def def = i2d_default_body_def();
    I2D_CHECK(def.internal_cookie != 0);
    def.internal_cookie ^= 1u;
    check_body_def_refused_at(__LINE__, "body def cookie ^ 1", f, &def, &before);
    def.internal_cookie = 0;
    check_body_def_refused_at(__LINE__, "body def cookie 0", f, &def, &before);
}

I2D_TEST(api_errors_body_def_not_from_default) { run_on_fixture(run_body_def_not_from_default); }

/* ---- Shape creators ------------------------------------------------------------------ */

/* The refused creation returned the null id with INVALID_ARGUMENT and a message, and the
 * fixture is as it was. Call right after the creator: it reads the recorded status. */
static void check_creation_refused_at(int line, const char* what, const fixture* f, i2d_shape_id shape,
                                      const snapshot* before) {
    check_refused_at(__FILE__, line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(shape)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a shape was created\n", __FILE__, line, what);
        i2d_shape_destroy(shape);
        return;
    }
    check_unchanged_at(__FILE__, line, what, f, before);
}

/* Every creator with valid geometry, so that the def alone decides. */
typedef i2d_shape_id (*creator)(i2d_body_id body, const i2d_shape_def* def);

static const i2d_vec2 k_triangle[3] = {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.0f, 0.5f}};

static i2d_shape_id create_a_circle(i2d_body_id body, const i2d_shape_def* def) {
    const i2d_circle circle = {{0.0f, 0.5f}, 0.25f};
    return i2d_shape_create_circle(body, def, &circle);
}
static i2d_shape_id create_a_box(i2d_body_id body, const i2d_shape_def* def) {
    return i2d_shape_create_box(body, def, 0.25f, 0.25f);
}
static i2d_shape_id create_an_offset_box(i2d_body_id body, const i2d_shape_def* def) {
    return i2d_shape_create_offset_box(body, def, 0.25f, 0.125f, v2(0.2f, 0.1f), rot(0.6f, 0.8f));
}
static i2d_shape_id create_a_polygon(i2d_body_id body, const i2d_shape_def* def) {
    return i2d_shape_create_polygon(body, def, k_triangle, 3);
}
static i2d_shape_id create_a_polygon_from(i2d_body_id body, const i2d_shape_def* def) {
    const i2d_polygon polygon = i2d_make_box(0.25f, 0.25f);
    return i2d_shape_create_polygon_from(body, def, &polygon);
}
static i2d_shape_id create_a_capsule(i2d_body_id body, const i2d_shape_def* def) {
    return i2d_shape_create_capsule(body, def, v2(-0.25f, 0.0f), v2(0.25f, 0.0f), 0.1f);
}
static i2d_shape_id create_a_segment(i2d_body_id body, const i2d_shape_def* def) {
    return i2d_shape_create_segment(body, def, v2(-0.25f, 0.0f), v2(0.25f, 0.0f));
}

typedef struct creator_row {
    const char* name;
    creator create;
} creator_row;

static const creator_row k_creators[] = {
    {"circle", create_a_circle},   {"box", create_a_box},           {"offset box", create_an_offset_box},
    {"polygon", create_a_polygon}, {"polygon from", create_a_polygon_from}, {"capsule", create_a_capsule},
    {"segment", create_a_segment},
};
enum { CREATOR_COUNT = sizeof k_creators / sizeof k_creators[0] };

static const float_field k_shape_def_floats[] = {
    {"density", offsetof(i2d_shape_def, density)},
    {"friction", offsetof(i2d_shape_def, friction)},
    {"restitution", offsetof(i2d_shape_def, restitution)},
    {"rolling_resistance", offsetof(i2d_shape_def, rolling_resistance)},
    {"tangent_speed", offsetof(i2d_shape_def, tangent_speed)},
};

static const float_field_value k_shape_def_out_of_range[] = {
    {"density", offsetof(i2d_shape_def, density), -1.0f},
    {"density", offsetof(i2d_shape_def, density), -1e-30f},
    {"density", offsetof(i2d_shape_def, density), 2e10f},
    {"friction", offsetof(i2d_shape_def, friction), -0.5f},
    {"restitution", offsetof(i2d_shape_def, restitution), -0.5f},
    {"restitution", offsetof(i2d_shape_def, restitution), 101.0f},
    {"rolling_resistance", offsetof(i2d_shape_def, rolling_resistance), -0.1f},
    {"rolling_resistance", offsetof(i2d_shape_def, rolling_resistance), 2e5f},
    {"tangent_speed", offsetof(i2d_shape_def, tangent_speed), 2e5f},
    {"tangent_speed", offsetof(i2d_shape_def, tangent_speed), -2e5f},
};

/* Every shape def refused by every creator. */
static void run_shape_def_bad_values(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_body_id ball = f->body[FIX_BALL];
    char what[160];
    for (int c = 0; c < CREATOR_COUNT; ++c) {
        const creator_row* row = &k_creators[c];
        for (size_t i = 0; i < sizeof k_shape_def_floats / sizeof k_shape_def_floats[0]; ++i) {
            for (int k = 0; k < NON_FINITE_COUNT; ++k) {
                i2d_shape_def def = i2d_default_shape_def();
                set_float_at(&def, k_shape_def_floats[i].offset, k_non_finite[k]);
                snprintf(what, sizeof what, "%s with shape def %s = %g", row->name, k_shape_def_floats[i].name,
                         k_non_finite[k]);
                check_creation_refused_at(__LINE__, what, f, row->create(ball, &def), &before);
            }
        }
        for (size_t i = 0; i < sizeof k_shape_def_out_of_range / sizeof k_shape_def_out_of_range[0]; ++i) {
            i2d_shape_def def = i2d_default_shape_def();
            set_float_at(&def, k_shape_def_out_of_range[i].offset, k_shape_def_out_of_range[i].value);
            snprintf(what, sizeof what, "%s with shape def %s = %g", row->name, k_shape_def_out_of_range[i].name,
                     k_shape_def_out_of_range[i].value);
            check_creation_refused_at(__LINE__, what, f, row->create(ball, &def), &before);
        }

        /* Defs that did not come from the default function, and a missing def. */
        i2d_shape_def zeroed;
        memset(&zeroed, 0, sizeof zeroed);
        snprintf(what, sizeof what, "%s with a zeroed shape def", row->name);
        check_creation_refused_at(__LINE__, what, f, row->create(ball, &zeroed), &before);
        i2d_shape_def bad_cookie = i2d_default_shape_def();
        I2D_CHECK(bad_cookie.internal_cookie != 0);
        bad_cookie.internal_cookie ^= 1u;
        snprintf(what, sizeof what, "%s with shape def cookie ^ 1", row->name);
        check_creation_refused_at(__LINE__, what, f, row->create(ball, &bad_cookie), &before);
        bad_cookie.internal_cookie = 0;
        snprintf(what, sizeof what, "%s with shape def cookie 0", row->name);
        check_creation_refused_at(__LINE__, what, f, row->create(ball, &bad_cookie), &before);
        snprintf(what, sizeof what, "%s with a NULL shape def", row->name);
        check_creation_refused_at(__LINE__, what, f, row->create(ball, NULL), &before);
    }
}

I2D_TEST(api_errors_shape_def_bad_values) { run_on_fixture(run_shape_def_bad_values); }

/* ---- Shape geometry: one float of a valid shape replaced ------------------------------ */

typedef i2d_shape_id (*geometry_call)(i2d_body_id body, const i2d_shape_def* def, float value);

static i2d_shape_id circle_center_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    const i2d_circle c = {{v, 0.5f}, 0.25f};
    return i2d_shape_create_circle(b, d, &c);
}
static i2d_shape_id circle_center_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    const i2d_circle c = {{0.0f, v}, 0.25f};
    return i2d_shape_create_circle(b, d, &c);
}
static i2d_shape_id circle_radius(i2d_body_id b, const i2d_shape_def* d, float v) {
    const i2d_circle c = {{0.0f, 0.5f}, v};
    return i2d_shape_create_circle(b, d, &c);
}
static i2d_shape_id box_half_width(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_box(b, d, v, 0.25f);
}
static i2d_shape_id box_half_height(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_box(b, d, 0.25f, v);
}
static i2d_shape_id offset_box_half_width(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_offset_box(b, d, v, 0.25f, v2(0.5f, 0.0f), rot(0.6f, 0.8f));
}
static i2d_shape_id offset_box_half_height(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_offset_box(b, d, 0.25f, v, v2(0.5f, 0.0f), rot(0.6f, 0.8f));
}
static i2d_shape_id offset_box_center_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_offset_box(b, d, 0.25f, 0.25f, v2(v, 0.0f), rot(0.6f, 0.8f));
}
static i2d_shape_id offset_box_center_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_offset_box(b, d, 0.25f, 0.25f, v2(0.5f, v), rot(0.6f, 0.8f));
}
static i2d_shape_id offset_box_rotation_c(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_offset_box(b, d, 0.25f, 0.25f, v2(0.5f, 0.0f), rot(v, 0.0f));
}
static i2d_shape_id offset_box_rotation_s(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_offset_box(b, d, 0.25f, 0.25f, v2(0.5f, 0.0f), rot(1.0f, v));
}
static i2d_shape_id polygon_point_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_vec2 points[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    points[1].x = v;
    return i2d_shape_create_polygon(b, d, points, 4);
}
static i2d_shape_id polygon_point_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_vec2 points[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    points[3].y = v;
    return i2d_shape_create_polygon(b, d, points, 4);
}
static i2d_shape_id polygon_from_vertex_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.vertices[1].x = v;
    return i2d_shape_create_polygon_from(b, d, &p);
}
static i2d_shape_id polygon_from_vertex_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.vertices[3].y = v;
    return i2d_shape_create_polygon_from(b, d, &p);
}
static i2d_shape_id polygon_from_normal_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.normals[2].x = v;
    return i2d_shape_create_polygon_from(b, d, &p);
}
static i2d_shape_id polygon_from_centroid_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.centroid.y = v;
    return i2d_shape_create_polygon_from(b, d, &p);
}
static i2d_shape_id polygon_from_radius(i2d_body_id b, const i2d_shape_def* d, float v) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.radius = v;
    return i2d_shape_create_polygon_from(b, d, &p);
}
static i2d_shape_id capsule_center1_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_capsule(b, d, v2(v, 0.0f), v2(1.0f, 0.0f), 0.25f);
}
static i2d_shape_id capsule_center1_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_capsule(b, d, v2(-1.0f, v), v2(1.0f, 0.0f), 0.25f);
}
static i2d_shape_id capsule_center2_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_capsule(b, d, v2(-1.0f, 0.0f), v2(v, 0.0f), 0.25f);
}
static i2d_shape_id capsule_center2_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_capsule(b, d, v2(-1.0f, 0.0f), v2(1.0f, v), 0.25f);
}
static i2d_shape_id capsule_radius(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_capsule(b, d, v2(-1.0f, 0.0f), v2(1.0f, 0.0f), v);
}
static i2d_shape_id segment_point1_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_segment(b, d, v2(v, 0.0f), v2(1.0f, 0.0f));
}
static i2d_shape_id segment_point1_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_segment(b, d, v2(-1.0f, v), v2(1.0f, 0.0f));
}
static i2d_shape_id segment_point2_x(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_segment(b, d, v2(-1.0f, 0.0f), v2(v, 0.0f));
}
static i2d_shape_id segment_point2_y(i2d_body_id b, const i2d_shape_def* d, float v) {
    return i2d_shape_create_segment(b, d, v2(-1.0f, 0.0f), v2(1.0f, v));
}

typedef struct geometry_row {
    const char* name;
    geometry_call call;
} geometry_row;

/* Every float of every creator's geometry: each refuses NaN and infinities. */
static const geometry_row k_geometry_floats[] = {
    {"circle center.x", circle_center_x},
    {"circle center.y", circle_center_y},
    {"circle radius", circle_radius},
    {"box half_width", box_half_width},
    {"box half_height", box_half_height},
    {"offset box half_width", offset_box_half_width},
    {"offset box half_height", offset_box_half_height},
    {"offset box center.x", offset_box_center_x},
    {"offset box center.y", offset_box_center_y},
    {"offset box rotation.c", offset_box_rotation_c},
    {"offset box rotation.s", offset_box_rotation_s},
    {"polygon points[1].x", polygon_point_x},
    {"polygon points[3].y", polygon_point_y},
    {"polygon_from vertices[1].x", polygon_from_vertex_x},
    {"polygon_from vertices[3].y", polygon_from_vertex_y},
    {"polygon_from normals[2].x", polygon_from_normal_x},
    {"polygon_from centroid.y", polygon_from_centroid_y},
    {"polygon_from radius", polygon_from_radius},
    {"capsule center1.x", capsule_center1_x},
    {"capsule center1.y", capsule_center1_y},
    {"capsule center2.x", capsule_center2_x},
    {"capsule center2.y", capsule_center2_y},
    {"capsule radius", capsule_radius},
    {"segment point1.x", segment_point1_x},
    {"segment point1.y", segment_point1_y},
    {"segment point2.x", segment_point2_x},
    {"segment point2.y", segment_point2_y},
};

/* Sizes (radii and half extents, from 0.0001 to 100,000 m): zero, negative, too small
 * or too large. */
static const float k_bad_sizes[] = {0.0f, -0.0f, -1.0f, -1e-30f, 5e-5f, 100001.0f, 1e30f};
static const geometry_row k_geometry_sizes[] = {
    {"circle radius", circle_radius},
    {"box half_width", box_half_width},
    {"box half_height", box_half_height},
    {"offset box half_width", offset_box_half_width},
    {"offset box half_height", offset_box_half_height},
    {"capsule radius", capsule_radius},
};

/* Points beyond 1e9 m of the body origin. */
static const float k_far_coordinates[] = {2e9f, -2e9f, 1e30f};
static const geometry_row k_geometry_points[] = {
    {"circle center.x", circle_center_x},
    {"circle center.y", circle_center_y},
    {"offset box center.x", offset_box_center_x},
    {"offset box center.y", offset_box_center_y},
    {"polygon points[1].x", polygon_point_x},
    {"polygon points[3].y", polygon_point_y},
    {"polygon_from vertices[1].x", polygon_from_vertex_x},
    {"capsule center1.x", capsule_center1_x},
    {"capsule center2.y", capsule_center2_y},
    {"segment point1.y", segment_point1_y},
    {"segment point2.x", segment_point2_x},
};

/* A table row with one value: the call must be refused and change nothing. */
static void check_geometry_refused_at(int line, const fixture* f, const geometry_row* row, float value,
                                      const snapshot* before) {
    char what[160];
    snprintf(what, sizeof what, "%s = %g", row->name, value);
    const i2d_shape_def def = i2d_default_shape_def();
    i2d_shape_id shape = row->call(f->body[FIX_BALL], &def, value);
    check_creation_refused_at(line, what, f, shape, before);
}

static void run_bad_geometry(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    for (size_t i = 0; i < sizeof k_geometry_floats / sizeof k_geometry_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            check_geometry_refused_at(__LINE__, f, &k_geometry_floats[i], k_non_finite[k], &before);
        }
    }
    for (size_t i = 0; i < sizeof k_geometry_sizes / sizeof k_geometry_sizes[0]; ++i) {
        for (size_t k = 0; k < sizeof k_bad_sizes / sizeof k_bad_sizes[0]; ++k) {
            check_geometry_refused_at(__LINE__, f, &k_geometry_sizes[i], k_bad_sizes[k], &before);
        }
    }
    for (size_t i = 0; i < sizeof k_geometry_points / sizeof k_geometry_points[0]; ++i) {
        for (size_t k = 0; k < sizeof k_far_coordinates / sizeof k_far_coordinates[0]; ++k) {
            check_geometry_refused_at(__LINE__, f, &k_geometry_points[i], k_far_coordinates[k], &before);
        }
    }
    /* A rounded polygon's radius is a size too: negative or beyond 100,000 m. */
    static const geometry_row polygon_radius = {"polygon_from radius", polygon_from_radius};
    static const float bad_radii[] = {-0.1f, -1e-30f, 100001.0f};
    for (size_t k = 0; k < sizeof bad_radii / sizeof bad_radii[0]; ++k) {
        check_geometry_refused_at(__LINE__, f, &polygon_radius, bad_radii[k], &before);
    }
}

I2D_TEST(api_errors_shape_bad_geometry) { run_on_fixture(run_bad_geometry); }

/* An offset box turned by a rotation that is not unit length within 1e-3. */
static void run_offset_box_bad_rotations(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_shape_def def = i2d_default_shape_def();
    char what[160];
    for (int i = 0; i < k_bad_rotation_count; ++i) {
        snprintf(what, sizeof what, "offset box rotation %s", k_bad_rotations[i].name);
        i2d_shape_id shape = i2d_shape_create_offset_box(f->body[FIX_BALL], &def, 0.25f, 0.25f, v2(0.5f, 0.0f),
                                                         rot(k_bad_rotations[i].c, k_bad_rotations[i].s));
        check_creation_refused_at(__LINE__, what, f, shape, &before);
    }
}

I2D_TEST(api_errors_offset_box_bad_rotations) { run_on_fixture(run_offset_box_bad_rotations); }

const point_set k_bad_point_sets[] = {
    {"count 2", 2, {{0.0f, 0.0f}, {1.0f, 0.0f}}},
    {"count 9 (a valid nonagon's points)",
     9,
     {{1.0f, 0.0f}, {0.77f, 0.64f}, {0.17f, 0.98f}, {-0.5f, 0.87f}, {-0.94f, 0.34f}, {-0.94f, -0.34f}, {-0.5f, -0.87f},
      {0.17f, -0.98f}, {0.77f, -0.64f}}},
    {"count 0", 0, {{0.0f, 0.0f}}},
    {"count -1", -1, {{0.0f, 0.0f}}},
    {"collinear", 3, {{0.0f, 0.0f}, {1.0f, 0.0f}, {2.0f, 0.0f}}},
    {"collinear, four points", 4, {{0.0f, 0.0f}, {1.0f, 1.0f}, {3.0f, 3.0f}, {-2.0f, -2.0f}}},
    {"nearly collinear (0.004 m off the line)", 3, {{0.0f, 0.0f}, {1.0f, 0.0f}, {2.0f, 0.004f}}},
    {"duplicate: two points 0.004 m apart", 3, {{0.0f, 0.0f}, {0.004f, 0.0f}, {1.0f, 1.0f}}},
    {"duplicate: the same point three times", 3, {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}},
    {"duplicate: two pairs", 4, {{0.0f, 0.0f}, {0.0f, 0.001f}, {1.0f, 0.0f}, {1.001f, 0.0f}}},
    {"tiny: area below 0.005^2", 3, {{0.0f, 0.0f}, {0.006f, 0.0f}, {0.0f, 0.006f}}},
};
const int k_bad_point_set_count = (int)(sizeof k_bad_point_sets / sizeof k_bad_point_sets[0]);

static void run_polygon_bad_points(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_shape_def def = i2d_default_shape_def();
    const i2d_body_id ball = f->body[FIX_BALL];
    char what[160];
    for (int i = 0; i < k_bad_point_set_count; ++i) {
        const point_set* set = &k_bad_point_sets[i];
        snprintf(what, sizeof what, "i2d_shape_create_polygon %s", set->name);
        check_creation_refused_at(__LINE__, what, f, i2d_shape_create_polygon(ball, &def, set->points, set->count),
                                  &before);
    }
    check_creation_refused_at(__LINE__, "i2d_shape_create_polygon NULL points", f,
                              i2d_shape_create_polygon(ball, &def, NULL, 3), &before);
    check_creation_refused_at(__LINE__, "i2d_shape_create_polygon NULL points, count 0", f,
                              i2d_shape_create_polygon(ball, &def, NULL, 0), &before);
}

I2D_TEST(api_errors_polygon_bad_points) { run_on_fixture(run_polygon_bad_points); }

/* Polygons not made by i2d_make_polygon or i2d_make_box, or spoiled after. */
static void run_polygon_from_bad(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_shape_def def = i2d_default_shape_def();
    const i2d_body_id ball = f->body[FIX_BALL];
    char what[160];

    check_creation_refused_at(__LINE__, "i2d_shape_create_polygon_from NULL polygon", f,
                              i2d_shape_create_polygon_from(ball, &def, NULL), &before);
    i2d_polygon zeroed;
    memset(&zeroed, 0, sizeof zeroed);
    check_creation_refused_at(__LINE__, "polygon_from a zeroed polygon (count 0)", f,
                              i2d_shape_create_polygon_from(ball, &def, &zeroed), &before);
    static const int32_t bad_counts[] = {0, 1, 2, 9, -1, INT32_MAX};
    for (size_t i = 0; i < sizeof bad_counts / sizeof bad_counts[0]; ++i) {
        i2d_polygon p = i2d_make_box(0.5f, 0.5f);
        p.count = bad_counts[i];
        snprintf(what, sizeof what, "polygon_from a box with count %d", (int)bad_counts[i]);
        check_creation_refused_at(__LINE__, what, f, i2d_shape_create_polygon_from(ball, &def, &p), &before);
    }
    /* What i2d_make_box gives for a bad size: the zero polygon. */
    i2d_polygon failed = i2d_make_box(-1.0f, 1.0f);
    I2D_CHECK(failed.count == 0);
    check_creation_refused_at(__LINE__, "polygon_from i2d_make_box(-1, 1)", f,
                              i2d_shape_create_polygon_from(ball, &def, &failed), &before);
    /* NaN in each vertex in turn. */
    for (int v = 0; v < 4; ++v) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_polygon p = i2d_make_box(0.5f, 0.5f);
            p.vertices[v].y = k_non_finite[k];
            snprintf(what, sizeof what, "polygon_from a box with vertices[%d].y = %g", v, k_non_finite[k]);
            check_creation_refused_at(__LINE__, what, f, i2d_shape_create_polygon_from(ball, &def, &p), &before);
        }
    }
    /* Documented: checked to be convex, counter-clockwise and consistent. */
    i2d_polygon square = i2d_make_box(0.5f, 0.5f);
    i2d_polygon clockwise = square;
    for (int i = 0; i < 4; ++i) {
        int j = (i + 1) % 4;
        clockwise.vertices[i] = square.vertices[3 - i];
        /* The normals of the reversed edges, so that only the winding is wrong. */
        i2d_vec2 a = square.vertices[3 - i], b = square.vertices[3 - j];
        float dx = b.x - a.x, dy = b.y - a.y, len = sqrtf(dx * dx + dy * dy);
        clockwise.normals[i] = v2(dy / len, -dx / len);
    }
    check_creation_refused_at(__LINE__, "polygon_from a clockwise square", f,
                              i2d_shape_create_polygon_from(ball, &def, &clockwise), &before);
    i2d_polygon dart = i2d_make_box(1.0f, 1.0f);
    dart.vertices[2] = v2(0.0f, -0.5f); /* the upper right corner pulled inside: not convex */
    check_creation_refused_at(__LINE__, "polygon_from a dart (not convex)", f,
                              i2d_shape_create_polygon_from(ball, &def, &dart), &before);
    i2d_polygon wrong_normal = square;
    wrong_normal.normals[0] = v2(0.0f, 1.0f); /* unit, but the bottom edge's normal is (0, -1) */
    check_creation_refused_at(__LINE__, "polygon_from a square with a wrong normal", f,
                              i2d_shape_create_polygon_from(ball, &def, &wrong_normal), &before);
    i2d_polygon long_normal = square;
    long_normal.normals[1] = v2(2.0f, 0.0f);
    check_creation_refused_at(__LINE__, "polygon_from a square with a normal of length 2", f,
                              i2d_shape_create_polygon_from(ball, &def, &long_normal), &before);
    /* Collinear or tiny vertices with matching normals. */
    i2d_polygon flat = square;
    flat.vertices[2] = v2(0.5f, -0.5f);
    flat.vertices[3] = v2(-0.5f, -0.5f);
    check_creation_refused_at(__LINE__, "polygon_from a square flattened to a line", f,
                              i2d_shape_create_polygon_from(ball, &def, &flat), &before);
}

I2D_TEST(api_errors_polygon_from_bad) { run_on_fixture(run_polygon_from_bad); }

/* Capsules whose centres and segments whose points are closer than 0.005 m. */
static void run_short_cores(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_shape_def def = i2d_default_shape_def();
    const i2d_body_id ball = f->body[FIX_BALL];
    char what[160];
    static const i2d_vec2 offsets[] = {
        {0.0f, 0.0f}, {0.0049f, 0.0f}, {0.0f, -0.0049f}, {0.003f, 0.003f}, {1e-30f, 0.0f},
    };
    for (size_t i = 0; i < sizeof offsets / sizeof offsets[0]; ++i) {
        i2d_vec2 a = v2(0.25f, 0.5f), b = v2(0.25f + offsets[i].x, 0.5f + offsets[i].y);
        snprintf(what, sizeof what, "capsule centres %g, %g apart", offsets[i].x, offsets[i].y);
        check_creation_refused_at(__LINE__, what, f, i2d_shape_create_capsule(ball, &def, a, b, 0.25f), &before);
        snprintf(what, sizeof what, "segment points %g, %g apart", offsets[i].x, offsets[i].y);
        check_creation_refused_at(__LINE__, what, f, i2d_shape_create_segment(ball, &def, a, b), &before);
    }
}

I2D_TEST(api_errors_short_capsules_and_segments) { run_on_fixture(run_short_cores); }

/* The largest documented sizes, the shortest cores, unit rotations within 1e-3, 3 and 8
 * points, and a density of 0 are accepted. */
static void run_shape_edges_accepted(i2d_world_id world) {
    i2d_body_def body_def = i2d_default_body_def();
    i2d_body_id body = i2d_body_create(world, &body_def);
    i2d_shape_def def = i2d_default_shape_def();
    def.density = 0.0f;
    def.friction = 0.0f;
    def.restitution = 0.0f;
    int created = 0;
    i2d_circle circle = {{0.0f, 0.0f}, 100000.0f};
    i2d_shape_id s = i2d_shape_create_circle(body, &def, &circle);
    CHECK_ACCEPTED("circle radius 100000", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    circle.radius = 0.0001f;
    circle.center = v2(1e5f, -1e5f);
    s = i2d_shape_create_circle(body, &def, &circle);
    CHECK_ACCEPTED("circle radius 0.0001 at (1e5, -1e5)", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    s = i2d_shape_create_box(body, &def, 100000.0f, 100000.0f);
    CHECK_ACCEPTED("box half extents 100000", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    def.density = 1e10f;
    def.restitution = 100.0f;
    s = i2d_shape_create_box(body, &def, 0.0001f, 0.0001f);
    CHECK_ACCEPTED("box half extents 0.0001, density 1e10, restitution 100", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    def.density = 1.0f;
    def.restitution = 0.0f;

    char what[160];
    for (int i = 0; i < k_unit_rotation_count; ++i) {
        snprintf(what, sizeof what, "offset box rotation %s", k_unit_rotations[i].name);
        s = i2d_shape_create_offset_box(body, &def, 0.5f, 0.25f, v2(2.0f, 0.0f),
                                        rot(k_unit_rotations[i].c, k_unit_rotations[i].s));
        check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
        created += I2D_IS_NULL(s) ? 0 : 1;
        /* Still a box of the sizes asked: the rotation was normalised. */
        i2d_polygon p = i2d_shape_get_polygon(s);
        I2D_CHECK(p.count == 4);
        double dx = (double)p.vertices[1].x - p.vertices[0].x, dy = (double)p.vertices[1].y - p.vertices[0].y;
        I2D_CHECK_NEAR(sqrt(dx * dx + dy * dy), 1.0, 1e-5);
    }
    s = i2d_shape_create_offset_box(body, &def, 100000.0f, 0.0001f, v2(-1e5f, 1e5f), i2d_make_rot(-2.0f));
    CHECK_ACCEPTED("offset box 100000 x 0.0001 at (-1e5, 1e5)", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;

    const i2d_vec2 octagon[8] = {{1.0f, 0.0f},   {0.7f, 0.7f},   {0.0f, 1.0f},  {-0.7f, 0.7f},
                                 {-1.0f, 0.0f}, {-0.7f, -0.7f}, {0.0f, -1.0f}, {0.7f, -0.7f}};
    s = i2d_shape_create_polygon(body, &def, octagon, 8);
    CHECK_ACCEPTED("polygon of 8 points", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    I2D_CHECK(i2d_shape_get_polygon(s).count == 8);
    s = i2d_shape_create_polygon(body, &def, k_triangle, 3);
    CHECK_ACCEPTED("polygon of 3 points", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    /* Points just 0.006 m apart are two points. */
    const i2d_vec2 thin[3] = {{0.0f, 0.0f}, {0.006f, 0.0f}, {0.003f, 1.0f}};
    s = i2d_shape_create_polygon(body, &def, thin, 3);
    CHECK_ACCEPTED("polygon with two points 0.006 m apart", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    i2d_polygon rounded;
    I2D_CHECK_STATUS(i2d_make_polygon(octagon, 8, 100000.0f, &rounded), I2D_OK);
    s = i2d_shape_create_polygon_from(body, &def, &rounded);
    CHECK_ACCEPTED("polygon_from an octagon rounded by 100000", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;

    s = i2d_shape_create_capsule(body, &def, v2(0.0f, 0.0f), v2(0.0051f, 0.0f), 100000.0f);
    CHECK_ACCEPTED("capsule centres 0.0051 apart, radius 100000", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    s = i2d_shape_create_capsule(body, &def, v2(-1e5f, 0.0f), v2(-1e5f, 0.0051f), 0.0001f);
    CHECK_ACCEPTED("capsule radius 0.0001 at x = -1e5", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    s = i2d_shape_create_segment(body, &def, v2(0.0f, 0.0f), v2(0.0f, 0.0051f));
    CHECK_ACCEPTED("segment 0.0051 long", i2d_last_status());
    created += I2D_IS_NULL(s) ? 0 : 1;
    I2D_CHECK(created == 4 + k_unit_rotation_count + 1 + 4 + 3);
    I2D_CHECK(i2d_world_get_counters(world).shape_count == created);

    /* Geometry beyond 100000 m from its body's origin is refused (its inertia would
     * overflow): every creator that takes body-frame points. */
    const float beyond = 100001.0f;
    circle.center = v2(beyond, 0.0f);
    I2D_CHECK(I2D_IS_NULL(i2d_shape_create_circle(body, &def, &circle)));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(I2D_IS_NULL(i2d_shape_create_offset_box(body, &def, 1.0f, 1.0f, v2(0.0f, -beyond), i2d_make_rot(0.0f))));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(I2D_IS_NULL(i2d_shape_create_capsule(body, &def, v2(beyond, 0.0f), v2(0.0f, 0.0f), 1.0f)));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(I2D_IS_NULL(i2d_shape_create_segment(body, &def, v2(0.0f, 0.0f), v2(0.0f, beyond))));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    const i2d_vec2 far_triangle[3] = {{0.0f, 0.0f}, {beyond, 0.0f}, {0.0f, 1.0f}};
    I2D_CHECK(I2D_IS_NULL(i2d_shape_create_polygon(body, &def, far_triangle, 3)));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_get_counters(world).shape_count == created);
}

I2D_TEST(api_errors_shape_edges_accepted) { run_in_default_world(run_shape_edges_accepted); }

/* ---- Getters of the wrong shape kind ------------------------------------------------ */

/* Each getter on each kind: the right kind answers, the others refuse with zeros. */
static bool read_kind(i2d_shape_id shape, i2d_shape_type getter) {
    switch (getter) {
    case I2D_SHAPE_CIRCLE: {
        i2d_circle c = i2d_shape_get_circle(shape);
        return c.center.x != 0.0f || c.center.y != 0.0f || c.radius != 0.0f;
    }
    case I2D_SHAPE_CAPSULE: {
        i2d_capsule c = i2d_shape_get_capsule(shape);
        return c.center1.x != 0.0f || c.center1.y != 0.0f || c.center2.x != 0.0f || c.center2.y != 0.0f ||
               c.radius != 0.0f;
    }
    case I2D_SHAPE_SEGMENT: {
        i2d_segment g = i2d_shape_get_segment(shape);
        return g.point1.x != 0.0f || g.point1.y != 0.0f || g.point2.x != 0.0f || g.point2.y != 0.0f;
    }
    default: {
        i2d_polygon p = i2d_shape_get_polygon(shape);
        bool nonzero = p.count != 0 || p.radius != 0.0f || p.centroid.x != 0.0f || p.centroid.y != 0.0f;
        for (int k = 0; k < I2D_MAX_POLYGON_VERTICES; ++k) {
            nonzero = nonzero || p.vertices[k].x != 0.0f || p.vertices[k].y != 0.0f || p.normals[k].x != 0.0f ||
                      p.normals[k].y != 0.0f;
        }
        return nonzero;
    }
    }
}

static void run_kind_mismatch(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    static const int shapes[] = {FIX_BALL_CIRCLE, FIX_BALL_BOX, FIX_MOVER_CAPSULE, FIX_GROUND_SEGMENT};
    static const i2d_shape_type kinds[] = {I2D_SHAPE_CIRCLE, I2D_SHAPE_POLYGON, I2D_SHAPE_CAPSULE, I2D_SHAPE_SEGMENT};
    static const char* const names[] = {"circle", "polygon", "capsule", "segment"};
    char what[128];
    for (int s = 0; s < 4; ++s) {
        i2d_shape_id shape = f->shape[shapes[s]];
        I2D_CHECK(i2d_shape_get_type(shape) == kinds[s]);
        for (int g = 0; g < 4; ++g) {
            bool nonzero = read_kind(shape, kinds[g]);
            snprintf(what, sizeof what, "i2d_shape_get_%s on a %s", names[g], names[s]);
            if (g == s) {
                check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
                I2D_CHECK(nonzero);
            } else {
                check_refused_at(__FILE__, __LINE__, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
                if (nonzero) {
                    ++i2d_check_failures;
                    fprintf(stderr, "%s:%d: %s: not the zero value\n", __FILE__, __LINE__, what);
                }
            }
        }
    }
    /* The right kinds give the geometry they were made with. */
    i2d_circle c = i2d_shape_get_circle(f->shape[FIX_BALL_CIRCLE]);
    I2D_CHECK(c.radius == 0.5f && c.center.x == 0.3f);
    i2d_polygon p = i2d_shape_get_polygon(f->shape[FIX_BALL_BOX]);
    I2D_CHECK(p.count == 4 && p.vertices[2].x == 0.4f && p.vertices[2].y == 0.4f);
    i2d_capsule cap = i2d_shape_get_capsule(f->shape[FIX_MOVER_CAPSULE]);
    I2D_CHECK(cap.center1.x == 0.5f && cap.center2.x == 1.5f && cap.radius == 0.2f);
    i2d_segment seg = i2d_shape_get_segment(f->shape[FIX_GROUND_SEGMENT]);
    I2D_CHECK(seg.point1.x == -19.0f && seg.point2.x == -17.0f && seg.point1.y == 3.0f);
    CHECK_UNCHANGED("the getters of the wrong kind", f, &before);
}

I2D_TEST(api_errors_shape_kind_mismatch) { run_on_fixture(run_kind_mismatch); }
