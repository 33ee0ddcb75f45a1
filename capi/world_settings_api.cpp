// SPDX-License-Identifier: MIT
// i2d_world_*: the world's settings after creation, and its user data.
#include "boundary.hpp"
#include "convert.hpp"
#include "world_def.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// The world's settings as a def, `edit`ed, then checked by the rules a def is created
// under (so a setting's range is the def's, in the world's units) and given to the world.
template <class Edit>
i2d_status change_settings(const char* function, i2d_world_id id, Edit&& edit) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!mutable_world(call, id, w)) {
            return last_status();
        }
        i2d_world_def def = to_public(w.world->settings());
        edit(def);
        if (!validate_world_def(call, &def)) {
            return last_status();
        }
        w.world->set_settings(to_core(def));
        return I2D_OK;
    });
}

}  // namespace

I2D_API i2d_status i2d_world_set_user_data(i2d_world_id id, void* user_data) {
    return guarded("i2d_world_set_user_data", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return last_status();
        }
        w.world->set_user_data(user_data);
        return I2D_OK;
    });
}

I2D_API void* i2d_world_get_user_data(i2d_world_id id) {
    return guarded("i2d_world_get_user_data", static_cast<void*>(nullptr), [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? w.world->user_data() : nullptr;
    });
}

I2D_API i2d_world_def i2d_world_get_settings(i2d_world_id id) {
    return guarded("i2d_world_get_settings", i2d_world_def{}, [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? to_public(w.world->settings()) : i2d_world_def{};
    });
}

I2D_API i2d_status i2d_world_enable_sleeping(i2d_world_id id, bool flag) {
    return change_settings("i2d_world_enable_sleeping", id, [&](i2d_world_def& def) { def.enable_sleep = flag; });
}

I2D_API i2d_status i2d_world_enable_continuous(i2d_world_id id, bool flag) {
    return change_settings("i2d_world_enable_continuous", id,
                           [&](i2d_world_def& def) { def.enable_continuous = flag; });
}

I2D_API i2d_status i2d_world_enable_impact_chains(i2d_world_id id, bool flag) {
    return change_settings("i2d_world_enable_impact_chains", id,
                           [&](i2d_world_def& def) { def.enable_impact_chains = flag; });
}

I2D_API i2d_status i2d_world_set_contact_tuning(i2d_world_id id, float hertz, float damping_ratio,
                                                float push_max_speed) {
    return change_settings("i2d_world_set_contact_tuning", id, [&](i2d_world_def& def) {
        def.contact_hertz = hertz;
        def.contact_damping_ratio = damping_ratio;
        def.contact_push_max_speed = push_max_speed;
    });
}

I2D_API i2d_status i2d_world_set_joint_tuning(i2d_world_id id, float hertz, float damping_ratio) {
    return change_settings("i2d_world_set_joint_tuning", id, [&](i2d_world_def& def) {
        def.joint_hertz = hertz;
        def.joint_damping_ratio = damping_ratio;
    });
}

I2D_API i2d_status i2d_world_set_restitution_threshold(i2d_world_id id, float speed) {
    return change_settings("i2d_world_set_restitution_threshold", id,
                           [&](i2d_world_def& def) { def.restitution_threshold = speed; });
}

I2D_API i2d_status i2d_world_set_hit_event_threshold(i2d_world_id id, float speed) {
    return change_settings("i2d_world_set_hit_event_threshold", id,
                           [&](i2d_world_def& def) { def.hit_event_threshold = speed; });
}
