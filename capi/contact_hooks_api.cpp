// SPDX-License-Identifier: MIT
// The contact hooks (toolkit.h): the world's custom filter and pre-solve callbacks, and a
// shape's opt-in to pre-solve after creation.
#include <cstring>

#include "boundary.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// The trampolines the core calls (contact_hooks.hpp): the host's function back in its own
// type, the ids and manifold in the C API's.
bool call_custom_filter(ContactHooks::HostFn fn, void* context, uint64_t shape_a, uint64_t shape_b) {
    return reinterpret_cast<i2d_custom_filter_fn*>(fn)(i2d_shape_id{shape_a}, i2d_shape_id{shape_b}, context);
}

bool call_pre_solve(ContactHooks::HostFn fn, void* context, uint64_t shape_a, uint64_t shape_b,
                    const Manifold& manifold) {
    static_assert(sizeof(Manifold) == sizeof(i2d_manifold), "the core's manifold is the C API's");
    i2d_manifold shown;
    std::memcpy(&shown, &manifold, sizeof shown);
    return reinterpret_cast<i2d_pre_solve_fn*>(fn)(i2d_shape_id{shape_a}, i2d_shape_id{shape_b}, &shown, context);
}

}  // namespace

I2D_API i2d_status i2d_world_set_custom_filter_callback(i2d_world_id world, i2d_custom_filter_fn* fn,
                                                        void* context) {
    return guarded("i2d_world_set_custom_filter_callback", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!mutable_world(call, world, w)) {
            return last_status();
        }
        ContactHooks::CustomFilter hook;
        if (fn != nullptr) {
            hook = {call_custom_filter, reinterpret_cast<ContactHooks::HostFn>(fn), context};
        }
        w.world->set_custom_filter(hook);
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_set_pre_solve_callback(i2d_world_id world, i2d_pre_solve_fn* fn, void* context) {
    return guarded("i2d_world_set_pre_solve_callback", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!mutable_world(call, world, w)) {
            return last_status();
        }
        ContactHooks::PreSolve hook;
        if (fn != nullptr) {
            hook = {call_pre_solve, reinterpret_cast<ContactHooks::HostFn>(fn), context};
        }
        w.world->set_pre_solve(hook);
        return I2D_OK;
    });
}
