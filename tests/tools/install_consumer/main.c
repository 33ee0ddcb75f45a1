/* SPDX-License-Identifier: MIT */
/* Uses the installed headers and library: the header and the loaded library must agree. */
#include <impulse2d/impulse2d.h>
#include <stdio.h>

int main(void) {
    if (i2d_version() != I2D_VERSION) {
        fprintf(stderr, "header version %u, library version %u\n", (unsigned)I2D_VERSION, (unsigned)i2d_version());
        return 1;
    }
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&def);
    if (!i2d_world_is_valid(world) || i2d_world_step(world, 1.0f / 60.0f, 4) != I2D_OK) {
        fprintf(stderr, "%s\n", i2d_last_error_message());
        return 1;
    }
    i2d_world_destroy(world);
    printf("installed impulse2d %u.%u.%u works\n", I2D_VERSION_MAJOR, I2D_VERSION_MINOR, I2D_VERSION_PATCH);
    return 0;
}
