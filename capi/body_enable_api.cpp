// SPDX-License-Identifier: MIT
// i2d_body_disable, i2d_body_enable, i2d_body_is_enabled: taking a body out of the world
// and bringing it back (the core's rules are in dynamics/world/world_body_enable.cpp).
#include "boundary.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// Both directions share the prologue of every call that changes a body: a live id and a
// world that is not locked (inside a query callback) or stepping.
i2d_status set_enabled(const char* function, i2d_body_id id, bool enabled) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!call.body(id, b) || !call.unlocked(*b.world)) {
            return last_status();
        }
        b.world->set_body_enabled(b.index, enabled);
        return I2D_OK;
    });
}

}  // namespace

I2D_API i2d_status i2d_body_disable(i2d_body_id id) { return set_enabled("i2d_body_disable", id, false); }

I2D_API i2d_status i2d_body_enable(i2d_body_id id) { return set_enabled("i2d_body_enable", id, true); }

I2D_API bool i2d_body_is_enabled(i2d_body_id id) {
    return guarded("i2d_body_is_enabled", false, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) && b.world->is_enabled(b.index);
    });
}
