/* SPDX-License-Identifier: MIT */
/* The ragdoll of scenes.md (Box2D v3's shared/human.c, rebuilt through the public C API): 11
 * capsule bodies held by 10 revolute joints, each with a limit, a spring toward its rest angle
 * and a motor at speed 0 acting as joint friction. The rain scene drops 1000 of them; the
 * physics tests, the determinism tests and the demo build the same one from here. */
#ifndef IMPULSE2D_BENCH_RAGDOLL_H
#define IMPULSE2D_BENCH_RAGDOLL_H

#include <impulse2d/impulse2d.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bones in creation order; every bone but the hip hangs from its parent by one joint. */
typedef enum bench_bone {
    BENCH_BONE_HIP,
    BENCH_BONE_TORSO,
    BENCH_BONE_HEAD,
    BENCH_BONE_UPPER_LEFT_LEG,
    BENCH_BONE_LOWER_LEFT_LEG,
    BENCH_BONE_UPPER_RIGHT_LEG,
    BENCH_BONE_LOWER_RIGHT_LEG,
    BENCH_BONE_UPPER_LEFT_ARM,
    BENCH_BONE_LOWER_LEFT_ARM,
    BENCH_BONE_UPPER_RIGHT_ARM,
    BENCH_BONE_LOWER_RIGHT_ARM,
    BENCH_BONE_COUNT
} bench_bone;

typedef struct bench_ragdoll_def {
    i2d_vec2 position;         /* the spawn point: the feet are 0.275 scale above it */
    float scale;               /* 1: a 1.7 m figure */
    float joint_friction;      /* N m of motor torque per unit friction scale; rain: 0.05 */
    float joint_hertz;         /* the joints' springs toward angle 0; rain: 5 (0: no spring) */
    float joint_damping_ratio; /* rain: 0.5 */
    int32_t group;             /* > 0: the shapes get filter group -group (never collide with
                                  another ragdoll of the same group); 0: no group */
    void* user_data;           /* given to every body */
} bench_ragdoll_def;

typedef struct bench_ragdoll {
    i2d_body_id bodies[BENCH_BONE_COUNT];
    i2d_joint_id joints[BENCH_BONE_COUNT]; /* joints[bone] joins the bone to its parent; the hip's is null */
} bench_ragdoll;

/* The rain scene's settings (scenes.md) at `position` in `group`. */
bench_ragdoll_def bench_default_ragdoll_def(i2d_vec2 position, int32_t group);

/* Builds one ragdoll, upright, at rest. False on a failed i2d_ call (read i2d_last_error_message()). */
bool bench_ragdoll_create(i2d_world_id world, const bench_ragdoll_def* def, bench_ragdoll* out);

/* Destroys the bodies (and so the joints). False on a failed i2d_ call. */
bool bench_ragdoll_destroy(bench_ragdoll* ragdoll);

#ifdef __cplusplus
}
#endif

#endif
