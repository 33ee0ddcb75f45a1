/* SPDX-License-Identifier: MIT */
/* Writes tests/determinism/data/golden_snapshot.bin and golden_snapshot.txt: a snapshot of a small
 * mixed world, and the state hash a world made from it has after 60 steps, which every platform
 * (x86-64, AArch64 under qemu, WebAssembly) must reproduce: test_golden_snapshot.cpp checks it.
 *
 * Format of golden_snapshot.txt, one line: "bytes=N hash_at_load=H0 steps=60 hash=H" (H0, H: 16 hex digits).
 * N is the size of the .bin; H0 and H are i2d_world_get_state_hash of a world made from the .bin by
 * i2d_world_create_from_snapshot, before stepping and after `steps` steps of 1/60 s, 4 substeps.
 *
 * The world: a static floor box, a static segment ramp and a chain of hills; a contact pile of
 * boxes, circles, a capsule, a rounded triangle and a body of two offset boxes, and a ball rolling
 * down the ramp; a pendulum of two capsules on revolute joints (limit and motor on the lower
 * one), a disc on a distance joint with a spring, and two boxes welded side by side on the floor.
 * Saved after 30 steps, so that contacts carry impulses and the pendulum swings. Regenerate only
 * when the snapshot format or the physics is meant to change, and say so in the commit.
 * usage: make_golden_snapshot OUT_DIR (built with the tests: build/tests/make_golden_snapshot) */
#include <impulse2d/impulse2d.h>
#include <impulse2d/snapshot.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TIME_STEP (1.0f / 60.0f)
#define SUBSTEPS 4
#define STEPS_BEFORE_SAVE 30
#define GOLDEN_STEPS 60

static i2d_vec2 v2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static i2d_body_id body_at(i2d_world_id world, i2d_body_type type, float x, float y, float angle) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = v2(x, y);
    def.rotation = i2d_make_rot(angle);
    return i2d_body_create(world, &def);
}

static i2d_world_id build(void) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    i2d_shape_def plain = i2d_default_shape_def();
    i2d_shape_def bouncy = i2d_default_shape_def();
    i2d_body_id ground, body, frame, upper, lower, disc, left, right;
    i2d_segment ramp;
    i2d_circle circle;
    i2d_polygon triangle;
    i2d_chain_def chain = i2d_default_chain_def();
    const i2d_vec2 hills[] = {{7.0f, 0.5f}, {8.0f, 0.0f}, {9.5f, 0.4f}, {11.0f, 0.1f}, {12.5f, 0.8f}, {13.5f, 1.5f}};
    const i2d_vec2 corners[] = {{-0.3f, -0.2f}, {0.3f, -0.2f}, {0.0f, 0.3f}};
    i2d_revolute_joint_def revolute;
    i2d_distance_joint_def distance;
    i2d_weld_joint_def weld;
    int i;

    bouncy.restitution = 0.5f;
    bouncy.friction = 0.3f;
    /* Static geometry: a floor whose top is at y = 0, a segment ramp, a chain of hills. */
    ground = body_at(world, I2D_BODY_STATIC, 0.0f, 0.0f, 0.0f);
    i2d_shape_create_offset_box(ground, &plain, 6.0f, 0.5f, v2(0.0f, -0.5f), i2d_make_rot(0.0f));
    ramp.point1 = v2(-6.0f, 3.0f);
    ramp.point2 = v2(-3.0f, 1.0f);
    i2d_shape_create_segment(ground, &plain, ramp.point1, ramp.point2);
    chain.points = hills;
    chain.count = (int32_t)(sizeof hills / sizeof hills[0]);
    i2d_chain_create(ground, &chain);

    /* The pile: three boxes stacked, two circles and a capsule on them, a rounded triangle and a
     * body of two offset boxes falling on top, a ball rolling down the ramp. */
    for (i = 0; i < 3; ++i) {
        body = body_at(world, I2D_BODY_DYNAMIC, 0.1f * (float)i, 0.5f + 1.0f * (float)i, 0.0f);
        i2d_shape_create_box(body, &plain, 0.5f, 0.5f);
    }
    circle.center = v2(0.0f, 0.0f);
    circle.radius = 0.3f;
    body = body_at(world, I2D_BODY_DYNAMIC, -0.2f, 3.4f, 0.0f);
    i2d_shape_create_circle(body, &bouncy, &circle);
    body = body_at(world, I2D_BODY_DYNAMIC, 0.4f, 4.2f, 0.0f);
    i2d_shape_create_circle(body, &plain, &circle);
    body = body_at(world, I2D_BODY_DYNAMIC, 0.0f, 5.0f, 0.3f);
    i2d_shape_create_capsule(body, &plain, v2(-0.4f, 0.0f), v2(0.4f, 0.0f), 0.15f);
    i2d_make_polygon(corners, 3, 0.05f, &triangle);
    body = body_at(world, I2D_BODY_DYNAMIC, 0.2f, 5.8f, 0.5f);
    i2d_shape_create_polygon_from(body, &plain, &triangle);
    body = body_at(world, I2D_BODY_DYNAMIC, -0.1f, 6.8f, -0.2f);
    i2d_shape_create_offset_box(body, &plain, 0.4f, 0.1f, v2(0.0f, 0.0f), i2d_make_rot(0.0f));
    i2d_shape_create_offset_box(body, &plain, 0.1f, 0.3f, v2(0.3f, 0.3f), i2d_make_rot(0.0f));
    circle.radius = 0.25f;
    body = body_at(world, I2D_BODY_DYNAMIC, -5.5f, 3.5f, 0.0f);
    i2d_shape_create_circle(body, &bouncy, &circle);

    /* A pendulum of two capsules from a static frame: revolute joints, the lower one with a
     * limit and a motor. */
    frame = body_at(world, I2D_BODY_STATIC, -3.0f, 8.0f, 0.0f);
    upper = body_at(world, I2D_BODY_DYNAMIC, -2.0f, 8.0f, 0.0f);
    i2d_shape_create_capsule(upper, &plain, v2(-0.5f, 0.0f), v2(0.5f, 0.0f), 0.1f);
    lower = body_at(world, I2D_BODY_DYNAMIC, -0.5f, 8.0f, 0.0f);
    i2d_shape_create_capsule(lower, &plain, v2(-0.5f, 0.0f), v2(0.5f, 0.0f), 0.1f);
    revolute = i2d_default_revolute_joint_def();
    revolute.base.body_a = frame;
    revolute.base.body_b = upper;
    revolute.base.local_anchor_a = v2(0.0f, 0.0f);
    revolute.base.local_anchor_b = v2(-0.75f, 0.0f);
    i2d_joint_create_revolute(world, &revolute);
    revolute = i2d_default_revolute_joint_def();
    revolute.base.body_a = upper;
    revolute.base.body_b = lower;
    revolute.base.local_anchor_a = v2(0.75f, 0.0f);
    revolute.base.local_anchor_b = v2(-0.75f, 0.0f);
    revolute.enable_limit = true;
    revolute.lower_angle = -0.6f;
    revolute.upper_angle = 0.6f;
    revolute.enable_motor = true;
    revolute.motor_speed = 0.5f;
    revolute.max_motor_torque = 2.0f;
    i2d_joint_create_revolute(world, &revolute);

    /* A disc hung from the frame by a springy distance joint. */
    circle.radius = 0.2f;
    disc = body_at(world, I2D_BODY_DYNAMIC, 3.0f, 6.5f, 0.0f);
    i2d_shape_create_circle(disc, &plain, &circle);
    distance = i2d_default_distance_joint_def();
    distance.base.body_a = frame;
    distance.base.body_b = disc;
    distance.base.local_anchor_a = v2(6.0f, 0.0f);
    distance.length = 1.5f;
    distance.enable_spring = true;
    distance.hertz = 2.0f;
    distance.damping_ratio = 0.1f;
    i2d_joint_create_distance(world, &distance);

    /* Two boxes welded side by side, dropped on the right of the floor. */
    left = body_at(world, I2D_BODY_DYNAMIC, 3.0f, 1.5f, 0.0f);
    i2d_shape_create_box(left, &plain, 0.4f, 0.4f);
    right = body_at(world, I2D_BODY_DYNAMIC, 3.8f, 1.5f, 0.0f);
    i2d_shape_create_box(right, &plain, 0.4f, 0.4f);
    weld = i2d_default_weld_joint_def();
    weld.base.body_a = left;
    weld.base.body_b = right;
    weld.base.local_anchor_a = v2(0.4f, 0.0f);
    weld.base.local_anchor_b = v2(-0.4f, 0.0f);
    i2d_joint_create_weld(world, &weld);
    return world;
}

static int write_file(const char* dir, const char* name, const void* data, size_t size) {
    char path[4096];
    FILE* f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        fprintf(stderr, "make_golden_snapshot: cannot write %s\n", path);
        return 0;
    }
    printf("wrote %s (%zu bytes)\n", path, size);
    return 1;
}

int main(int argc, char** argv) {
    i2d_world_id world, loaded;
    unsigned char* bytes;
    size_t size;
    uint64_t hash_at_load, hash;
    char line[160];
    int i;
    if (argc != 2) {
        fprintf(stderr, "usage: make_golden_snapshot OUT_DIR (tests/determinism/data)\n");
        return 2;
    }
    world = build();
    if (I2D_IS_NULL(world) || i2d_last_status() != I2D_OK) {
        fprintf(stderr, "make_golden_snapshot: building the world failed: %s\n", i2d_last_error_message());
        return 1;
    }
    for (i = 0; i < STEPS_BEFORE_SAVE; ++i) {
        i2d_world_step(world, TIME_STEP, SUBSTEPS);
    }
    size = i2d_world_get_snapshot_size(world);
    bytes = (unsigned char*)malloc(size);
    if (!bytes || i2d_world_save_snapshot(world, bytes, size, NULL) != I2D_OK) {
        fprintf(stderr, "make_golden_snapshot: saving failed: %s\n", i2d_last_error_message());
        return 1;
    }
    /* The hashes are of a world made from the bytes, as the tests make it. */
    loaded = i2d_world_create_from_snapshot(bytes, size, NULL);
    if (I2D_IS_NULL(loaded)) {
        fprintf(stderr, "make_golden_snapshot: loading failed: %s\n", i2d_last_error_message());
        return 1;
    }
    hash_at_load = i2d_world_get_state_hash(loaded);
    for (i = 0; i < GOLDEN_STEPS; ++i) {
        i2d_world_step(loaded, TIME_STEP, SUBSTEPS);
    }
    hash = i2d_world_get_state_hash(loaded);
    snprintf(line, sizeof line, "bytes=%zu hash_at_load=%016llx steps=%d hash=%016llx\n", size,
             (unsigned long long)hash_at_load, GOLDEN_STEPS, (unsigned long long)hash);
    if (!write_file(argv[1], "golden_snapshot.bin", bytes, size) ||
        !write_file(argv[1], "golden_snapshot.txt", line, strlen(line))) {
        return 1;
    }
    printf("%s", line);
    i2d_world_destroy(loaded);
    i2d_world_destroy(world);
    free(bytes);
    return 0;
}
