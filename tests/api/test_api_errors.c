/* SPDX-License-Identifier: MIT */
/* C API bad input: every refusal of capi.md answers its status with a message and leaves the world as it was. */
#include <impulse2d/impulse2d.h>

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

/* ---- Small helpers ---------------------------------------------------------------- */

static i2d_vec2 v2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static i2d_rot rot(float c, float s) {
    i2d_rot q;
    q.c = c;
    q.s = s;
    return q;
}

static i2d_aabb box(float min_x, float min_y, float max_x, float max_y) {
    i2d_aabb b;
    b.min = v2(min_x, min_y);
    b.max = v2(max_x, max_y);
    return b;
}

/* The three non-finite values every float input must refuse. */
static const float k_non_finite[] = {NAN, INFINITY, -INFINITY};
enum { NON_FINITE_COUNT = sizeof k_non_finite / sizeof k_non_finite[0] };

/* Checks the call just made answered `expected` through both its return value and
 * i2d_last_status(), with a non-empty message. Reads the status and copies the message
 * before calling anything else, since every i2d_ call may overwrite them. */
static void check_refused_at(int line, const char* what, i2d_status returned, i2d_status expected) {
    i2d_status last = i2d_last_status();
    const char* message = i2d_last_error_message();
    char copy[256] = "(null)";
    if (message != NULL) {
        strncpy(copy, message, sizeof copy - 1);
        copy[sizeof copy - 1] = '\0';
    }
    if (returned != expected || last != expected || message == NULL || message[0] == '\0') {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: returned %s, last status %s, message \"%s\"; expected %s with a message\n",
                __FILE__, line, what, i2d_status_string(returned), i2d_status_string(last), copy,
                i2d_status_string(expected));
    }
}
#define CHECK_REFUSED(what, returned, expected) check_refused_at(__LINE__, (what), (returned), (expected))

/* Checks the call just made succeeded: I2D_OK returned and recorded, empty message. */
static void check_accepted_at(int line, const char* what, i2d_status returned) {
    i2d_status last = i2d_last_status();
    const char* message = i2d_last_error_message();
    char copy[256] = "(null)";
    if (message != NULL) {
        strncpy(copy, message, sizeof copy - 1);
        copy[sizeof copy - 1] = '\0';
    }
    if (returned != I2D_OK || last != I2D_OK || message == NULL || message[0] != '\0') {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: returned %s, last status %s, message \"%s\"; expected I2D_OK, no message\n",
                __FILE__, line, what, i2d_status_string(returned), i2d_status_string(last), copy);
    }
}
#define CHECK_ACCEPTED(what, returned) check_accepted_at(__LINE__, (what), (returned))

/* ---- Snapshots: everything the API lets us observe about a world ------------------- */

enum { SNAP_MAX = 512 };

/* A flat record of observable values, compared bit for bit: a refused call must not
 * change a single bit. Each value remembers the object index and field for the log. */
typedef struct snapshot {
    int count;
    uint64_t value[SNAP_MAX];
    const char* field[SNAP_MAX];
    int object[SNAP_MAX];
} snapshot;

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

/* The world every table below works on: a static ground, a dynamic ball (circle and box)
 * resting slightly inside the ground and sliding, and a kinematic mover. Built
 * identically twice ("twins") so that hidden state can be compared by stepping both. */
enum { FIX_GROUND, FIX_BALL, FIX_MOVER, FIX_BODIES };
enum { FIX_GROUND_BOX, FIX_BALL_CIRCLE, FIX_BALL_BOX, FIX_MOVER_CIRCLE, FIX_SHAPES };

typedef struct fixture {
    i2d_world_id world;
    i2d_body_id body[FIX_BODIES];
    i2d_shape_id shape[FIX_SHAPES];
} fixture;

/* Addresses used as user data; the same in both twins. */
static int k_tags[FIX_BODIES + FIX_SHAPES];

static const float k_ball_y = 0.45f;

static bool fixture_create(fixture* f) {
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
    mover_def.linear_velocity = v2(0.5f, 0.0f);
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

static void fixture_destroy(fixture* f) {
    if (!I2D_IS_NULL(f->world)) {
        i2d_world_destroy(f->world);
    }
    memset(f, 0, sizeof *f);
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
    snap_vec2(s, i, "body.center_of_mass.x", "body.center_of_mass.y", i2d_body_get_world_center_of_mass(b));
    snap_put(s, i, "body.is_awake", i2d_body_is_awake(b));
    snap_pointer(s, i, "body.user_data", i2d_body_get_user_data(b));
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
    if (type == I2D_SHAPE_CIRCLE) {
        i2d_circle c = i2d_shape_get_circle(sh);
        snap_vec2(s, object, "shape.circle.center.x", "shape.circle.center.y", c.center);
        snap_float(s, object, "shape.circle.radius", c.radius);
    } else {
        i2d_polygon p = i2d_shape_get_polygon(sh);
        snap_put(s, object, "shape.polygon.count", (uint64_t)p.count);
        snap_vec2(s, object, "shape.half.x", "shape.half.y", p.vertices[2]);
    }
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
    snap_pointer(s, object, "shape.user_data", i2d_shape_get_user_data(sh));
}

static void snapshot_take(const fixture* f, snapshot* s) {
    s->count = 0;
    snap_vec2(s, -1, "world.gravity.x", "world.gravity.y", i2d_world_get_gravity(f->world));
    i2d_world_counters counters = i2d_world_get_counters(f->world);
    snap_put(s, -1, "world.body_count", (uint64_t)(int64_t)counters.body_count);
    snap_put(s, -1, "world.shape_count", (uint64_t)(int64_t)counters.shape_count);
    snap_put(s, -1, "world.contact_count", (uint64_t)(int64_t)counters.contact_count);
    snap_put(s, -1, "world.pair_count", (uint64_t)(int64_t)counters.pair_count);
    for (int i = 0; i < FIX_BODIES; ++i) {
        snap_body(s, f, i);
    }
    for (int j = 0; j < FIX_SHAPES; ++j) {
        snap_shape(s, f, j);
    }
}

/* Fails (once, naming the first difference) unless the two snapshots are bit-identical. */
static void check_same_snapshot_at(int line, const char* what, const snapshot* expected, const snapshot* actual) {
    if (expected->count != actual->count) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: after %s: snapshot has %d values, expected %d\n", __FILE__, line, what,
                actual->count, expected->count);
        return;
    }
    for (int k = 0; k < expected->count; ++k) {
        if (expected->value[k] != actual->value[k]) {
            ++i2d_check_failures;
            fprintf(stderr, "%s:%d: after %s: %s of object %d changed (bits 0x%llx, expected 0x%llx)\n",
                    __FILE__, line, what, expected->field[k], expected->object[k],
                    (unsigned long long)actual->value[k], (unsigned long long)expected->value[k]);
            return;
        }
    }
}
#define CHECK_SAME_SNAPSHOT(what, expected, actual) check_same_snapshot_at(__LINE__, (what), (expected), (actual))

/* Fails unless the fixture still matches `before`. */
static void check_unchanged_at(int line, const char* what, const fixture* f, const snapshot* before) {
    static snapshot now; /* static: large, and tests run one at a time */
    snapshot_take(f, &now);
    check_same_snapshot_at(line, what, before, &now);
}
#define CHECK_UNCHANGED(what, f, before) check_unchanged_at(__LINE__, (what), (f), (before))

/* Steps both twins and checks they still agree, which catches hidden state a refused
 * call may have changed (accumulated forces, materials read only by the solver...). */
static void check_twins_agree_after_steps(const fixture* a, const fixture* b) {
    static snapshot sa, sb;
    for (int i = 0; i < 10; ++i) {
        I2D_CHECK_STATUS(i2d_world_step(a->world, 1.0f / 60.0f, 4), I2D_OK);
        I2D_CHECK_STATUS(i2d_world_step(b->world, 1.0f / 60.0f, 4), I2D_OK);
    }
    snapshot_take(a, &sa);
    snapshot_take(b, &sb);
    CHECK_SAME_SNAPSHOT("stepping both twins 10 times", &sb, &sa);
}

/* Writes a float field of a def through its offset (the tables below name fields by offset). */
static void set_float_at(void* def, size_t offset, float value) {
    memcpy((char*)def + offset, &value, sizeof value);
}

typedef struct float_field {
    const char* name;
    size_t offset;
} float_field;

typedef struct float_field_value {
    const char* name;
    size_t offset;
    float value;
} float_field_value;

/* ---- World defs ------------------------------------------------------------------- */

static const float_field k_world_def_floats[] = {
    {"gravity.x", offsetof(i2d_world_def, gravity.x)},
    {"gravity.y", offsetof(i2d_world_def, gravity.y)},
    {"contact_slop", offsetof(i2d_world_def, contact_slop)},
    {"contact_correction_percent", offsetof(i2d_world_def, contact_correction_percent)},
    {"restitution_threshold", offsetof(i2d_world_def, restitution_threshold)},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed)},
};

/* Finite values outside the documented ranges. */
static const float_field_value k_world_def_out_of_range[] = {
    {"contact_slop", offsetof(i2d_world_def, contact_slop), -0.001f},
    {"contact_slop", offsetof(i2d_world_def, contact_slop), 1.5f},
    {"contact_correction_percent", offsetof(i2d_world_def, contact_correction_percent), 0.0f},
    {"contact_correction_percent", offsetof(i2d_world_def, contact_correction_percent), -0.5f},
    {"contact_correction_percent", offsetof(i2d_world_def, contact_correction_percent), 1.5f},
    {"restitution_threshold", offsetof(i2d_world_def, restitution_threshold), -1.0f},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed), 0.0f},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed), -1.0f},
};

/* The edges of the same ranges, which must be accepted. */
static const float_field_value k_world_def_in_range[] = {
    {"gravity.x", offsetof(i2d_world_def, gravity.x), -1e6f},
    {"gravity.y", offsetof(i2d_world_def, gravity.y), 1e6f},
    {"contact_slop", offsetof(i2d_world_def, contact_slop), 0.0f},
    {"contact_slop", offsetof(i2d_world_def, contact_slop), 1.0f},
    {"contact_correction_percent", offsetof(i2d_world_def, contact_correction_percent), 1.0f},
    {"contact_correction_percent", offsetof(i2d_world_def, contact_correction_percent), 0.001f},
    {"restitution_threshold", offsetof(i2d_world_def, restitution_threshold), 0.0f},
    {"maximum_linear_speed", offsetof(i2d_world_def, maximum_linear_speed), 0.001f},
};

static void check_world_def_refused_at(int line, const char* what, const i2d_world_def* def) {
    i2d_world_id world = i2d_world_create(def);
    check_refused_at(line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(world)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a world was created\n", __FILE__, line, what);
        i2d_world_destroy(world);
    }
}

static void check_world_def_accepted_at(int line, const char* what, const i2d_world_def* def) {
    i2d_world_id world = i2d_world_create(def);
    check_accepted_at(line, what, i2d_last_status());
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
    static const int32_t bad_iterations[] = {0, -1, 1001, INT32_MIN};
    for (size_t i = 0; i < sizeof bad_iterations / sizeof bad_iterations[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        def.velocity_iterations = bad_iterations[i];
        snprintf(what, sizeof what, "world def velocity_iterations = %d", (int)bad_iterations[i]);
        check_world_def_refused_at(__LINE__, what, &def);
    }

    /* The edges of every range are accepted, so the refusals above are about the values. */
    for (size_t i = 0; i < sizeof k_world_def_in_range / sizeof k_world_def_in_range[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        set_float_at(&def, k_world_def_in_range[i].offset, k_world_def_in_range[i].value);
        snprintf(what, sizeof what, "world def %s = %g", k_world_def_in_range[i].name, k_world_def_in_range[i].value);
        check_world_def_accepted_at(__LINE__, what, &def);
    }
    static const int32_t good_iterations[] = {1, 1000};
    for (size_t i = 0; i < sizeof good_iterations / sizeof good_iterations[0]; ++i) {
        i2d_world_def def = i2d_default_world_def();
        def.velocity_iterations = good_iterations[i];
        snprintf(what, sizeof what, "world def velocity_iterations = %d", (int)good_iterations[i]);
        check_world_def_accepted_at(__LINE__, what, &def);
    }
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

static const float_field_value k_body_def_out_of_range[] = {
    {"linear_damping", offsetof(i2d_body_def, linear_damping), -0.1f},
    {"angular_damping", offsetof(i2d_body_def, angular_damping), -1.0f},
    /* Rotation has not landed: any angular velocity but 0 is refused. */
    {"angular_velocity", offsetof(i2d_body_def, angular_velocity), 1.0f},
    {"angular_velocity", offsetof(i2d_body_def, angular_velocity), -1e-3f},
};

/* Rotations that are not identity within 1e-6. */
typedef struct named_rot {
    const char* name;
    float c, s;
} named_rot;

static const named_rot k_non_identity[] = {
    {"quarter turn (0, 1)", 0.0f, 1.0f},
    {"half turn (-1, 0)", -1.0f, 0.0f},
    {"1e-3 rad", 0.9999995f, 0.001f},
    {"1e-5 rad", 1.0f, 1e-5f},
    {"-1e-5 rad", 1.0f, -1e-5f},
    {"zero (0, 0)", 0.0f, 0.0f},
};

/* Identity within 1e-6: accepted. */
static const named_rot k_near_identity[] = {
    {"exact identity", 1.0f, 0.0f},
    {"s = -0", 1.0f, -0.0f},
    {"s = 1e-7", 1.0f, 1e-7f},
    {"c = 1 - 5e-7, s = 5e-7", 1.0f - 5e-7f, 5e-7f},
    {"s = -5e-7", 1.0f, -5e-7f},
};

/* A body def refused by i2d_body_create leaves the fixture exactly as it was. */
static void check_body_def_refused_at(int line, const char* what, const fixture* f, const i2d_body_def* def,
                                      const snapshot* before) {
    i2d_body_id body = i2d_body_create(f->world, def);
    check_refused_at(line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(body)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a body was created\n", __FILE__, line, what);
        i2d_body_destroy(body);
        return;
    }
    check_unchanged_at(line, what, f, before);
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
    for (size_t i = 0; i < sizeof k_non_identity / sizeof k_non_identity[0]; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        def.rotation = rot(k_non_identity[i].c, k_non_identity[i].s);
        snprintf(what, sizeof what, "body def rotation %s", k_non_identity[i].name);
        check_body_def_refused_at(__LINE__, what, f, &def, &before);
    }
    /* Enum values that name no body type. */
    static const int bad_types[] = {3, 7, -1};
    for (size_t i = 0; i < sizeof bad_types / sizeof bad_types[0]; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = (i2d_body_type)bad_types[i];
        snprintf(what, sizeof what, "body def type = %d", bad_types[i]);
        check_body_def_refused_at(__LINE__, what, f, &def, &before);
    }
}

I2D_TEST(api_errors_body_def_bad_values) {
    fixture f;
    if (fixture_create(&f)) {
        run_body_def_bad_values(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* Values at the edges of the body def ranges: each creates a body. */
static void run_body_def_accepted(i2d_world_id world) {
    char what[128];
    for (size_t i = 0; i < sizeof k_near_identity / sizeof k_near_identity[0]; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        def.rotation = rot(k_near_identity[i].c, k_near_identity[i].s);
        i2d_body_id body = i2d_body_create(world, &def);
        snprintf(what, sizeof what, "body def rotation %s", k_near_identity[i].name);
        check_accepted_at(__LINE__, what, i2d_last_status());
        I2D_CHECK(!I2D_IS_NULL(body));
    }
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.angular_velocity = -0.0f;
    def.gravity_scale = -2.0f; /* documented: may be negative */
    def.linear_damping = 0.0f;
    def.angular_damping = 5.0f;
    i2d_body_id body = i2d_body_create(world, &def);
    CHECK_ACCEPTED("body def angular_velocity -0, gravity_scale -2, angular_damping 5", i2d_last_status());
    I2D_CHECK(!I2D_IS_NULL(body));
    static const i2d_body_type types[] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    for (size_t i = 0; i < 3; ++i) {
        def = i2d_default_body_def();
        def.type = types[i];
        body = i2d_body_create(world, &def);
        CHECK_ACCEPTED("body def with each valid type", i2d_last_status());
        I2D_CHECK(i2d_body_get_type(body) == types[i]);
    }
    i2d_world_counters counters = i2d_world_get_counters(world);
    I2D_CHECK(counters.body_count == (int32_t)(sizeof k_near_identity / sizeof k_near_identity[0]) + 4);
}

I2D_TEST(api_errors_body_def_edges_accepted) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    run_body_def_accepted(world);
    i2d_world_destroy(world);
}

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

I2D_TEST(api_errors_body_def_not_from_default) {
    fixture f;
    if (fixture_create(&f)) {
        run_body_def_not_from_default(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* ---- Shape defs, circles, boxes ----------------------------------------------------- */

static const float_field k_shape_def_floats[] = {
    {"density", offsetof(i2d_shape_def, density)},
    {"friction", offsetof(i2d_shape_def, friction)},
    {"restitution", offsetof(i2d_shape_def, restitution)},
};

static const float_field_value k_shape_def_out_of_range[] = {
    {"density", offsetof(i2d_shape_def, density), -1.0f},
    {"density", offsetof(i2d_shape_def, density), -1e-30f},
    {"friction", offsetof(i2d_shape_def, friction), -0.5f},
    {"restitution", offsetof(i2d_shape_def, restitution), -0.5f},
};

static const float_field k_circle_floats[] = {
    {"center.x", offsetof(i2d_circle, center.x)},
    {"center.y", offsetof(i2d_circle, center.y)},
    {"radius", offsetof(i2d_circle, radius)},
};

/* Zero, negative and too large sizes (limit 100,000 m). */
static const float k_bad_sizes[] = {0.0f, -0.0f, -1.0f, -1e-30f, 100001.0f, 1e30f};
enum { BAD_SIZE_COUNT = sizeof k_bad_sizes / sizeof k_bad_sizes[0] };

/* Both shape creators with one def or geometry: each must be refused and change nothing. */
static void check_circle_refused_at(int line, const char* what, const fixture* f, const i2d_shape_def* def,
                                    const i2d_circle* circle, const snapshot* before) {
    i2d_shape_id shape = i2d_shape_create_circle(f->body[FIX_BALL], def, circle);
    check_refused_at(line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(shape)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a circle was created\n", __FILE__, line, what);
        i2d_shape_destroy(shape);
        return;
    }
    check_unchanged_at(line, what, f, before);
}

static void check_box_refused_at(int line, const char* what, const fixture* f, const i2d_shape_def* def, float hw,
                                 float hh, const snapshot* before) {
    i2d_shape_id shape = i2d_shape_create_box(f->body[FIX_BALL], def, hw, hh);
    check_refused_at(line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!I2D_IS_NULL(shape)) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: a box was created\n", __FILE__, line, what);
        i2d_shape_destroy(shape);
        return;
    }
    check_unchanged_at(line, what, f, before);
}

static void run_shape_def_bad_values(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_circle circle = {{0.0f, 0.5f}, 0.25f};
    char what[128];
    for (size_t i = 0; i < sizeof k_shape_def_floats / sizeof k_shape_def_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_shape_def def = i2d_default_shape_def();
            set_float_at(&def, k_shape_def_floats[i].offset, k_non_finite[k]);
            snprintf(what, sizeof what, "circle with shape def %s = %g", k_shape_def_floats[i].name, k_non_finite[k]);
            check_circle_refused_at(__LINE__, what, f, &def, &circle, &before);
            snprintf(what, sizeof what, "box with shape def %s = %g", k_shape_def_floats[i].name, k_non_finite[k]);
            check_box_refused_at(__LINE__, what, f, &def, 0.25f, 0.25f, &before);
        }
    }
    for (size_t i = 0; i < sizeof k_shape_def_out_of_range / sizeof k_shape_def_out_of_range[0]; ++i) {
        i2d_shape_def def = i2d_default_shape_def();
        set_float_at(&def, k_shape_def_out_of_range[i].offset, k_shape_def_out_of_range[i].value);
        snprintf(what, sizeof what, "circle with shape def %s = %g", k_shape_def_out_of_range[i].name,
                 k_shape_def_out_of_range[i].value);
        check_circle_refused_at(__LINE__, what, f, &def, &circle, &before);
        snprintf(what, sizeof what, "box with shape def %s = %g", k_shape_def_out_of_range[i].name,
                 k_shape_def_out_of_range[i].value);
        check_box_refused_at(__LINE__, what, f, &def, 0.25f, 0.25f, &before);
    }

    /* Defs that did not come from the default function, and missing pointers. */
    i2d_shape_def zeroed;
    memset(&zeroed, 0, sizeof zeroed);
    check_circle_refused_at(__LINE__, "circle with a zeroed shape def", f, &zeroed, &circle, &before);
    check_box_refused_at(__LINE__, "box with a zeroed shape def", f, &zeroed, 0.25f, 0.25f, &before);
    i2d_shape_def bad_cookie = i2d_default_shape_def();
    I2D_CHECK(bad_cookie.internal_cookie != 0);
    bad_cookie.internal_cookie ^= 1u;
    check_circle_refused_at(__LINE__, "circle with shape def cookie ^ 1", f, &bad_cookie, &circle, &before);
    check_box_refused_at(__LINE__, "box with shape def cookie ^ 1", f, &bad_cookie, 0.25f, 0.25f, &before);
    bad_cookie.internal_cookie = 0;
    check_circle_refused_at(__LINE__, "circle with shape def cookie 0", f, &bad_cookie, &circle, &before);
    check_box_refused_at(__LINE__, "box with shape def cookie 0", f, &bad_cookie, 0.25f, 0.25f, &before);

    i2d_shape_def def = i2d_default_shape_def();
    check_circle_refused_at(__LINE__, "circle with a NULL shape def", f, NULL, &circle, &before);
    check_box_refused_at(__LINE__, "box with a NULL shape def", f, NULL, 0.25f, 0.25f, &before);
    check_circle_refused_at(__LINE__, "circle with a NULL circle", f, &def, NULL, &before);
}

I2D_TEST(api_errors_shape_def_bad_values) {
    fixture f;
    if (fixture_create(&f)) {
        run_shape_def_bad_values(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

static void run_bad_geometry(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_shape_def def = i2d_default_shape_def();
    char what[128];
    for (size_t i = 0; i < sizeof k_circle_floats / sizeof k_circle_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_circle circle = {{0.0f, 0.5f}, 0.25f};
            set_float_at(&circle, k_circle_floats[i].offset, k_non_finite[k]);
            snprintf(what, sizeof what, "circle %s = %g", k_circle_floats[i].name, k_non_finite[k]);
            check_circle_refused_at(__LINE__, what, f, &def, &circle, &before);
        }
    }
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        snprintf(what, sizeof what, "box half_width = %g", k_non_finite[k]);
        check_box_refused_at(__LINE__, what, f, &def, k_non_finite[k], 0.25f, &before);
        snprintf(what, sizeof what, "box half_height = %g", k_non_finite[k]);
        check_box_refused_at(__LINE__, what, f, &def, 0.25f, k_non_finite[k], &before);
    }
    for (int k = 0; k < BAD_SIZE_COUNT; ++k) {
        i2d_circle circle = {{0.0f, 0.5f}, k_bad_sizes[k]};
        snprintf(what, sizeof what, "circle radius = %g", k_bad_sizes[k]);
        check_circle_refused_at(__LINE__, what, f, &def, &circle, &before);
        snprintf(what, sizeof what, "box half_width = %g", k_bad_sizes[k]);
        check_box_refused_at(__LINE__, what, f, &def, k_bad_sizes[k], 0.25f, &before);
        snprintf(what, sizeof what, "box half_height = %g", k_bad_sizes[k]);
        check_box_refused_at(__LINE__, what, f, &def, 0.25f, k_bad_sizes[k], &before);
    }
}

I2D_TEST(api_errors_shape_bad_geometry) {
    fixture f;
    if (fixture_create(&f)) {
        run_bad_geometry(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* The largest documented size and a density of 0 are accepted. */
I2D_TEST(api_errors_shape_edges_accepted) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_body_def body_def = i2d_default_body_def();
    i2d_body_id body = i2d_body_create(world, &body_def);
    i2d_shape_def def = i2d_default_shape_def();
    def.density = 0.0f;
    def.friction = 0.0f;
    def.restitution = 0.0f;
    i2d_circle circle = {{0.0f, 0.0f}, 100000.0f};
    i2d_shape_id a = i2d_shape_create_circle(body, &def, &circle);
    CHECK_ACCEPTED("circle radius 100000", i2d_last_status());
    i2d_shape_id b = i2d_shape_create_box(body, &def, 100000.0f, 100000.0f);
    CHECK_ACCEPTED("box half extents 100000", i2d_last_status());
    I2D_CHECK(!I2D_IS_NULL(a) && !I2D_IS_NULL(b));
    I2D_CHECK(i2d_world_get_counters(world).shape_count == 2);
    i2d_world_destroy(world);
}

/* ---- Setters with non-finite or out-of-range values -------------------------------- */

/* A call with one argument replaced by `value`; every other argument is valid. */
typedef i2d_status (*float_call)(const fixture* f, float value);

typedef struct float_call_row {
    const char* name;
    float_call call;
} float_call_row;

static i2d_vec2 ball_position(const fixture* f) { return i2d_body_get_position(f->body[FIX_BALL]); }

static i2d_status call_gravity_x(const fixture* f, float v) { return i2d_world_set_gravity(f->world, v2(v, -10.0f)); }
static i2d_status call_gravity_y(const fixture* f, float v) { return i2d_world_set_gravity(f->world, v2(0.0f, v)); }
static i2d_status call_transform_px(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], v2(v, 1.0f), rot(1.0f, 0.0f));
}
static i2d_status call_transform_py(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], v2(1.0f, v), rot(1.0f, 0.0f));
}
static i2d_status call_transform_qc(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], ball_position(f), rot(v, 0.0f));
}
static i2d_status call_transform_qs(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], ball_position(f), rot(1.0f, v));
}
static i2d_status call_velocity_x(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_BALL], v2(v, 0.0f));
}
static i2d_status call_velocity_y(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_BALL], v2(0.0f, v));
}
/* Documented: ignored for static bodies but still checked. */
static i2d_status call_static_velocity_x(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_GROUND], v2(v, 0.0f));
}
static i2d_status call_kinematic_velocity_y(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_MOVER], v2(0.0f, v));
}
static i2d_status call_angular_velocity(const fixture* f, float v) {
    return i2d_body_set_angular_velocity(f->body[FIX_BALL], v);
}
static i2d_status call_force_x(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(v, 0.0f), ball_position(f), true);
}
static i2d_status call_force_y(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(0.0f, v), ball_position(f), true);
}
static i2d_status call_force_point_x(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(v, 0.0f), true);
}
static i2d_status call_force_point_y(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(0.0f, v), false);
}
static i2d_status call_impulse_x(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(v, 0.0f), ball_position(f), true);
}
static i2d_status call_impulse_y(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(0.0f, v), ball_position(f), true);
}
static i2d_status call_impulse_point_x(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(v, 0.0f), true);
}
static i2d_status call_impulse_point_y(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(0.0f, v), false);
}
static i2d_status call_friction(const fixture* f, float v) {
    return i2d_shape_set_friction(f->shape[FIX_BALL_CIRCLE], v);
}
static i2d_status call_restitution(const fixture* f, float v) {
    return i2d_shape_set_restitution(f->shape[FIX_BALL_BOX], v);
}
static i2d_status call_step_time(const fixture* f, float v) { return i2d_world_step(f->world, v, 4); }

static const float_call_row k_float_calls[] = {
    {"i2d_world_set_gravity gravity.x", call_gravity_x},
    {"i2d_world_set_gravity gravity.y", call_gravity_y},
    {"i2d_body_set_transform position.x", call_transform_px},
    {"i2d_body_set_transform position.y", call_transform_py},
    {"i2d_body_set_transform rotation.c", call_transform_qc},
    {"i2d_body_set_transform rotation.s", call_transform_qs},
    {"i2d_body_set_linear_velocity v.x", call_velocity_x},
    {"i2d_body_set_linear_velocity v.y", call_velocity_y},
    {"i2d_body_set_linear_velocity v.x (static body)", call_static_velocity_x},
    {"i2d_body_set_linear_velocity v.y (kinematic body)", call_kinematic_velocity_y},
    {"i2d_body_set_angular_velocity", call_angular_velocity},
    {"i2d_body_apply_force force.x", call_force_x},
    {"i2d_body_apply_force force.y", call_force_y},
    {"i2d_body_apply_force point.x", call_force_point_x},
    {"i2d_body_apply_force point.y", call_force_point_y},
    {"i2d_body_apply_linear_impulse impulse.x", call_impulse_x},
    {"i2d_body_apply_linear_impulse impulse.y", call_impulse_y},
    {"i2d_body_apply_linear_impulse point.x", call_impulse_point_x},
    {"i2d_body_apply_linear_impulse point.y", call_impulse_point_y},
    {"i2d_shape_set_friction", call_friction},
    {"i2d_shape_set_restitution", call_restitution},
    {"i2d_world_step time_step", call_step_time},
};

typedef struct float_call_value {
    const char* name;
    float_call call;
    float value;
} float_call_value;

/* Finite values outside the documented ranges. */
static const float_call_value k_out_of_range_calls[] = {
    {"i2d_body_set_angular_velocity", call_angular_velocity, 1.0f},
    {"i2d_body_set_angular_velocity", call_angular_velocity, -1e-3f},
    {"i2d_body_set_angular_velocity", call_angular_velocity, 100.0f},
    {"i2d_body_set_transform rotation.s (1e-5 rad)", call_transform_qs, 1e-5f},
    {"i2d_body_set_transform rotation.s (quarter turn, c = 1)", call_transform_qs, 1.0f},
    {"i2d_body_set_transform rotation.c (half turn)", call_transform_qc, -1.0f},
    {"i2d_body_set_transform rotation.c (zero rotation)", call_transform_qc, 0.0f},
    {"i2d_shape_set_friction", call_friction, -0.5f},
    {"i2d_shape_set_friction", call_friction, -1e-30f},
    {"i2d_shape_set_restitution", call_restitution, -0.5f},
    {"i2d_world_step time_step", call_step_time, -1.0f / 60.0f},
    {"i2d_world_step time_step", call_step_time, -1e-30f},
};

static void run_setters_refused(const fixture* a, const fixture* b) {
    static snapshot before, twin;
    snapshot_take(a, &before);
    snapshot_take(b, &twin);
    CHECK_SAME_SNAPSHOT("building the twins", &twin, &before);
    char what[160];
    for (size_t i = 0; i < sizeof k_float_calls / sizeof k_float_calls[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_status status = k_float_calls[i].call(a, k_non_finite[k]);
            snprintf(what, sizeof what, "%s = %g", k_float_calls[i].name, k_non_finite[k]);
            CHECK_REFUSED(what, status, I2D_ERR_INVALID_ARGUMENT);
            CHECK_UNCHANGED(what, a, &before);
        }
    }
    for (size_t i = 0; i < sizeof k_out_of_range_calls / sizeof k_out_of_range_calls[0]; ++i) {
        i2d_status status = k_out_of_range_calls[i].call(a, k_out_of_range_calls[i].value);
        snprintf(what, sizeof what, "%s = %g", k_out_of_range_calls[i].name, k_out_of_range_calls[i].value);
        CHECK_REFUSED(what, status, I2D_ERR_INVALID_ARGUMENT);
        CHECK_UNCHANGED(what, a, &before);
    }
    /* Rotations with both components off identity. */
    for (size_t i = 0; i < sizeof k_non_identity / sizeof k_non_identity[0]; ++i) {
        i2d_status status = i2d_body_set_transform(a->body[FIX_BALL], ball_position(a),
                                                   rot(k_non_identity[i].c, k_non_identity[i].s));
        snprintf(what, sizeof what, "i2d_body_set_transform rotation %s", k_non_identity[i].name);
        CHECK_REFUSED(what, status, I2D_ERR_INVALID_ARGUMENT);
        CHECK_UNCHANGED(what, a, &before);
    }
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_setters_bad_values) {
    fixture a, b;
    bool built_a = fixture_create(&a);
    bool built_b = fixture_create(&b);
    if (built_a && built_b) {
        run_setters_refused(&a, &b);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&a);
    fixture_destroy(&b);
}

/* Zero angular velocity (also -0) and identity rotations within 1e-6 are accepted. */
static void run_identity_accepted(const fixture* f) {
    i2d_body_id ball = f->body[FIX_BALL];
    CHECK_ACCEPTED("i2d_body_set_angular_velocity(0)", i2d_body_set_angular_velocity(ball, 0.0f));
    CHECK_ACCEPTED("i2d_body_set_angular_velocity(-0)", i2d_body_set_angular_velocity(ball, -0.0f));
    I2D_CHECK(i2d_body_get_angular_velocity(ball) == 0.0f);
    char what[128];
    for (size_t i = 0; i < sizeof k_near_identity / sizeof k_near_identity[0]; ++i) {
        float x = 2.0f + (float)i;
        i2d_status status =
            i2d_body_set_transform(ball, v2(x, 3.0f), rot(k_near_identity[i].c, k_near_identity[i].s));
        snprintf(what, sizeof what, "i2d_body_set_transform rotation %s", k_near_identity[i].name);
        CHECK_ACCEPTED(what, status);
        i2d_vec2 p = i2d_body_get_position(ball);
        I2D_CHECK(p.x == x && p.y == 3.0f);
    }
}

I2D_TEST(api_errors_identity_accepted) {
    fixture f;
    if (fixture_create(&f)) {
        run_identity_accepted(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* ---- Steps -------------------------------------------------------------------------- */

static void run_step_bad_values(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    char what[128];
    static const int32_t bad_substeps[] = {0, -1, 1001, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof bad_substeps / sizeof bad_substeps[0]; ++i) {
        snprintf(what, sizeof what, "i2d_world_step substep_count = %d", (int)bad_substeps[i]);
        CHECK_REFUSED(what, i2d_world_step(a->world, 1.0f / 60.0f, bad_substeps[i]), I2D_ERR_INVALID_ARGUMENT);
        CHECK_UNCHANGED(what, a, &before);
    }
    /* Both arguments bad at once. */
    CHECK_REFUSED("i2d_world_step(NaN, 0)", i2d_world_step(a->world, NAN, 0), I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("i2d_world_step(NaN, 0)", a, &before);

    /* A zero time step is accepted and does nothing. */
    CHECK_ACCEPTED("i2d_world_step(0, 4)", i2d_world_step(a->world, 0.0f, 4));
    CHECK_UNCHANGED("i2d_world_step(0, 4)", a, &before);
    check_twins_agree_after_steps(a, b);

    /* The edges of the substep range are accepted. */
    CHECK_ACCEPTED("i2d_world_step(1/60, 1)", i2d_world_step(a->world, 1.0f / 60.0f, 1));
    CHECK_ACCEPTED("i2d_world_step(1/60, 1000)", i2d_world_step(a->world, 1.0f / 60.0f, 1000));
}

I2D_TEST(api_errors_step_bad_values) {
    fixture a, b;
    bool built_a = fixture_create(&a);
    bool built_b = fixture_create(&b);
    if (built_a && built_b) {
        run_step_bad_values(&a, &b);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&a);
    fixture_destroy(&b);
}

/* ---- Queries ------------------------------------------------------------------------ */

static bool count_shape(i2d_shape_id shape, void* context) {
    (void)shape;
    ++*(int*)context;
    return true;
}

/* Every AABB that must be refused: NaN or infinite corners, min > max. */
static void bad_aabbs(i2d_aabb* out, int* count) {
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

static void run_query_bad_arguments(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_query_filter filter = i2d_default_query_filter();
    const i2d_aabb everything = box(-100.0f, -100.0f, 100.0f, 100.0f);
    i2d_shape_id out[8];
    char what[160];
    int calls = 0;

    CHECK_REFUSED("i2d_world_overlap_aabb with NULL fn",
                  i2d_world_overlap_aabb(f->world, everything, filter, NULL, &calls), I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_world_overlap_point with NULL fn",
                  i2d_world_overlap_point(f->world, v2(0.0f, 0.0f), filter, NULL, &calls), I2D_ERR_INVALID_ARGUMENT);

    i2d_aabb bad[32];
    int bad_count = 0;
    bad_aabbs(bad, &bad_count);
    for (int i = 0; i < bad_count; ++i) {
        snprintf(what, sizeof what, "aabb (%g, %g)-(%g, %g)", bad[i].min.x, bad[i].min.y, bad[i].max.x, bad[i].max.y);
        calls = 0;
        CHECK_REFUSED(what, i2d_world_overlap_aabb(f->world, bad[i], filter, count_shape, &calls),
                      I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(calls == 0);
        out[0].bits = 12345;
        int32_t n = i2d_world_overlap_aabb_ids(f->world, bad[i], filter, out, 8);
        CHECK_REFUSED(what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(n == -1);
        I2D_CHECK(out[0].bits == 12345); /* nothing written */
    }
    for (int axis = 0; axis < 2; ++axis) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_vec2 point = axis == 0 ? v2(k_non_finite[k], 0.0f) : v2(0.0f, k_non_finite[k]);
            snprintf(what, sizeof what, "i2d_world_overlap_point (%g, %g)", point.x, point.y);
            calls = 0;
            CHECK_REFUSED(what, i2d_world_overlap_point(f->world, point, filter, count_shape, &calls),
                          I2D_ERR_INVALID_ARGUMENT);
            I2D_CHECK(calls == 0);
        }
    }

    /* Output buffers for the FFI variant: negative capacity, NULL out with capacity. */
    int32_t n = i2d_world_overlap_aabb_ids(f->world, everything, filter, out, -1);
    CHECK_REFUSED("i2d_world_overlap_aabb_ids capacity -1", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(n == -1);
    n = i2d_world_overlap_aabb_ids(f->world, everything, filter, NULL, 4);
    CHECK_REFUSED("i2d_world_overlap_aabb_ids NULL out, capacity 4", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(n == -1);
    /* NULL with capacity 0 is how a caller sizes its buffer: it returns the total. */
    n = i2d_world_overlap_aabb_ids(f->world, everything, filter, NULL, 0);
    CHECK_ACCEPTED("i2d_world_overlap_aabb_ids NULL out, capacity 0", i2d_last_status());
    I2D_CHECK(n == FIX_SHAPES);

    /* Rays with a bad origin or translation hit nothing and say why. */
    for (int field = 0; field < 4; ++field) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_vec2 origin = v2(0.0f, 5.0f);
            i2d_vec2 translation = v2(0.0f, -10.0f);
            float* slot[4] = {&origin.x, &origin.y, &translation.x, &translation.y};
            *slot[field] = k_non_finite[k];
            i2d_ray_result r = i2d_world_cast_ray_closest(f->world, origin, translation, filter);
            snprintf(what, sizeof what, "i2d_world_cast_ray_closest origin (%g, %g) translation (%g, %g)", origin.x,
                     origin.y, translation.x, translation.y);
            CHECK_REFUSED(what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
            I2D_CHECK(!r.hit);
            I2D_CHECK(I2D_IS_NULL(r.shape));
        }
    }
    CHECK_UNCHANGED("the refused queries", f, &before);

    /* The same ray with valid input does hit the ground, so the refusals are about the input. */
    i2d_ray_result r = i2d_world_cast_ray_closest(f->world, v2(10.0f, 5.0f), v2(0.0f, -10.0f), filter);
    CHECK_ACCEPTED("i2d_world_cast_ray_closest valid", i2d_last_status());
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, f->shape[FIX_GROUND_BOX]));
}

I2D_TEST(api_errors_query_bad_arguments) {
    fixture f;
    if (fixture_create(&f)) {
        run_query_bad_arguments(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* ---- Overflow of accumulated forces and velocities -------------------------------- */

/* Forces accumulate until the step. The accumulated force is not observable directly,
 * so the test cancels it: after F accepted and F refused, -F must bring the total back to
 * exactly 0, which a step then shows as a body that does not move. Had the refused call
 * left anything behind (inf, a clamped FLT_MAX), the total would not cancel. */
static void run_force_overflow(i2d_world_id world) {
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_body_id body = i2d_body_create(world, &body_def); /* no shapes: 1 kg */
    I2D_REQUIRE(!I2D_IS_NULL(body));
    I2D_CHECK(i2d_body_get_mass(body) == 1.0f);

    const i2d_vec2 origin = v2(0.0f, 0.0f);
    CHECK_ACCEPTED("first force 3e38", i2d_body_apply_force(body, v2(3e38f, 0.0f), origin, true));
    /* 3e38 + 3e38 overflows to inf: refused, and the first force is kept as it was. */
    CHECK_REFUSED("second force 3e38", i2d_body_apply_force(body, v2(3e38f, 0.0f), origin, true),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_ACCEPTED("first force -3e38 on y", i2d_body_apply_force(body, v2(0.0f, -3e38f), origin, true));
    CHECK_REFUSED("second force -3e38 on y", i2d_body_apply_force(body, v2(0.0f, -3e38f), origin, true),
                  I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_body_get_linear_velocity(body).x == 0.0f); /* forces act at the step */

    CHECK_ACCEPTED("cancelling force", i2d_body_apply_force(body, v2(-3e38f, 3e38f), origin, true));
    I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 1), I2D_OK);
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    i2d_vec2 p = i2d_body_get_position(body);
    I2D_CHECK(v.x == 0.0f && v.y == 0.0f);
    I2D_CHECK(p.x == 0.0f && p.y == 0.0f);

    /* Forces do act on this body: 120 N on 1 kg for 1/60 s adds 2 m/s. */
    CHECK_ACCEPTED("force 120 N", i2d_body_apply_force(body, v2(120.0f, 0.0f), origin, true));
    I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 1), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(body).x, 2.0, 1e-5);
}

I2D_TEST(api_errors_force_overflow) {
    i2d_world_def world_def = i2d_default_world_def();
    world_def.gravity = v2(0.0f, 0.0f);
    i2d_world_id world = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    run_force_overflow(world);
    i2d_world_destroy(world);
}

/* An impulse changes the velocity at once: a second one that would make it inf is refused. */
static void run_impulse_overflow(i2d_world_id world) {
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_body_id body = i2d_body_create(world, &body_def); /* no shapes: 1 kg */
    I2D_REQUIRE(!I2D_IS_NULL(body));
    I2D_CHECK(i2d_body_get_mass(body) == 1.0f);
    const i2d_vec2 origin = v2(0.0f, 0.0f);
    CHECK_ACCEPTED("first impulse 3e38", i2d_body_apply_linear_impulse(body, v2(3e38f, 0.0f), origin, true));
    I2D_CHECK(i2d_body_get_linear_velocity(body).x == 3e38f);
    CHECK_REFUSED("second impulse 3e38", i2d_body_apply_linear_impulse(body, v2(3e38f, 0.0f), origin, true),
                  I2D_ERR_INVALID_ARGUMENT);
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == 3e38f && v.y == 0.0f);

    /* The same on y, starting from a velocity set directly. */
    CHECK_ACCEPTED("velocity -3e38 on y", i2d_body_set_linear_velocity(body, v2(0.0f, -3e38f)));
    CHECK_REFUSED("impulse -3e38 on y", i2d_body_apply_linear_impulse(body, v2(0.0f, -3e38f), origin, false),
                  I2D_ERR_INVALID_ARGUMENT);
    v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == 0.0f && v.y == -3e38f);
}

I2D_TEST(api_errors_impulse_overflow) {
    i2d_world_def world_def = i2d_default_world_def();
    world_def.gravity = v2(0.0f, 0.0f);
    i2d_world_id world = i2d_world_create(&world_def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    run_impulse_overflow(world);
    i2d_world_destroy(world);
}

/* ---- Calls from inside query callbacks --------------------------------------------- */

typedef struct lock_probe {
    const fixture* f;
    const snapshot* before;
    bool probed;
    int shapes_seen;
} lock_probe;

/* The call must answer WORLD_LOCKED and leave the fixture as it was. */
#define CHECK_LOCKED(f, before, call)                                    \
    do {                                                                 \
        i2d_status locked_status_ = (call);                              \
        CHECK_REFUSED(#call, locked_status_, I2D_ERR_WORLD_LOCKED);      \
        CHECK_UNCHANGED(#call, (f), (before));                           \
    } while (0)

/* The creation must return the null id with WORLD_LOCKED and leave the fixture as it was. */
#define CHECK_LOCKED_CREATE(f, before, id_expr)                                        \
    do {                                                                               \
        bool created_ = !I2D_IS_NULL(id_expr);                                         \
        CHECK_REFUSED(#id_expr, i2d_last_status(), I2D_ERR_WORLD_LOCKED);              \
        I2D_CHECK(!created_);                                                          \
        CHECK_UNCHANGED(#id_expr, (f), (before));                                      \
    } while (0)

static void try_changes_while_locked(const fixture* f, const snapshot* before) {
    i2d_body_id ball = f->body[FIX_BALL];
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_circle circle = {{0.0f, 0.0f}, 0.25f};

    CHECK_LOCKED(f, before, i2d_world_step(f->world, 1.0f / 60.0f, 4));
    CHECK_LOCKED(f, before, i2d_world_destroy(f->world));
    CHECK_LOCKED_CREATE(f, before, i2d_body_create(f->world, &body_def));
    CHECK_LOCKED(f, before, i2d_body_destroy(f->body[FIX_MOVER]));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_circle(ball, &shape_def, &circle));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_box(ball, &shape_def, 0.5f, 0.5f));
    CHECK_LOCKED(f, before, i2d_shape_destroy(f->shape[FIX_BALL_BOX]));
    CHECK_LOCKED(f, before, i2d_body_set_transform(ball, v2(3.0f, 3.0f), rot(1.0f, 0.0f)));
    CHECK_LOCKED(f, before, i2d_body_set_linear_velocity(ball, v2(0.0f, 7.0f)));
    CHECK_LOCKED(f, before, i2d_body_set_angular_velocity(ball, 0.0f));
    CHECK_LOCKED(f, before, i2d_body_apply_force(ball, v2(0.0f, 100.0f), v2(0.0f, 0.0f), true));
    CHECK_LOCKED(f, before, i2d_body_apply_linear_impulse(ball, v2(0.0f, 100.0f), v2(0.0f, 0.0f), true));
    CHECK_LOCKED(f, before, i2d_world_set_gravity(f->world, v2(0.0f, 10.0f)));
    CHECK_LOCKED(f, before, i2d_shape_set_friction(f->shape[FIX_BALL_CIRCLE], 0.1f));
    CHECK_LOCKED(f, before, i2d_shape_set_restitution(f->shape[FIX_BALL_CIRCLE], 0.9f));
    CHECK_LOCKED(f, before, i2d_shape_set_filter(f->shape[FIX_BALL_CIRCLE], i2d_default_filter()));
}

/* Getters, user data and nested queries still work inside a callback. */
static void try_reads_while_locked(const fixture* f, const snapshot* before, i2d_shape_id reported) {
    I2D_CHECK(i2d_shape_is_valid(reported));
    i2d_vec2 p = i2d_body_get_position(f->body[FIX_BALL]);
    CHECK_ACCEPTED("i2d_body_get_position inside a callback", i2d_last_status());
    I2D_CHECK(p.x == 0.0f && p.y == k_ball_y);
    i2d_world_counters counters = i2d_world_get_counters(f->world);
    CHECK_ACCEPTED("i2d_world_get_counters inside a callback", i2d_last_status());
    I2D_CHECK(counters.shape_count == FIX_SHAPES);

    static int marker;
    i2d_body_id ball = f->body[FIX_BALL];
    void* old_body_data = i2d_body_get_user_data(ball);
    CHECK_ACCEPTED("i2d_body_set_user_data inside a callback", i2d_body_set_user_data(ball, &marker));
    I2D_CHECK(i2d_body_get_user_data(ball) == &marker);
    CHECK_ACCEPTED("i2d_body_set_user_data back", i2d_body_set_user_data(ball, old_body_data));
    i2d_shape_id circle = f->shape[FIX_BALL_CIRCLE];
    void* old_shape_data = i2d_shape_get_user_data(circle);
    CHECK_ACCEPTED("i2d_shape_set_user_data inside a callback", i2d_shape_set_user_data(circle, &marker));
    I2D_CHECK(i2d_shape_get_user_data(circle) == &marker);
    CHECK_ACCEPTED("i2d_shape_set_user_data back", i2d_shape_set_user_data(circle, old_shape_data));

    const i2d_query_filter filter = i2d_default_query_filter();
    int nested = 0;
    CHECK_ACCEPTED("nested i2d_world_overlap_aabb",
                   i2d_world_overlap_aabb(f->world, box(-100.0f, -100.0f, 100.0f, 100.0f), filter, count_shape,
                                          &nested));
    I2D_CHECK(nested == FIX_SHAPES);
    nested = 0;
    CHECK_ACCEPTED("nested i2d_world_overlap_point",
                   i2d_world_overlap_point(f->world, v2(10.0f, -1.0f), filter, count_shape, &nested));
    I2D_CHECK(nested == 1); /* only the ground contains (10, -1) */
    i2d_shape_id ids[8];
    int32_t n = i2d_world_overlap_aabb_ids(f->world, box(-100.0f, -100.0f, 100.0f, 100.0f), filter, ids, 8);
    CHECK_ACCEPTED("nested i2d_world_overlap_aabb_ids", i2d_last_status());
    I2D_CHECK(n == FIX_SHAPES);
    i2d_ray_result r = i2d_world_cast_ray_closest(f->world, v2(10.0f, 5.0f), v2(0.0f, -10.0f), filter);
    CHECK_ACCEPTED("nested i2d_world_cast_ray_closest", i2d_last_status());
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, f->shape[FIX_GROUND_BOX]));

    /* The end of a nested query must not unlock the outer one. */
    CHECK_LOCKED(f, before, i2d_body_set_linear_velocity(ball, v2(0.0f, 7.0f)));
    CHECK_UNCHANGED("the reads inside a callback", f, before);
}

static bool probe_locked_world(i2d_shape_id shape, void* context) {
    lock_probe* probe = (lock_probe*)context;
    ++probe->shapes_seen;
    if (!probe->probed) {
        probe->probed = true;
        try_changes_while_locked(probe->f, probe->before);
        try_reads_while_locked(probe->f, probe->before, shape);
    }
    return true;
}

static void run_locked_in_callbacks(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    const i2d_query_filter filter = i2d_default_query_filter();

    lock_probe probe = {a, &before, false, 0};
    CHECK_ACCEPTED("i2d_world_overlap_aabb around a probing callback",
                   i2d_world_overlap_aabb(a->world, box(-100.0f, -100.0f, 100.0f, 100.0f), filter,
                                          probe_locked_world, &probe));
    I2D_CHECK(probe.probed);
    I2D_CHECK(probe.shapes_seen == FIX_SHAPES); /* the outer query went on to the end */

    /* The same from a point query's callback (a point inside the ball's circle only). */
    lock_probe point_probe = {a, &before, false, 0};
    CHECK_ACCEPTED("i2d_world_overlap_point around a probing callback",
                   i2d_world_overlap_point(a->world, v2(0.6f, k_ball_y), filter, probe_locked_world, &point_probe));
    I2D_CHECK(point_probe.probed);
    I2D_CHECK(point_probe.shapes_seen == 1);

    CHECK_UNCHANGED("the queries with probing callbacks", a, &before);
    check_twins_agree_after_steps(a, b);

    /* Once the queries have returned, the world takes changes again. */
    CHECK_ACCEPTED("i2d_body_set_linear_velocity after the query",
                   i2d_body_set_linear_velocity(a->body[FIX_BALL], v2(0.0f, 7.0f)));
    I2D_CHECK(i2d_body_get_linear_velocity(a->body[FIX_BALL]).y == 7.0f);
    CHECK_ACCEPTED("i2d_world_step after the query", i2d_world_step(a->world, 1.0f / 60.0f, 4));
}

I2D_TEST(api_errors_locked_in_query_callbacks) {
    fixture a, b;
    bool built_a = fixture_create(&a);
    bool built_b = fixture_create(&b);
    if (built_a && built_b) {
        run_locked_in_callbacks(&a, &b);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&a);
    fixture_destroy(&b);
}

/* ---- Order of checks: handle, then lock, then arguments ---------------------------- */

typedef struct order_probe {
    const fixture* f;
    const snapshot* before;
    i2d_body_id stale;
    bool probed;
} order_probe;

static bool probe_check_order(i2d_shape_id shape, void* context) {
    (void)shape;
    order_probe* probe = (order_probe*)context;
    if (probe->probed) {
        return false;
    }
    probe->probed = true;
    const fixture* f = probe->f;
    /* Locked wins over bad arguments... */
    CHECK_LOCKED(f, probe->before, i2d_body_set_linear_velocity(f->body[FIX_BALL], v2(NAN, 0.0f)));
    CHECK_LOCKED(f, probe->before, i2d_world_step(f->world, NAN, 0));
    CHECK_LOCKED(f, probe->before, i2d_world_set_gravity(f->world, v2(INFINITY, 0.0f)));
    CHECK_LOCKED(f, probe->before, i2d_shape_set_friction(f->shape[FIX_BALL_BOX], -1.0f));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_body_create(f->world, NULL));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_circle(f->body[FIX_BALL], NULL, NULL));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_box(f->body[FIX_BALL], NULL, -1.0f, NAN));
    /* ...and a bad handle wins over the lock. */
    CHECK_REFUSED("stale body inside a callback", i2d_body_set_linear_velocity(probe->stale, v2(NAN, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null body inside a callback", i2d_body_apply_force(I2D_NULL_BODY_ID, v2(1, 0), v2(0, 0), true),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_UNCHANGED("the order probe", f, probe->before);
    return false;
}

static void run_check_order(const fixture* f) {
    /* A stale body id: created and destroyed before the snapshot. */
    i2d_body_def body_def = i2d_default_body_def();
    i2d_body_id stale = i2d_body_create(f->world, &body_def);
    I2D_CHECK_STATUS(i2d_body_destroy(stale), I2D_OK);

    static snapshot before;
    snapshot_take(f, &before);

    /* Bad handle wins over bad arguments. */
    CHECK_REFUSED("null body, NaN velocity", i2d_body_set_linear_velocity(I2D_NULL_BODY_ID, v2(NAN, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("stale body, NaN velocity", i2d_body_set_linear_velocity(stale, v2(NAN, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null world, NaN step", i2d_world_step(I2D_NULL_WORLD_ID, NAN, 0), I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null world, NULL fn",
                  i2d_world_overlap_aabb(I2D_NULL_WORLD_ID, box(1.0f, 1.0f, 0.0f, 0.0f), i2d_default_query_filter(),
                                         NULL, NULL),
                  I2D_ERR_INVALID_HANDLE);
    i2d_body_id body = i2d_body_create(I2D_NULL_WORLD_ID, NULL);
    CHECK_REFUSED("i2d_body_create(null world, NULL)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(body));
    i2d_shape_id shape = i2d_shape_create_circle(stale, NULL, NULL);
    CHECK_REFUSED("i2d_shape_create_circle(stale body, NULL, NULL)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    shape = i2d_shape_create_box(I2D_NULL_BODY_ID, NULL, NAN, -1.0f);
    CHECK_REFUSED("i2d_shape_create_box(null body, NULL, NaN, -1)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    CHECK_UNCHANGED("calls with bad handles and bad arguments", f, &before);

    order_probe probe = {f, &before, stale, false};
    CHECK_ACCEPTED("query around the order probe",
                   i2d_world_overlap_aabb(f->world, box(-100.0f, -100.0f, 100.0f, 100.0f), i2d_default_query_filter(),
                                          probe_check_order, &probe));
    I2D_CHECK(probe.probed);
}

I2D_TEST(api_errors_check_order) {
    fixture f;
    if (fixture_create(&f)) {
        run_check_order(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* ---- Getters of the wrong shape kind ------------------------------------------------ */

static void run_kind_mismatch(const fixture* f) {
    i2d_circle c = i2d_shape_get_circle(f->shape[FIX_BALL_BOX]);
    CHECK_REFUSED("i2d_shape_get_circle on a box", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(c.center.x == 0.0f && c.center.y == 0.0f && c.radius == 0.0f);
    i2d_polygon p = i2d_shape_get_polygon(f->shape[FIX_BALL_CIRCLE]);
    CHECK_REFUSED("i2d_shape_get_polygon on a circle", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(p.count == 0 && p.vertices[2].x == 0.0f && p.vertices[2].y == 0.0f);
    /* The right kind still works. */
    c = i2d_shape_get_circle(f->shape[FIX_BALL_CIRCLE]);
    CHECK_ACCEPTED("i2d_shape_get_circle on a circle", i2d_last_status());
    I2D_CHECK(c.radius == 0.5f && c.center.x == 0.3f);
    p = i2d_shape_get_polygon(f->shape[FIX_BALL_BOX]);
    CHECK_ACCEPTED("i2d_shape_get_polygon on a box", i2d_last_status());
    I2D_CHECK(p.count == 4 && p.vertices[2].x == 0.4f && p.vertices[2].y == 0.4f);
}

I2D_TEST(api_errors_shape_kind_mismatch) {
    fixture f;
    if (fixture_create(&f)) {
        run_kind_mismatch(&f);
    } else {
        I2D_CHECK(!"fixture_create");
    }
    fixture_destroy(&f);
}

/* ---- Pure collision functions ------------------------------------------------------- */

static void check_no_manifold_at(int line, const char* what, i2d_manifold m) {
    check_refused_at(line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (m.point_count != 0) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: point_count %d, expected 0\n", __FILE__, line, what, (int)m.point_count);
    }
}

I2D_TEST(api_errors_collide_bad_input) {
    const i2d_circle good = {{0.0f, 0.0f}, 1.0f};
    const i2d_aabb good_box = box(-1.0f, -1.0f, 1.0f, 1.0f);
    char what[128];
    for (size_t i = 0; i < sizeof k_circle_floats / sizeof k_circle_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_circle bad = good;
            set_float_at(&bad, k_circle_floats[i].offset, k_non_finite[k]);
            snprintf(what, sizeof what, "i2d_collide_circles with %s = %g", k_circle_floats[i].name, k_non_finite[k]);
            check_no_manifold_at(__LINE__, what, i2d_collide_circles(good, bad));
            check_no_manifold_at(__LINE__, what, i2d_collide_circles(bad, good));
            snprintf(what, sizeof what, "i2d_collide_aabb_circle with %s = %g", k_circle_floats[i].name,
                     k_non_finite[k]);
            check_no_manifold_at(__LINE__, what, i2d_collide_aabb_circle(good_box, bad));
        }
    }
    i2d_circle negative = good;
    negative.radius = -0.5f;
    check_no_manifold_at(__LINE__, "i2d_collide_circles negative radius", i2d_collide_circles(good, negative));
    check_no_manifold_at(__LINE__, "i2d_collide_aabb_circle negative radius",
                         i2d_collide_aabb_circle(good_box, negative));

    i2d_aabb bad[32];
    int bad_count = 0;
    bad_aabbs(bad, &bad_count);
    for (int i = 0; i < bad_count; ++i) {
        snprintf(what, sizeof what, "aabb (%g, %g)-(%g, %g)", bad[i].min.x, bad[i].min.y, bad[i].max.x, bad[i].max.y);
        check_no_manifold_at(__LINE__, what, i2d_collide_aabbs(good_box, bad[i]));
        check_no_manifold_at(__LINE__, what, i2d_collide_aabbs(bad[i], good_box));
        check_no_manifold_at(__LINE__, what, i2d_collide_aabb_circle(bad[i], good));
    }
    /* Valid overlapping input reports a contact, so the zeros above come from the checks. */
    i2d_manifold m = i2d_collide_circles(good, good);
    CHECK_ACCEPTED("i2d_collide_circles valid", i2d_last_status());
    I2D_CHECK(m.point_count == 1);
}
