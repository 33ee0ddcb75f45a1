// SPDX-License-Identifier: MIT
// i2d_joint_create_* and i2d_joint_*: creating and destroying joints, what every kind
// shares (bodies, anchors, collide_connected, thresholds, reaction, user data), the
// world's joint events and count. Per-kind settings are in joint_settings_api.cpp.
#include <cstddef>
#include <cstdio>

#include "boundary.hpp"
#include "convert.hpp"
#include "joint_rules.hpp"
#include "loaded_values.hpp"

using namespace i2d;
using namespace i2d::capi;
using namespace i2d::capi::joint_rules;

// The core's event records are the public structs, byte for byte (event_api.cpp).
static_assert(sizeof(JointEvent) == sizeof(i2d_joint_event), "event layout");
static_assert(offsetof(JointEvent, user_data) == offsetof(i2d_joint_event, user_data), "event layout");
static_assert(sizeof(i2d_joint_id) == sizeof(uint64_t), "a joint id is its bits");

namespace {

// The bodies of a def: live, of `world`, two different ones, and one that moves under
// the joint (dynamic: a joint between bodies that cannot respond would do nothing, and
// its solver would divide by zero mass). A mouse joint moves body_b alone.
bool check_bodies(Call& call, const WorldRef& w, const i2d_joint_base& base, const char* def_name, bool mouse,
                  JointDef& core) {
    char field_a[64], field_b[64];
    std::snprintf(field_a, sizeof field_a, "%s: body_a", def_name);
    std::snprintf(field_b, sizeof field_b, "%s: body_b", def_name);
    BodyRef a, b;
    if (!call.body(base.body_a, a, field_a) || !call.body(base.body_b, b, field_b)) {
        return false;
    }
    if (a.world != w.world || b.world != w.world) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s belongs to another world than the one given",
                         a.world != w.world ? field_a : field_b);
    }
    if (a.index == b.index) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s: body_a and body_b are the same body; a joint needs two",
                         def_name);
    }
    const bool a_dynamic = a.body().type == BodyType::dynamic;
    const bool b_dynamic = b.body().type == BodyType::dynamic;
    if (mouse && !b_dynamic) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s is not dynamic; a mouse joint drags a dynamic body",
                         field_b);
    }
    if (!a_dynamic && !b_dynamic) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "%s: neither body_a nor body_b is dynamic; a joint needs one that it can move", def_name);
    }
    core.body_a = a.index;
    core.body_b = b.index;
    return true;
}

// What every def shares besides its bodies.
bool check_base(Call& call, const i2d_joint_base& base, const char* def_name, JointDef& core) {
    char anchor_a[64], anchor_b[64], force[64], torque[64];
    std::snprintf(anchor_a, sizeof anchor_a, "%s: local_anchor_a", def_name);
    std::snprintf(anchor_b, sizeof anchor_b, "%s: local_anchor_b", def_name);
    std::snprintf(force, sizeof force, "%s: force_threshold", def_name);
    std::snprintf(torque, sizeof torque, "%s: torque_threshold", def_name);
    if (!call.local_point(base.local_anchor_a, anchor_a) || !call.local_point(base.local_anchor_b, anchor_b) ||
        !NonNegative::check(call, base.force_threshold, force) ||
        !NonNegative::check(call, base.torque_threshold, torque)) {
        return false;
    }
    core.local_anchor_a = capi::to_core(base.local_anchor_a);
    core.local_anchor_b = capi::to_core(base.local_anchor_b);
    core.collide_connected = base.collide_connected;
    core.force_threshold = base.force_threshold;
    core.torque_threshold = base.torque_threshold;
    core.user_data = base.user_data;
    return true;
}

// Per kind: every field checked by its rule, then stored; then the cross-field checks.
#define I2D_CHECK_FIELD(kind, field, Rule) \
    &&joint_rules::Rule::check(call, def.field, #kind "_joint_def: " #field)
#define I2D_STORE_FIELD(kind, field, Rule) core.kind.field = joint_rules::Rule::store(def.field);
#define I2D_JOINT_DEF_CHECK(kind, FIELDS)                                                        \
    bool check_settings(Call& call, const i2d_##kind##_joint_def& def, JointDef& core) {         \
        static_cast<void>(def); /* a filter joint has no settings */                            \
        core.type = JointType::kind;                                                             \
        if (!(true FIELDS(I2D_CHECK_FIELD))) {                                                   \
            return false;                                                                        \
        }                                                                                        \
        FIELDS(I2D_STORE_FIELD)                                                                  \
        return ordered_bounds(call, core, #kind "_joint_def: ");                                 \
    }

I2D_JOINT_DEF_CHECK(revolute, I2D_REVOLUTE_FIELDS)
I2D_JOINT_DEF_CHECK(prismatic, I2D_PRISMATIC_FIELDS)
I2D_JOINT_DEF_CHECK(distance, I2D_DISTANCE_FIELDS)
I2D_JOINT_DEF_CHECK(weld, I2D_WELD_FIELDS)
I2D_JOINT_DEF_CHECK(wheel, I2D_WHEEL_FIELDS)
I2D_JOINT_DEF_CHECK(motor, I2D_MOTOR_FIELDS)
I2D_JOINT_DEF_CHECK(mouse, I2D_MOUSE_FIELDS)
I2D_JOINT_DEF_CHECK(filter, I2D_FILTER_FIELDS)

#undef I2D_JOINT_DEF_CHECK
#undef I2D_STORE_FIELD
#undef I2D_CHECK_FIELD

// A loaded joint's settings: each field as its def's rule checks it and in the form the
// rule stores it, then the cross-field checks.
#define I2D_CHECK_LOADED_FIELD(kind, field, Rule)                                                          \
    &&(joint_rules::Rule::check(call, joint_rules::Rule::out(core.kind.field), name(#field)) &&              \
       (joint_rules::stored_form<joint_rules::Rule>(core.kind.field) ||                                    \
        call.fail(I2D_ERR_INVALID_ARGUMENT, "joint %d: " #field " is not as a joint stores it", int(index))))
#define I2D_LOADED_SETTINGS_CHECK(kind, FIELDS)                                        \
    case JointType::kind:                                                              \
        if (!(true FIELDS(I2D_CHECK_LOADED_FIELD))) {                                  \
            return false;                                                              \
        }                                                                              \
        break;

template <class Name>
bool valid_loaded_settings(Call& call, const JointDef& core, int32_t index, Name name) {
    switch (core.type) {
        I2D_LOADED_SETTINGS_CHECK(revolute, I2D_REVOLUTE_FIELDS)
        I2D_LOADED_SETTINGS_CHECK(prismatic, I2D_PRISMATIC_FIELDS)
        I2D_LOADED_SETTINGS_CHECK(distance, I2D_DISTANCE_FIELDS)
        I2D_LOADED_SETTINGS_CHECK(weld, I2D_WELD_FIELDS)
        I2D_LOADED_SETTINGS_CHECK(wheel, I2D_WHEEL_FIELDS)
        I2D_LOADED_SETTINGS_CHECK(motor, I2D_MOTOR_FIELDS)
        I2D_LOADED_SETTINGS_CHECK(mouse, I2D_MOUSE_FIELDS)
        case JointType::filter:
            break;
        default:
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "joint %d: its kind is unknown", int(index));
    }
    return ordered_bounds(call, core, name(""));
}

#undef I2D_LOADED_SETTINGS_CHECK
#undef I2D_CHECK_LOADED_FIELD

// The order of every create: the world, not locked, the def there and initialised, its
// bodies, its base, its settings; only then the core, so a refusal changes nothing.
template <class Def>
i2d_joint_id create(Call& call, i2d_world_id world_id, const Def* def, const char* def_name, bool mouse) {
    WorldRef w;
    JointDef core;
    if (!call.world(world_id, w) || !call.unlocked(*w.world) || !call.not_null(def, def_name) ||
        !call.cookie(def->internal_cookie, def_name) || !check_bodies(call, w, def->base, def_name, mouse, core) ||
        !check_base(call, def->base, def_name, core) || !check_settings(call, *def, core)) {
        return I2D_NULL_JOINT_ID;
    }
    const int32_t index = w.world->create_joint(core);
    if (index == null_index) {
        call.fail(I2D_ERR_CAPACITY, "the world holds %d joints, the most it can", Pool<Joint>::max_slots);
        return I2D_NULL_JOINT_ID;
    }
    return make_joint_id(w.id, index, w.world->joints().generation(index));
}

// The common prologue of calls that change a joint: a live id and an unlocked world.
bool mutable_joint(Call& call, i2d_joint_id id, JointRef& j) { return call.joint(id, j) && call.unlocked(*j.world); }

// A change to the shared part of a joint's def: checked on a copy, so that a refusal
// leaves the joint as it was, then stored and the world told (which wakes the bodies).
template <class Change>
i2d_status change_joint(const char* function, i2d_joint_id id, Change&& change) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        JointRef j;
        if (!mutable_joint(call, id, j)) {
            return last_status();
        }
        JointDef def = j.joint().def;
        if (!change(call, def)) {
            return last_status();
        }
        j.world->set_joint_def(j.index, def);
        return I2D_OK;
    });
}

template <class R, class Read>
R read_joint(const char* function, i2d_joint_id id, R on_failure, Read&& read) {
    return guarded(function, on_failure, [&](Call& call) -> R {
        JointRef j;
        return call.joint(id, j) ? read(j) : on_failure;
    });
}

}  // namespace

namespace i2d::capi {

// A loaded joint as check_base and its kind's settings would take it. Its bodies' types
// are not checked: i2d_body_set_type may since have made both static.
bool valid_loaded_joint(Call& call, const World& world, int32_t index) {
    return valid_joint_values(call, world.joints()[index].def, index);
}

bool valid_recorded_joint(Call& call, const World& world, const JointDef& def) {
    const Pool<Body>& bodies = world.bodies();
    if (!bodies.is_live(def.body_a) || !bodies.is_live(def.body_b) || def.body_a == def.body_b) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "joint: its bodies are not two live bodies");
    }
    const bool a_dynamic = bodies[def.body_a].type == BodyType::dynamic;
    const bool b_dynamic = bodies[def.body_b].type == BodyType::dynamic;
    if (def.type == JointType::mouse ? !b_dynamic : !(a_dynamic || b_dynamic)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "joint: it has no dynamic body to move");
    }
    return valid_joint_values(call, def, -1);
}

bool valid_joint_values(Call& call, const JointDef& core, int32_t index) {
    // Every kind's angles, not only this kind's, are stored wound (the joint set checks).
    if (!angles_wound(core)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "joint %d: an angle is not wound into (-pi, pi]", int(index));
    }
    return checked_with_names("joint", index, [&](auto name) {
        return call.local_point(to_public(core.local_anchor_a), name("local_anchor_a")) &&
               call.local_point(to_public(core.local_anchor_b), name("local_anchor_b")) &&
               NonNegative::check(call, core.force_threshold, name("force_threshold")) &&
               NonNegative::check(call, core.torque_threshold, name("torque_threshold")) &&
               valid_loaded_settings(call, core, index, name);
    });
}

}  // namespace i2d::capi

#define I2D_JOINT_CREATE(kind, is_mouse)                                                                        \
    I2D_API i2d_joint_id i2d_joint_create_##kind(i2d_world_id world, const i2d_##kind##_joint_def* def) {      \
        return guarded("i2d_joint_create_" #kind, I2D_NULL_JOINT_ID,                                            \
                       [&](Call& call) { return create(call, world, def, #kind "_joint_def", is_mouse); });    \
    }

I2D_JOINT_CREATE(revolute, false)
I2D_JOINT_CREATE(prismatic, false)
I2D_JOINT_CREATE(distance, false)
I2D_JOINT_CREATE(weld, false)
I2D_JOINT_CREATE(wheel, false)
I2D_JOINT_CREATE(motor, false)
I2D_JOINT_CREATE(mouse, true)
I2D_JOINT_CREATE(filter, false)

#undef I2D_JOINT_CREATE

I2D_API i2d_status i2d_joint_destroy(i2d_joint_id id) {
    return guarded("i2d_joint_destroy", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        JointRef j;
        if (!mutable_joint(call, id, j)) {
            return last_status();
        }
        j.world->destroy_joint(j.index);
        return I2D_OK;
    });
}

I2D_API bool i2d_joint_is_valid(i2d_joint_id id) {
    return guarded("i2d_joint_is_valid", false, [&](Call& call) {
        JointRef j;
        return call.joint(id, j);
    });
}

I2D_API i2d_joint_type i2d_joint_get_type(i2d_joint_id id) {
    return read_joint("i2d_joint_get_type", id, I2D_JOINT_DISTANCE,
                      [](const JointRef& j) { return static_cast<i2d_joint_type>(j.joint().def.type); });
}

I2D_API i2d_world_id i2d_joint_get_world(i2d_joint_id id) {
    return read_joint("i2d_joint_get_world", id, I2D_NULL_WORLD_ID,
                      [](const JointRef& j) { return make_world_id(j.id); });
}

I2D_API i2d_body_id i2d_joint_get_body_a(i2d_joint_id id) {
    return read_joint("i2d_joint_get_body_a", id, I2D_NULL_BODY_ID, [](const JointRef& j) {
        const int32_t body = j.joint().def.body_a;
        return make_body_id(j.id, body, j.world->bodies().generation(body));
    });
}

I2D_API i2d_body_id i2d_joint_get_body_b(i2d_joint_id id) {
    return read_joint("i2d_joint_get_body_b", id, I2D_NULL_BODY_ID, [](const JointRef& j) {
        const int32_t body = j.joint().def.body_b;
        return make_body_id(j.id, body, j.world->bodies().generation(body));
    });
}

I2D_API i2d_vec2 i2d_joint_get_local_anchor_a(i2d_joint_id id) {
    return read_joint("i2d_joint_get_local_anchor_a", id, i2d_vec2{0, 0},
                      [](const JointRef& j) { return to_public(j.joint().def.local_anchor_a); });
}

I2D_API i2d_vec2 i2d_joint_get_local_anchor_b(i2d_joint_id id) {
    return read_joint("i2d_joint_get_local_anchor_b", id, i2d_vec2{0, 0},
                      [](const JointRef& j) { return to_public(j.joint().def.local_anchor_b); });
}

I2D_API i2d_status i2d_joint_set_local_anchor_a(i2d_joint_id id, i2d_vec2 anchor) {
    return change_joint("i2d_joint_set_local_anchor_a", id, [&](Call& call, JointDef& def) {
        def.local_anchor_a = capi::to_core(anchor);
        return call.local_point(anchor, "local_anchor_a");
    });
}

I2D_API i2d_status i2d_joint_set_local_anchor_b(i2d_joint_id id, i2d_vec2 anchor) {
    return change_joint("i2d_joint_set_local_anchor_b", id, [&](Call& call, JointDef& def) {
        def.local_anchor_b = capi::to_core(anchor);
        return call.local_point(anchor, "local_anchor_b");
    });
}

I2D_API bool i2d_joint_get_collide_connected(i2d_joint_id id) {
    return read_joint("i2d_joint_get_collide_connected", id, false,
                      [](const JointRef& j) { return j.joint().def.collide_connected; });
}

I2D_API i2d_status i2d_joint_set_collide_connected(i2d_joint_id id, bool collide) {
    return change_joint("i2d_joint_set_collide_connected", id, [&](Call&, JointDef& def) {
        def.collide_connected = collide;
        return true;
    });
}

I2D_API float i2d_joint_get_force_threshold(i2d_joint_id id) {
    return read_joint("i2d_joint_get_force_threshold", id, 0.0f,
                      [](const JointRef& j) { return j.joint().def.force_threshold; });
}

I2D_API i2d_status i2d_joint_set_force_threshold(i2d_joint_id id, float threshold) {
    return change_joint("i2d_joint_set_force_threshold", id, [&](Call& call, JointDef& def) {
        def.force_threshold = threshold;
        return NonNegative::check(call, threshold, "force_threshold");
    });
}

I2D_API float i2d_joint_get_torque_threshold(i2d_joint_id id) {
    return read_joint("i2d_joint_get_torque_threshold", id, 0.0f,
                      [](const JointRef& j) { return j.joint().def.torque_threshold; });
}

I2D_API i2d_status i2d_joint_set_torque_threshold(i2d_joint_id id, float threshold) {
    return change_joint("i2d_joint_set_torque_threshold", id, [&](Call& call, JointDef& def) {
        def.torque_threshold = threshold;
        return NonNegative::check(call, threshold, "torque_threshold");
    });
}

I2D_API i2d_vec2 i2d_joint_get_reaction_force(i2d_joint_id id) {
    return read_joint("i2d_joint_get_reaction_force", id, i2d_vec2{0, 0},
                      [](const JointRef& j) { return to_public(j.joint().reaction_force); });
}

I2D_API float i2d_joint_get_reaction_torque(i2d_joint_id id) {
    return read_joint("i2d_joint_get_reaction_torque", id, 0.0f,
                      [](const JointRef& j) { return j.joint().reaction_torque; });
}

I2D_API void* i2d_joint_get_user_data(i2d_joint_id id) {
    return read_joint("i2d_joint_get_user_data", id, static_cast<void*>(nullptr),
                      [](const JointRef& j) { return j.joint().def.user_data; });
}

// User data does not touch the simulation, so it may be set from inside a callback.
I2D_API i2d_status i2d_joint_set_user_data(i2d_joint_id id, void* user_data) {
    return guarded("i2d_joint_set_user_data", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        JointRef j;
        if (!call.joint(id, j)) {
            return last_status();
        }
        j.world->set_joint_user_data(j.index, user_data);
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_joint_wake_bodies(i2d_joint_id id) {
    return guarded("i2d_joint_wake_bodies", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        JointRef j;
        if (!mutable_joint(call, id, j)) {
            return last_status();
        }
        j.world->wake_body(j.joint().def.body_a);
        j.world->wake_body(j.joint().def.body_b);
        return I2D_OK;
    });
}

I2D_API i2d_joint_events i2d_world_get_joint_events(i2d_world_id id) {
    return guarded("i2d_world_get_joint_events", i2d_joint_events{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return i2d_joint_events{};
        }
        const std::vector<JointEvent>& events = w.world->joint_events();
        const i2d_joint_event* first =
            events.empty() ? nullptr : reinterpret_cast<const i2d_joint_event*>(events.data());
        return i2d_joint_events{first, int32_t(events.size())};
    });
}

I2D_API int32_t i2d_world_get_joint_count(i2d_world_id id) {
    return guarded("i2d_world_get_joint_count", int32_t(0), [&](Call& call) {
        WorldRef w;
        return call.world(id, w) ? w.world->joints().count() : int32_t(0);
    });
}
