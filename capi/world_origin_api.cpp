// SPDX-License-Identifier: MIT
// i2d_world_shift_origin: the checks of a new origin, then the world's shift.
#include <cmath>

#include "boundary.hpp"
#include "convert.hpp"
#include "limits.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

bool within_limit(Vec2 p) { return std::fabs(p.x) <= max_coordinate && std::fabs(p.y) <= max_coordinate; }

bool fail_beyond(Call& call, Vec2 origin, const char* what, int32_t index, Vec2 moved) {
    return call.fail(I2D_ERR_INVALID_ARGUMENT,
                     "new_origin (%g, %g) would put %s %d at (%g, %g), beyond %g m from the origin", double(origin.x),
                     double(origin.y), what, int(index), double(moved.x), double(moved.y), double(max_coordinate));
}

// Seen from the new origin, every position the world keeps must stay where a caller could
// have put it (within max_coordinate): beyond, a snapshot of the world would be refused
// and products of coordinates come near float overflow.
bool keeps_positions_in_range(Call& call, const World& world, Vec2 origin) {
    const Pool<Body>& bodies = world.bodies();
    for (int32_t i = 0; i < bodies.capacity(); ++i) {
        if (!bodies.is_live(i)) {
            continue;
        }
        const Body& b = bodies[i];
        for (const Vec2 p : {b.transform.p, b.center, b.center0}) {
            if (!within_limit(p - origin)) {
                return fail_beyond(call, origin, "body", i, p - origin);
            }
        }
    }
    const Pool<Joint>& joints = world.joints();
    for (int32_t i = 0; i < joints.capacity(); ++i) {
        if (joints.is_live(i) && joints[i].def.type == JointType::mouse) {
            const Vec2 moved = joints[i].def.mouse.target - origin;
            if (!within_limit(moved)) {
                return fail_beyond(call, origin, "the target of mouse joint", i, moved);
            }
        }
    }
    return true;
}

}  // namespace

I2D_API i2d_status i2d_world_shift_origin(i2d_world_id id, i2d_vec2 new_origin) {
    return guarded("i2d_world_shift_origin", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w) || !call.unlocked(*w.world) || !call.coordinate(new_origin, "new_origin") ||
            !keeps_positions_in_range(call, *w.world, capi::to_core(new_origin))) {
            return last_status();
        }
        w.world->shift_origin(capi::to_core(new_origin));
        return I2D_OK;
    });
}
