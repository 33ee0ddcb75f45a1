// SPDX-License-Identifier: MIT
// Compiled as pedantic C++ so that a header change that breaks C++ users fails the build.
#include <impulse2d/impulse2d.h>

extern "C" int i2d_header_cpp_check(void);
extern "C" int i2d_header_cpp_check(void) {
    i2d_world_id id = I2D_NULL_WORLD_ID;
    return I2D_IS_NULL(id) ? 0 : 1;
}
