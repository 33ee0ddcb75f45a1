/* SPDX-License-Identifier: MIT */
/* Shared by the C API bad-input tests (test_api_errors_defs.c, test_api_errors_calls.c):
 * checks that a call was refused or accepted, the fixture world both files work on, and
 * the snapshots that show a refused call left that world exactly as it was. The
 * definitions live in test_api_errors_defs.c. */
#ifndef I2D_TESTS_API_ERRORS_H
#define I2D_TESTS_API_ERRORS_H

#include <impulse2d/impulse2d.h>

#include <stddef.h>
#include <stdint.h>

#include "api_test_support.h"
#include "check.h"

/* NaN, inf and -inf: the three non-finite values every float input must refuse. */
enum { NON_FINITE_COUNT = 3 };
extern const float k_non_finite[NON_FINITE_COUNT];

/* Rotations by name. k_bad_rotations: finite but c^2 + s^2 more than 1e-3 from 1, refused
 * wherever a rotation is taken. k_unit_rotations: within 1e-3 of unit length, accepted
 * (and stored exactly normalised). */
typedef struct named_rot {
    const char* name;
    float c, s;
} named_rot;
extern const named_rot k_bad_rotations[];
extern const named_rot k_unit_rotations[];
extern const int k_bad_rotation_count, k_unit_rotation_count;

/* The call just made answered `expected`, with a message (check_refused_at,
 * api_test_support.h). */
#define CHECK_REFUSED(what, returned, expected) check_refused_at(__FILE__, __LINE__, (what), (returned), (expected))

/* The call just made succeeded: I2D_OK returned and recorded, empty message. */
void check_accepted_at(const char* file, int line, const char* what, i2d_status returned);
#define CHECK_ACCEPTED(what, returned) check_accepted_at(__FILE__, __LINE__, (what), (returned))

/* A rotation accepted as (c, s) is stored normalised and turned the same way. */
void check_stored_rotation_at(const char* file, int line, const char* what, i2d_rot stored, float c, float s);

/* Point sets that make no polygon (collinear, duplicate, tiny), and counts outside 3..8:
 * refused by i2d_shape_create_polygon and i2d_make_polygon alike. */
typedef struct point_set {
    const char* name;
    int32_t count;
    i2d_vec2 points[9];
} point_set;
extern const point_set k_bad_point_sets[];
extern const int k_bad_point_set_count;

/* ---- The fixture ------------------------------------------------------------------ */

/* A static ground (a box and a segment), a dynamic ball (circle and box) resting slightly
 * inside the ground and sliding, and a spinning kinematic mover (circle and capsule).
 * Built identically twice ("twins") so that hidden state can be compared by stepping
 * both. */
enum { FIX_GROUND, FIX_BALL, FIX_MOVER, FIX_BODIES };
enum {
    FIX_GROUND_BOX,
    FIX_GROUND_SEGMENT,
    FIX_BALL_CIRCLE,
    FIX_BALL_BOX,
    FIX_MOVER_CIRCLE,
    FIX_MOVER_CAPSULE,
    FIX_SHAPES
};

typedef struct fixture {
    i2d_world_id world;
    i2d_body_id body[FIX_BODIES];
    i2d_shape_id shape[FIX_SHAPES];
} fixture;

/* The ball's height: its position is (0, k_ball_y) until the first step. */
extern const float k_ball_y;

bool fixture_create(fixture* f);
void fixture_destroy(fixture* f);

/* Runs a test body on a fresh fixture, or on two fresh twins, and destroys them after it
 * (also when the body stops early at an I2D_REQUIRE). */
typedef void (*fixture_test_body)(const fixture* f);
typedef void (*twins_test_body)(const fixture* a, const fixture* b);
void run_on_fixture(fixture_test_body test_body);
void run_on_twins(twins_test_body test_body);

/* ---- Snapshots: everything the API lets us observe about the fixture ---------------- */

enum { SNAP_MAX = 1024 };

/* A flat record of observable values, compared bit for bit: a refused call must not
 * change a single bit. Each value remembers the object index and field for the log. */
typedef struct snapshot {
    int count;
    uint64_t value[SNAP_MAX];
    const char* field[SNAP_MAX];
    int object[SNAP_MAX];
} snapshot;

void snapshot_take(const fixture* f, snapshot* s);

/* Fails (once, naming the first difference) unless the two snapshots are bit-identical. */
void check_same_snapshot_at(const char* file, int line, const char* what, const snapshot* expected,
                            const snapshot* actual);
#define CHECK_SAME_SNAPSHOT(what, expected, actual) \
    check_same_snapshot_at(__FILE__, __LINE__, (what), (expected), (actual))

/* Fails unless the fixture still matches `before`. */
void check_unchanged_at(const char* file, int line, const char* what, const fixture* f, const snapshot* before);
#define CHECK_UNCHANGED(what, f, before) check_unchanged_at(__FILE__, __LINE__, (what), (f), (before))

/* Steps both twins and checks they still agree, which catches hidden state a refused
 * call may have changed (accumulated forces and torques, materials read only by the
 * solver...). */
void check_twins_agree_after_steps(const fixture* a, const fixture* b);

/* ---- Tables ------------------------------------------------------------------------ */

/* Writes a float field of a struct through its offset (the tables name fields by offset). */
void set_float_at(void* object, size_t offset, float value);

typedef struct float_field {
    const char* name;
    size_t offset;
} float_field;

typedef struct float_field_value {
    const char* name;
    size_t offset;
    float value;
} float_field_value;

/* Every AABB that must be refused: NaN or infinite corners, min > max. Fills out (room
 * for 32) and sets *count. */
void bad_aabbs(i2d_aabb* out, int* count);

#endif
