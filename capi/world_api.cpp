// SPDX-License-Identifier: MIT
// i2d_world_*: create, destroy, step, gravity, counters.
#include <cstring>
#include <memory>
#include <type_traits>

#include "boundary.hpp"
#include "convert.hpp"
#include "limits.hpp"
#include "registry.hpp"
#include "world_def.hpp"

using namespace i2d;
using namespace i2d::capi;

I2D_API i2d_world_id i2d_world_create(const i2d_world_def* def) {
    return guarded("i2d_world_create", I2D_NULL_WORLD_ID, [&](Call& call) -> i2d_world_id {
        if (!validate_world_def(call, def)) {
            return I2D_NULL_WORLD_ID;
        }
        return register_new_world(call, std::make_unique<World>(to_core(*def)));
    });
}

I2D_API i2d_status i2d_world_destroy(i2d_world_id id) {
    return guarded("i2d_world_destroy", I2D_ERR_INVALID_HANDLE, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w) || !call.unlocked(*w.world)) {
            return last_status();
        }
        release_world(w.id.world_slot);
        delete w.world;
        return I2D_OK;
    });
}

I2D_API bool i2d_world_is_valid(i2d_world_id id) {
    return guarded("i2d_world_is_valid", false, [&](Call& call) {
        WorldRef w;
        return call.world(id, w);
    });
}

I2D_API i2d_status i2d_world_step(i2d_world_id id, float time_step, int32_t substep_count) {
    return guarded("i2d_world_step", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w) || !call.unlocked(*w.world) || !valid_step(call, time_step, substep_count)) {
            return last_status();
        }
        w.world->step(time_step, substep_count);
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_set_gravity(i2d_world_id id, i2d_vec2 gravity) {
    return guarded("i2d_world_set_gravity", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w) || !call.unlocked(*w.world) || !call.finite(gravity, "gravity")) {
            return last_status();
        }
        w.world->set_gravity(capi::to_core(gravity));
        return I2D_OK;
    });
}

I2D_API i2d_vec2 i2d_world_get_gravity(i2d_world_id id) {
    return guarded("i2d_world_get_gravity", i2d_vec2{0, 0}, [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? to_public(w.world->settings().gravity) : i2d_vec2{0, 0};
    });
}

I2D_API i2d_world_counters i2d_world_get_counters(i2d_world_id id) {
    return guarded("i2d_world_get_counters", i2d_world_counters{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return i2d_world_counters{};
        }
        const WorldCounters c = w.world->counters();
        return i2d_world_counters{c.body_count,
                                  c.shape_count,
                                  c.contact_count,
                                  c.pair_count,
                                  c.tree_heights[int32_t(ProxyKind::static_proxy)],
                                  c.tree_heights[int32_t(ProxyKind::kinematic_proxy)],
                                  c.tree_heights[int32_t(ProxyKind::dynamic_proxy)],
                                  c.awake_body_count,
                                  c.sleeping_island_count};
    });
}

I2D_API i2d_profile i2d_world_get_profile(i2d_world_id id) {
    return guarded("i2d_world_get_profile", i2d_profile{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return i2d_profile{};
        }
        const StepProfile& p = w.world->profile();
        return i2d_profile{p.step, p.pairs, p.collide, p.solve, p.update_bounds, p.sleep, p.events, p.continuous};
    });
}

I2D_API i2d_status i2d_world_rebuild_static_tree(i2d_world_id id) {
    return guarded("i2d_world_rebuild_static_tree", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w) || !call.unlocked(*w.world)) {
            return last_status();
        }
        w.world->rebuild_static_tree();
        return I2D_OK;
    });
}

I2D_API uint64_t i2d_world_get_state_hash(i2d_world_id id) {
    return guarded("i2d_world_get_state_hash", uint64_t(0), [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? w.world->state_hash() : uint64_t(0);
    });
}

I2D_API int32_t i2d_world_get_worker_count(i2d_world_id id) {
    return guarded("i2d_world_get_worker_count", int32_t(0), [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? w.world->worker_count() : int32_t(0);
    });
}

I2D_API i2d_simd_path i2d_world_get_simd_path(i2d_world_id id) {
    return guarded("i2d_world_get_simd_path", I2D_SIMD_SCALAR, [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? static_cast<i2d_simd_path>(w.world->simd_path()) : I2D_SIMD_SCALAR;
    });
}

I2D_API bool i2d_simd_path_supported(i2d_simd_path path) {
    return guarded("i2d_simd_path_supported", false, [&](Call&) {
        int32_t value = 0;
        std::memcpy(&value, &path, sizeof value);
        return value >= 0 && value < static_cast<int32_t>(SimdPath::count) && simd_path_supported(SimdPath(value));
    });
}
