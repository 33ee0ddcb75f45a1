/* SPDX-License-Identifier: MIT */
/* The ragdoll of scenes.md, built from one table of bones. */
#include "ragdoll.h"

#include <string.h>

#define RAGDOLL_PI 3.14159265358979f

/* One bone: heights are above the spawn point, at scale 1; capsules run along the body's y axis
 * from c1 to c2; limits and frame rotation in units of pi (scenes.md, "Ragdoll bones"). */
typedef struct bone_spec {
    int32_t parent; /* -1: the hip, the root */
    float body_y;
    float c1, c2, radius;
    float linear_damping;   /* 1/s: the head and lower arms are damped a little */
    float pivot_y;
    float lower, upper;     /* joint angle limits / pi */
    float friction_scale;   /* share of the joint friction torque */
    float frame_rotation;   /* / pi: the joint's reference angle (the lower arms start bent) */
    bool foot;              /* the lower legs carry a foot polygon */
} bone_spec;

static const bone_spec bones[BENCH_BONE_COUNT] = {
    /* parent, body y, c1, c2, radius, damping, pivot, lower, upper, friction, frame, foot */
    {-1, 0.95f, -0.02f, 0.02f, 0.095f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, false},                         /* hip */
    {BENCH_BONE_HIP, 1.2f, -0.135f, 0.135f, 0.09f, 0.0f, 1.0f, -0.25f, 0.0f, 0.5f, 0.0f, false},           /* torso */
    {BENCH_BONE_TORSO, 1.475f, -0.038f, 0.039f, 0.075f, 0.1f, 1.4f, -0.3f, 0.1f, 0.25f, 0.0f, false},      /* head */
    {BENCH_BONE_HIP, 0.775f, -0.125f, 0.125f, 0.06f, 0.0f, 0.9f, -0.05f, 0.4f, 1.0f, 0.0f, false},         /* upper left leg */
    {BENCH_BONE_UPPER_LEFT_LEG, 0.475f, -0.155f, 0.125f, 0.045f, 0.0f, 0.625f, -0.5f, -0.02f, 0.5f, 0.0f, true},
    {BENCH_BONE_HIP, 0.775f, -0.125f, 0.125f, 0.06f, 0.0f, 0.9f, -0.05f, 0.4f, 1.0f, 0.0f, false},         /* upper right leg */
    {BENCH_BONE_UPPER_RIGHT_LEG, 0.475f, -0.155f, 0.125f, 0.045f, 0.0f, 0.625f, -0.5f, -0.02f, 0.5f, 0.0f, true},
    {BENCH_BONE_TORSO, 1.225f, -0.125f, 0.125f, 0.035f, 0.0f, 1.35f, -0.1f, 0.8f, 0.5f, 0.0f, false},      /* upper left arm */
    {BENCH_BONE_UPPER_LEFT_ARM, 0.975f, -0.125f, 0.125f, 0.03f, 0.1f, 1.1f, -0.2f, 0.3f, 0.1f, 0.25f, false},
    {BENCH_BONE_TORSO, 1.225f, -0.125f, 0.125f, 0.035f, 0.0f, 1.35f, -0.1f, 0.8f, 0.5f, 0.0f, false},      /* upper right arm */
    {BENCH_BONE_UPPER_RIGHT_ARM, 0.975f, -0.125f, 0.125f, 0.03f, 0.1f, 1.1f, -0.2f, 0.3f, 0.1f, 0.25f, false},
};

/* The foot, in the lower leg's frame at scale 1, rounded by FOOT_RADIUS. */
static const i2d_vec2 foot_points[4] = {{-0.03f, -0.185f}, {0.11f, -0.185f}, {0.11f, -0.16f}, {-0.03f, -0.14f}};
#define FOOT_RADIUS 0.015f
/* Ragdolls collide with the ground (category 1) and with other ragdolls (category 2); feet
 * only with the ground, so that a pile of ragdolls does not snag on its feet. */
#define RAGDOLL_CATEGORY 2u
#define RAGDOLL_MASK (1u | 2u)
#define FOOT_MASK 1u
#define RAGDOLL_FRICTION 0.2f
#define FOOT_FRICTION 0.05f

bench_ragdoll_def bench_default_ragdoll_def(i2d_vec2 position, int32_t group) {
    bench_ragdoll_def def;
    memset(&def, 0, sizeof def);
    def.position = position;
    def.scale = 1.0f;
    def.joint_friction = 0.05f;
    def.joint_hertz = 5.0f;
    def.joint_damping_ratio = 0.5f;
    def.group = group;
    return def;
}

static i2d_vec2 make_vec2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static bool add_foot(i2d_body_id body, const i2d_shape_def* leg_def, float s) {
    i2d_shape_def def = *leg_def;
    i2d_vec2 points[4];
    i2d_polygon foot;
    int k;
    for (k = 0; k < 4; ++k) {
        points[k] = make_vec2(s * foot_points[k].x, s * foot_points[k].y);
    }
    def.friction = FOOT_FRICTION;
    def.filter.mask_bits = FOOT_MASK;
    return i2d_make_polygon(points, 4, s * FOOT_RADIUS, &foot) == I2D_OK &&
           !I2D_IS_NULL(i2d_shape_create_polygon_from(body, &def, &foot));
}

/* The revolute joint from the bone's parent (A) to the bone (B) at the bone's pivot. */
static i2d_joint_id add_joint(i2d_world_id world, const bench_ragdoll_def* def, const bench_ragdoll* r, int32_t bone) {
    const bone_spec* b = &bones[bone];
    float s = def->scale;
    i2d_vec2 pivot = make_vec2(def->position.x, def->position.y + s * b->pivot_y);
    i2d_revolute_joint_def jd = i2d_default_revolute_joint_def();
    jd.base.body_a = r->bodies[b->parent];
    jd.base.body_b = r->bodies[bone];
    jd.base.local_anchor_a = i2d_body_get_local_point(jd.base.body_a, pivot);
    jd.base.local_anchor_b = i2d_body_get_local_point(jd.base.body_b, pivot);
    jd.reference_angle = b->frame_rotation * RAGDOLL_PI;
    jd.enable_limit = true;
    jd.lower_angle = b->lower * RAGDOLL_PI;
    jd.upper_angle = b->upper * RAGDOLL_PI;
    jd.enable_motor = true;
    jd.motor_speed = 0.0f;
    jd.max_motor_torque = b->friction_scale * def->joint_friction * s;
    jd.enable_spring = def->joint_hertz > 0.0f;
    jd.hertz = def->joint_hertz;
    jd.damping_ratio = def->joint_damping_ratio;
    jd.target_angle = 0.0f;
    return i2d_joint_create_revolute(world, &jd);
}

bool bench_ragdoll_create(i2d_world_id world, const bench_ragdoll_def* def, bench_ragdoll* out) {
    float s = def->scale;
    i2d_shape_def shape_def = i2d_default_shape_def();
    int32_t bone;
    memset(out, 0, sizeof *out);
    shape_def.friction = RAGDOLL_FRICTION;
    shape_def.filter.category_bits = RAGDOLL_CATEGORY;
    shape_def.filter.mask_bits = RAGDOLL_MASK;
    shape_def.filter.group_index = -def->group;
    for (bone = 0; bone < BENCH_BONE_COUNT; ++bone) {
        const bone_spec* b = &bones[bone];
        i2d_body_def body_def = i2d_default_body_def();
        i2d_body_id body;
        body_def.type = I2D_BODY_DYNAMIC;
        body_def.position = make_vec2(def->position.x, def->position.y + s * b->body_y);
        body_def.linear_damping = b->linear_damping;
        body_def.user_data = def->user_data;
        body = i2d_body_create(world, &body_def);
        if (I2D_IS_NULL(body)) {
            return false;
        }
        out->bodies[bone] = body;
        if (I2D_IS_NULL(i2d_shape_create_capsule(body, &shape_def, make_vec2(0.0f, s * b->c1),
                                                 make_vec2(0.0f, s * b->c2), s * b->radius)) ||
            (b->foot && !add_foot(body, &shape_def, s))) {
            return false;
        }
        if (b->parent >= 0) {
            out->joints[bone] = add_joint(world, def, out, bone);
            if (I2D_IS_NULL(out->joints[bone])) {
                return false;
            }
        }
    }
    return true;
}

bool bench_ragdoll_destroy(bench_ragdoll* ragdoll) {
    bool ok = true;
    int32_t bone;
    for (bone = 0; bone < BENCH_BONE_COUNT; ++bone) {
        if (!I2D_IS_NULL(ragdoll->bodies[bone])) {
            ok = i2d_body_destroy(ragdoll->bodies[bone]) == I2D_OK && ok;
        }
    }
    memset(ragdoll, 0, sizeof *ragdoll);
    return ok;
}
