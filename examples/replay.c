/* SPDX-License-Identifier: MIT */
/* impulse2d_replay: replays a recording and says whether, and where, it diverges.
 *
 *   impulse2d_replay FILE [--workers N]   replay FILE, checking every step's hash
 *   impulse2d_replay --record FILE        record a small session (a pile, pushes, a
 *                                         gravity change) into FILE, to try it on
 *
 * Exit status: 0 no divergence, 1 a step diverged, 2 the file was refused or unreadable.
 * A recording made by one build and replayed by another tells whether the two compute
 * the same bits, and from which step they part. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <impulse2d/impulse2d.h>

#define SESSION_STEPS 240

static void write_to_file(const void* bytes, size_t size, void* context) {
    fwrite(bytes, 1, size, (FILE*)context);
}

static int record_session(const char* path) {
    FILE* file = fopen(path, "wb");
    if (file == NULL) {
        fprintf(stderr, "cannot write %s\n", path);
        return 2;
    }
    const i2d_world_def wd = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&wd);
    i2d_body_def bd = i2d_default_body_def();
    const i2d_body_id ground = i2d_body_create(world, &bd);
    const i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(ground, &sd, 20.0f, 0.5f);
    i2d_world_start_recording(world, write_to_file, file);
    bd.type = I2D_BODY_DYNAMIC;
    i2d_body_id last = I2D_NULL_BODY_ID;
    for (int step = 1; step <= SESSION_STEPS; ++step) {
        if (step % 8 == 1 && step < 160) { /* a box or a ball dropped every 8 steps */
            bd.position = (i2d_vec2){-3.0f + 0.37f * (float)(step % 17), 12.0f};
            last = i2d_body_create(world, &bd);
            if (step % 16 == 1) {
                i2d_shape_create_box(last, &sd, 0.4f, 0.3f);
            } else {
                const i2d_circle ball = {{0.0f, 0.0f}, 0.35f};
                i2d_shape_create_circle(last, &sd, &ball);
            }
        }
        if (step % 30 == 0) {
            i2d_body_apply_linear_impulse(last, (i2d_vec2){2.0f, 1.0f}, i2d_body_get_position(last), true);
        }
        if (step == 180) {
            i2d_world_set_gravity(world, (i2d_vec2){-3.0f, -9.8f});
        }
        i2d_world_step(world, 1.0f / 60.0f, 4);
    }
    i2d_world_stop_recording(world);
    printf("recorded %d steps into %s (%ld bytes), final hash %016llx\n", SESSION_STEPS, path, ftell(file),
           (unsigned long long)i2d_world_get_state_hash(world));
    i2d_world_destroy(world);
    return fclose(file) == 0 ? 0 : 2;
}

static unsigned char* read_file(const char* path, size_t* size) {
    FILE* file = fopen(path, "rb");
    if (file == NULL) {
        return NULL;
    }
    fseek(file, 0, SEEK_END);
    const long length = ftell(file);
    fseek(file, 0, SEEK_SET);
    unsigned char* bytes = length > 0 ? (unsigned char*)malloc((size_t)length) : NULL;
    *size = bytes != NULL ? fread(bytes, 1, (size_t)length, file) : 0;
    fclose(file);
    return bytes;
}

static int replay_file(const char* path, int workers) {
    size_t size = 0;
    unsigned char* bytes = read_file(path, &size);
    if (bytes == NULL) {
        fprintf(stderr, "cannot read %s\n", path);
        return 2;
    }
    i2d_world_def runtime = i2d_default_world_def();
    runtime.worker_count = workers;
    const i2d_replay_id replay = i2d_replay_open(bytes, size, &runtime);
    free(bytes);
    if (replay.bits == 0) {
        fprintf(stderr, "%s\n", i2d_last_error_message());
        return 2;
    }
    const int32_t total = i2d_replay_get_step_count(replay);
    i2d_replay_step(replay, total);
    if (i2d_last_status() != I2D_OK) {
        fprintf(stderr, "%s\n", i2d_last_error_message());
        i2d_replay_close(replay);
        return 2;
    }
    const int32_t divergent = i2d_replay_get_divergent_step(replay);
    if (divergent >= 0) {
        printf("%s: diverges at step %d of %d (the first step whose hash differs from the recording's)\n", path,
               (int)divergent, (int)total);
    } else {
        printf("%s: replayed %d of %d steps with %d worker(s), every hash as recorded; final hash %016llx\n", path,
               (int)i2d_replay_get_step(replay), (int)total, workers,
               (unsigned long long)i2d_world_get_state_hash(i2d_replay_get_world(replay)));
    }
    i2d_replay_close(replay);
    return divergent >= 0 ? 1 : 0;
}

int main(int argc, char** argv) {
    if (argc == 3 && strcmp(argv[1], "--record") == 0) {
        return record_session(argv[2]);
    }
    if (argc == 2 || (argc == 4 && strcmp(argv[2], "--workers") == 0)) {
        return replay_file(argv[1], argc == 4 ? atoi(argv[3]) : 1);
    }
    fprintf(stderr, "usage: %s FILE [--workers N] | --record FILE\n", argv[0]);
    return 2;
}
