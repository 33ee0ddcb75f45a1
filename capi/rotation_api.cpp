// SPDX-License-Identifier: MIT
// i2d_make_rot, i2d_rot_get_angle: rotations from and to angles.
#include "boundary.hpp"
#include "convert.hpp"

using namespace i2d;
using namespace i2d::capi;

I2D_API i2d_rot i2d_make_rot(float angle) {
    return guarded("i2d_make_rot", i2d_rot{1, 0}, [&](Call& call) {
        return call.finite(angle, "angle") ? to_public(make_rot(angle)) : i2d_rot{1, 0};
    });
}

I2D_API float i2d_rot_get_angle(i2d_rot rotation) {
    return guarded("i2d_rot_get_angle", 0.0f, [&](Call& call) {
        if (!call.finite(rotation.c, "rotation.c") || !call.finite(rotation.s, "rotation.s")) {
            return 0.0f;
        }
        return get_angle(capi::to_core(rotation));
    });
}
