/* SPDX-License-Identifier: MIT */
/* The README's example: a ball dropped on the ground, and a refused NaN. */
#include <impulse2d/impulse2d.h>
#include <math.h>
#include <stdio.h>

int main(void) {
    i2d_world_def world_def = i2d_default_world_def();   /* gravity (0, -10) */
    i2d_world_id world = i2d_world_create(&world_def);

    i2d_body_def ground_def = i2d_default_body_def();    /* static */
    ground_def.position = (i2d_vec2){0.0f, -1.0f};
    i2d_body_id ground = i2d_body_create(world, &ground_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_shape_create_box(ground, &shape_def, 50.0f, 1.0f); /* top face at y = 0 */

    i2d_body_def ball_def = i2d_default_body_def();
    ball_def.type = I2D_BODY_DYNAMIC;
    ball_def.position = (i2d_vec2){0.0f, 4.0f};
    i2d_body_id ball = i2d_body_create(world, &ball_def);
    shape_def.restitution = 0.5f;
    i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    i2d_shape_create_circle(ball, &shape_def, &circle);

    for (int i = 0; i < 120; ++i) {
        i2d_world_step(world, 1.0f / 60.0f, 4);            /* 60 Hz, 4 substeps */
    }
    i2d_vec2 p = i2d_body_get_position(ball);
    printf("ball at (%.2f, %.2f)\n", p.x, p.y);

    if (i2d_body_set_linear_velocity(ball, (i2d_vec2){NAN, 0.0f}) != I2D_OK) {
        printf("refused: %s\n", i2d_last_error_message()); /* "...: velocity.x is NaN" */
    }
    i2d_world_destroy(world);                              /* frees everything in it */
    return 0;
}
