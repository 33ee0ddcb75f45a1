/* SPDX-License-Identifier: MIT */
/* Joint angles more than a turn from zero. Every angle a joint takes as any finite
 * number (the revolute, prismatic and weld reference_angle, the revolute spring's
 * target_angle, the motor joint's angular_offset) names the same pose as its reduced
 * angle in (-pi, pi]. Each is given at +-7, +-100 and +-1e4 rad, through the def and
 * through the setter, and must move its body as the reduced angle (computed here in
 * double) does; its getter reads back the reduced angle, and a revolute joint's measured
 * angle stays in (-pi, pi]. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdio.h>

#include "api_test_support.h"
#include "check.h"

static const double k_pi = 3.14159265358979323846;

/* Angles more than a turn from zero, rad: 7 is within one wind-back of (-pi, pi], 100
 * and 1e4 are 16 and 1592 turns out. */
static const float k_far_angles[] = {7.0f, -7.0f, 100.0f, -100.0f, 1.0e4f, -1.0e4f};
enum { FAR_ANGLE_COUNT = sizeof k_far_angles / sizeof k_far_angles[0] };

/* 2 s at the tests' step: long enough for every joint here to have turned its body. */
enum { STEPS = 120 };

/* A far angle and its reduced one differ by whole turns up to the float rounding of the
 * reduced one; the motion they give may differ by that rounding carried through 2 s,
 * far below these (a wrong wind is off by metres and radians). */
static const double k_pose_tolerance_m = 1.0e-4;
static const double k_rotation_tolerance = 1.0e-4; /* on the rotation's cosine and sine */
/* One float ulp at pi, rad: the stored angle is the reduced one rounded to float. */
static const double k_stored_angle_tolerance_rad = 2.4e-7;

/* The angle in (-pi, pi] that names the same pose, in double: fmod is exact, so only the
 * final whole-turn shift rounds (in double, far below a float ulp). */
static double reduced_angle(float angle) {
    const double turn = 2.0 * k_pi;
    double r = fmod((double)angle, turn);
    if (r > k_pi) {
        r -= turn;
    } else if (r <= -k_pi) {
        r += turn;
    }
    return r;
}

/* ---- One joint setting that is an angle, on a scene where that angle steers B ------- */

typedef struct angle_setting {
    const char* name;
    float gravity_y;
    bool revolute; /* whether i2d_revolute_joint_get_angle applies */
    i2d_joint_id (*create)(i2d_world_id world, i2d_body_id a, i2d_body_id b, float angle);
    i2d_status (*set)(i2d_joint_id joint, float angle);
    float (*get)(i2d_joint_id joint);
} angle_setting;

/* The shared scene: static A at the origin, dynamic B a 1 m by 0.2 m bar centred at
 * (1, 0), anchored at its left end (the origin); the motor joint's B sits on A's origin. */
static const float k_arm_x = 1.0f;
static i2d_vec2 arm_anchor(void) { return v2(-k_arm_x, 0.0f); }

static i2d_joint_id create_revolute_reference(i2d_world_id world, i2d_body_id a, i2d_body_id b, float angle) {
    i2d_revolute_joint_def d = i2d_default_revolute_joint_def();
    d.base.body_a = a;
    d.base.body_b = b;
    d.base.local_anchor_b = arm_anchor();
    d.reference_angle = angle;
    d.enable_limit = true;
    d.lower_angle = -0.25f;
    d.upper_angle = 0.25f;
    return i2d_joint_create_revolute(world, &d);
}

static i2d_joint_id create_revolute_target(i2d_world_id world, i2d_body_id a, i2d_body_id b, float angle) {
    i2d_revolute_joint_def d = i2d_default_revolute_joint_def();
    d.base.body_a = a;
    d.base.body_b = b;
    d.base.local_anchor_b = arm_anchor();
    d.enable_spring = true;
    d.hertz = 1.0f;
    d.damping_ratio = 1.0f;
    d.target_angle = angle;
    return i2d_joint_create_revolute(world, &d);
}

static i2d_joint_id create_prismatic_reference(i2d_world_id world, i2d_body_id a, i2d_body_id b, float angle) {
    i2d_prismatic_joint_def d = i2d_default_prismatic_joint_def();
    d.base.body_a = a;
    d.base.body_b = b;
    d.base.local_anchor_b = arm_anchor();
    d.reference_angle = angle;
    d.enable_limit = true;
    d.lower_translation = -0.1f;
    d.upper_translation = 0.1f;
    return i2d_joint_create_prismatic(world, &d);
}

static i2d_joint_id create_weld_reference(i2d_world_id world, i2d_body_id a, i2d_body_id b, float angle) {
    i2d_weld_joint_def d = i2d_default_weld_joint_def();
    d.base.body_a = a;
    d.base.body_b = b;
    d.base.local_anchor_b = arm_anchor();
    d.reference_angle = angle;
    return i2d_joint_create_weld(world, &d);
}

static i2d_joint_id create_motor_offset(i2d_world_id world, i2d_body_id a, i2d_body_id b, float angle) {
    i2d_motor_joint_def d = i2d_default_motor_joint_def();
    d.base.body_a = a;
    d.base.body_b = b;
    d.linear_offset = v2(k_arm_x, 0.0f);
    d.angular_offset = angle;
    d.max_force = 10.0f;
    d.max_torque = 10.0f;
    return i2d_joint_create_motor(world, &d);
}

static const angle_setting k_revolute_reference = {"revolute reference_angle", -10.0f, true,
                                                   create_revolute_reference, i2d_revolute_joint_set_reference_angle,
                                                   i2d_revolute_joint_get_reference_angle};
static const angle_setting k_revolute_target = {"revolute target_angle", 0.0f, true, create_revolute_target,
                                                i2d_revolute_joint_set_target_angle,
                                                i2d_revolute_joint_get_target_angle};
static const angle_setting k_prismatic_reference = {"prismatic reference_angle", -10.0f, false,
                                                    create_prismatic_reference,
                                                    i2d_prismatic_joint_set_reference_angle,
                                                    i2d_prismatic_joint_get_reference_angle};
static const angle_setting k_weld_reference = {"weld reference_angle", -10.0f, false, create_weld_reference,
                                               i2d_weld_joint_set_reference_angle,
                                               i2d_weld_joint_get_reference_angle};
static const angle_setting k_motor_offset = {"motor angular_offset", 0.0f, false, create_motor_offset,
                                             i2d_motor_joint_set_angular_offset,
                                             i2d_motor_joint_get_angular_offset};

/* ---- Running a scene ------------------------------------------------------------------ */

typedef enum angle_path { BY_DEF, BY_SETTER } angle_path;

/* What a run shows: B's pose after STEPS, the stored angle read back, and for a revolute
 * joint its measured angle at the start and the end (else 0). */
typedef struct outcome {
    bool ok;
    i2d_vec2 position;
    i2d_rot rotation;
    float stored;
    float joint_angle_start, joint_angle_end;
} outcome;

static outcome run_scene(const angle_setting* setting, float angle, angle_path path) {
    outcome out = {0};
    i2d_world_id world = make_world(setting->gravity_y);
    i2d_body_id a = make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_body_id b = make_body(world, I2D_BODY_DYNAMIC, k_arm_x, 0.0f);
    i2d_shape_def shape = i2d_default_shape_def();
    i2d_shape_create_box(b, &shape, 0.5f, 0.1f);
    i2d_joint_id joint = setting->create(world, a, b, path == BY_DEF ? angle : 0.0f);
    out.ok = !I2D_IS_NULL(joint) && (path == BY_DEF || setting->set(joint, angle) == I2D_OK);
    if (out.ok) {
        out.stored = setting->get(joint);
        out.joint_angle_start = setting->revolute ? i2d_revolute_joint_get_angle(joint) : 0.0f;
        for (int i = 0; i < STEPS && out.ok; ++i) {
            out.ok = step_ok(world);
        }
        out.position = i2d_body_get_position(b);
        out.rotation = i2d_body_get_rotation(b);
        out.joint_angle_end = setting->revolute ? i2d_revolute_joint_get_angle(joint) : 0.0f;
    }
    i2d_world_destroy(world);
    return out;
}

static bool within_half_turn(float angle) { return angle > -(float)k_pi && angle <= (float)k_pi; }

static bool same_pose(const outcome* x, const outcome* y) {
    return fabs((double)x->position.x - y->position.x) <= k_pose_tolerance_m &&
           fabs((double)x->position.y - y->position.y) <= k_pose_tolerance_m &&
           fabs((double)x->rotation.c - y->rotation.c) <= k_rotation_tolerance &&
           fabs((double)x->rotation.s - y->rotation.s) <= k_rotation_tolerance;
}

/* Every far angle, by def and by setter, against its reduced angle given by def. */
static void check_far_angles_act_as_reduced(const angle_setting* setting) {
    g_reports_left = 12;
    for (int i = 0; i < FAR_ANGLE_COUNT; ++i) {
        const float far = k_far_angles[i];
        const double reduced = reduced_angle(far);
        const outcome expected = run_scene(setting, (float)reduced, BY_DEF);
        I2D_REQUIRE(expected.ok);
        for (int path = BY_DEF; path <= BY_SETTER; ++path) {
            const outcome got = run_scene(setting, far, (angle_path)path);
            const char* how = path == BY_DEF ? "def" : "setter";
            if (!got.ok) {
                ++i2d_check_failures;
                report("%s %g by %s: refused or a step failed", setting->name, (double)far, how);
                continue;
            }
            if (fabs((double)got.stored - reduced) > k_stored_angle_tolerance_rad) {
                ++i2d_check_failures;
                report("%s %g by %s: reads back %.9g, not the reduced %.9g", setting->name, (double)far, how,
                       (double)got.stored, reduced);
            }
            if (!same_pose(&got, &expected)) {
                ++i2d_check_failures;
                report("%s %g by %s: B ends at (%g, %g) turned (%g, %g); with %.7g at (%g, %g) turned (%g, %g)",
                       setting->name, (double)far, how, (double)got.position.x, (double)got.position.y,
                       (double)got.rotation.c, (double)got.rotation.s, reduced, (double)expected.position.x,
                       (double)expected.position.y, (double)expected.rotation.c, (double)expected.rotation.s);
            }
            const bool wound = within_half_turn(got.joint_angle_start) && within_half_turn(got.joint_angle_end);
            if (setting->revolute && !wound) {
                ++i2d_check_failures;
                report("%s %g by %s: i2d_revolute_joint_get_angle reads %g at the start and %g at the end, "
                       "outside (-pi, pi]",
                       setting->name, (double)far, how, (double)got.joint_angle_start, (double)got.joint_angle_end);
            }
        }
    }
}

I2D_TEST(api_joint_far_revolute_reference_acts_as_reduced) { check_far_angles_act_as_reduced(&k_revolute_reference); }
I2D_TEST(api_joint_far_revolute_target_acts_as_reduced) { check_far_angles_act_as_reduced(&k_revolute_target); }
I2D_TEST(api_joint_far_prismatic_reference_acts_as_reduced) {
    check_far_angles_act_as_reduced(&k_prismatic_reference);
}
I2D_TEST(api_joint_far_weld_reference_acts_as_reduced) { check_far_angles_act_as_reduced(&k_weld_reference); }
I2D_TEST(api_joint_far_motor_offset_acts_as_reduced) { check_far_angles_act_as_reduced(&k_motor_offset); }
