// SPDX-License-Identifier: MIT
// i2d_world_explode: the blast's checks, then the world's explode (world_explode.cpp).
#include "boundary.hpp"
#include "convert.hpp"
#include "limits.hpp"

using namespace i2d;
using namespace i2d::capi;

I2D_API i2d_explosion_def i2d_default_explosion_def(void) {
    set_ok();
    const ExplosionDef core;
    return i2d_explosion_def{core.mask_bits, to_public(core.position), core.radius, core.falloff,
                             core.impulse_per_length};
}

I2D_API i2d_status i2d_world_explode(i2d_world_id world, const i2d_explosion_def* def) {
    return guarded("i2d_world_explode", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!mutable_world(call, world, w) || !call.not_null(def, "def") || !call.coordinate(def->position, "position") ||
            !call.in_range(def->radius, 0.0f, max_explosion_reach, "radius") ||
            !call.in_range(def->falloff, 0.0f, max_explosion_reach, "falloff") ||
            !call.in_range(def->impulse_per_length, -max_explosion_impulse_per_length,
                           max_explosion_impulse_per_length, "impulse_per_length")) {
            return last_status();
        }
        w.world->explode(ExplosionDef{def->mask_bits, capi::to_core(def->position), def->radius, def->falloff,
                                      def->impulse_per_length});
        return I2D_OK;
    });
}
