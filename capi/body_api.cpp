// SPDX-License-Identifier: MIT
// i2d_body_*: create, destroy, transform, velocity, mass, forces, user data, shapes.
#include <cfloat>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "boundary.hpp"
#include "convert.hpp"
#include "geometry_checks.hpp"
#include "limits.hpp"
#include "loaded_values.hpp"
#include "dynamics/body/body_rules.hpp"
#include "dynamics/constants.hpp"
#include "math/math.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// Chains are one-sided and massless: a body that holds one stays static or kinematic.
bool has_chain(const World& world, const Body& body) {
    for (int32_t s = body.head_shape; s != null_index; s = world.shapes()[s].next_in_body) {
        if (world.shapes()[s].chain != null_index) {
            return true;
        }
    }
    return false;
}

// A C caller can store any integer in the enum; in C++ merely loading an out-of-range
// enum value is undefined, so read the raw bytes.
bool valid_body_type(Call& call, const i2d_body_type* value, const char* what) {
    std::underlying_type_t<i2d_body_type> type = 0;
    std::memcpy(&type, value, sizeof type);
    if (type != I2D_BODY_STATIC && type != I2D_BODY_KINEMATIC && type != I2D_BODY_DYNAMIC) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s %lld is not an i2d_body_type", what,
                         static_cast<long long>(type));
    }
    return true;
}

bool validate_body_def(Call& call, const i2d_body_def* def) {
    if (!call.not_null(def, "body def") || !call.cookie(def->internal_cookie, "body_def") ||
        !valid_body_type(call, &def->type, "body def: type")) {
        return false;
    }
    Rot rotation;
    if (!call.coordinate(def->position, "body def: position") ||
        !normalized_rotation(call, def->rotation, "body def: rotation", rotation) ||
        !call.finite(def->linear_velocity, "body def: linear_velocity") ||
        !call.finite(def->angular_velocity, "body def: angular_velocity")) {
        return false;
    }
    return call.in_range(def->linear_damping, 0.0f, FLT_MAX, "body def: linear_damping") &&
           call.in_range(def->angular_damping, 0.0f, FLT_MAX, "body def: angular_damping") &&
           call.finite(def->gravity_scale, "body def: gravity_scale");
}

BodyDef to_core(const i2d_body_def& def) {
    BodyDef core;
    core.type = static_cast<BodyType>(def.type);
    core.position = capi::to_core(def.position);
    core.rotation = normalize(capi::to_core(def.rotation));  // checked to be near unit length
    core.linear_velocity = capi::to_core(def.linear_velocity);
    core.angular_velocity = def.angular_velocity;
    core.linear_damping = def.linear_damping;
    core.angular_damping = def.angular_damping;
    core.gravity_scale = def.gravity_scale;
    core.fixed_rotation = def.fixed_rotation;
    core.enable_sleep = def.enable_sleep;
    core.is_bullet = def.is_bullet;
    core.user_data = def.user_data;
    return core;
}


}  // namespace

namespace i2d::capi {

namespace {

// A mass i2d_body_set_mass_data could have set.
template <class Name>
bool valid_mass_override(Call& call, const Body& b, Name name) {
    if (b.type != BodyType::dynamic) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s: a mass set on a body that is not dynamic",
                         static_cast<const char*>(name("mass")));
    }
    return call.in_range(b.mass, FLT_MIN, max_mass, name("mass")) &&
           call.in_range(b.override_inertia, 0.0f, max_inertia, name("override_inertia")) &&
           call.local_point(to_public(b.local_center), name("local_center"));
}

// The mass, inertia, centre and extents the body's shapes (or the mass it was set) give
// it, bit for bit: no call sets them any other way.
bool mass_from_shapes(Call& call, const World& world, const Body& body, int32_t index) {
    Body expected = body;
    update_mass_from_shapes(expected, world.shapes(), world.tolerances().linear_slop);
    const bool same = expected.mass == body.mass && expected.inv_mass == body.inv_mass &&
                      expected.inertia == body.inertia && expected.inv_inertia == body.inv_inertia &&
                      expected.local_center == body.local_center && expected.max_extent == body.max_extent &&
                      expected.min_extent == body.min_extent && expected.angular_velocity == body.angular_velocity;
    if (!same) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "body %d: its mass, inertia or extents are not its shapes'",
                         static_cast<int>(index));
    }
    const Vec2 center = transform_point(body.transform, body.local_center);
    const float reach = max_of(1.0f, max_of(std::fabs(center.x), std::fabs(center.y)));
    if (!(length(center - body.center) <= loaded_center_tolerance * reach)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "body %d: its centre of mass is not where its origin puts it",
                         static_cast<int>(index));
    }
    return true;
}

}  // namespace

bool valid_loaded_body(Call& call, const World& world, int32_t index) {
    const Body& b = world.bodies()[index];
    return checked_with_names("body", index, [&](auto name) {
        Rot unused;
        if (!call.coordinate(to_public(b.transform.p), name("position")) ||
            !normalized_rotation(call, to_public(b.transform.q), name("rotation"), unused) ||
            !call.coordinate(to_public(b.center), name("center")) ||
            !call.coordinate(to_public(b.center0), name("center0")) ||
            !normalized_rotation(call, to_public(b.rotation0), name("rotation0"), unused) ||
            !call.in_range(b.linear_damping, 0.0f, FLT_MAX, name("linear_damping")) ||
            !call.in_range(b.angular_damping, 0.0f, FLT_MAX, name("angular_damping")) ||
            !call.in_range(b.sleep_time, 0.0f, FLT_MAX, name("sleep_time")) ||
            !call.in_range(b.sleep_threshold, 0.0f, max_speed_limit * world.settings().length_units_per_meter,
                           name("sleep_threshold")) ||
            (b.mass_overridden && !valid_mass_override(call, b, name)) ||
            !call.in_range(b.angular_velocity, -max_angular_speed, max_angular_speed, name("angular_velocity"))) {
            return false;
        }
        const double speed = std::hypot(double(b.linear_velocity.x), double(b.linear_velocity.y));
        if (!(speed <= double(world.settings().maximum_linear_speed) * (1.0 + loaded_speed_tolerance))) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "body %d: its speed %g m/s is above the world's maximum %g",
                             static_cast<int>(index), speed, double(world.settings().maximum_linear_speed));
        }
        if (b.type == BodyType::static_body && !(b.linear_velocity == Vec2{} && b.angular_velocity == 0.0f)) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "body %d: it is static and moves", static_cast<int>(index));
        }
        return mass_from_shapes(call, world, b, index);
    });
}

// As validate_body_def; velocities are finite as read, and the world limits them.
bool valid_recorded_body_def(Call& call, const BodyDef& def) {
    Rot unused;
    return call.coordinate(to_public(def.position), "body def: position") &&
           normalized_rotation(call, to_public(def.rotation), "body def: rotation", unused) &&
           call.in_range(def.linear_damping, 0.0f, FLT_MAX, "body def: linear_damping") &&
           call.in_range(def.angular_damping, 0.0f, FLT_MAX, "body def: angular_damping");
}

}  // namespace i2d::capi

I2D_API i2d_body_id i2d_body_create(i2d_world_id world_id, const i2d_body_def* def) {
    return guarded("i2d_body_create", I2D_NULL_BODY_ID, [&](Call& call) -> i2d_body_id {
        WorldRef w;
        if (!call.world(world_id, w) || !call.unlocked(*w.world) || !validate_body_def(call, def)) {
            return I2D_NULL_BODY_ID;
        }
        const int32_t index = w.world->create_body(to_core(*def));
        if (index == null_index) {
            call.fail(I2D_ERR_CAPACITY, "the world holds %d bodies, the most it can", Pool<Body>::max_slots);
            return I2D_NULL_BODY_ID;
        }
        return make_body_id(w.id, index, w.world->bodies().generation(index));
    });
}

I2D_API i2d_status i2d_body_destroy(i2d_body_id id) {
    return guarded("i2d_body_destroy", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b)) {
            return last_status();
        }
        b.world->destroy_body(b.index);
        return I2D_OK;
    });
}

I2D_API bool i2d_body_is_valid(i2d_body_id id) {
    return guarded("i2d_body_is_valid", false, [&](Call& call) {
        BodyRef b;
        return call.body(id, b);
    });
}

I2D_API i2d_world_id i2d_body_get_world(i2d_body_id id) {
    return guarded("i2d_body_get_world", I2D_NULL_WORLD_ID, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? make_world_id(b.id) : I2D_NULL_WORLD_ID;
    });
}

I2D_API i2d_body_type i2d_body_get_type(i2d_body_id id) {
    return guarded("i2d_body_get_type", I2D_BODY_STATIC, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? static_cast<i2d_body_type>(b.body().type) : I2D_BODY_STATIC;
    });
}

I2D_API i2d_status i2d_body_set_type(i2d_body_id id, i2d_body_type type) {
    return guarded("i2d_body_set_type", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !valid_body_type(call, &type, "type")) {
            return last_status();
        }
        if (type == I2D_BODY_DYNAMIC && has_chain(*b.world, b.body())) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT,
                             "the body holds a chain, which cannot be dynamic; destroy the chain first"),
                   last_status();
        }
        b.world->set_type(b.index, static_cast<BodyType>(type));
        return I2D_OK;
    });
}

I2D_API i2d_vec2 i2d_body_get_position(i2d_body_id id) {
    return guarded("i2d_body_get_position", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? to_public(b.body().transform.p) : i2d_vec2{0, 0};
    });
}

I2D_API i2d_rot i2d_body_get_rotation(i2d_body_id id) {
    return guarded("i2d_body_get_rotation", i2d_rot{0, 0}, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? to_public(b.body().transform.q) : i2d_rot{0, 0};
    });
}

I2D_API i2d_transform i2d_body_get_transform(i2d_body_id id) {
    return guarded("i2d_body_get_transform", i2d_transform{}, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? to_public(b.body().transform) : i2d_transform{};
    });
}

I2D_API i2d_status i2d_body_set_transform(i2d_body_id id, i2d_vec2 position, i2d_rot rotation) {
    return guarded("i2d_body_set_transform", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        Rot q;
        if (!mutable_body(call, id, b) || !call.coordinate(position, "position") ||
            !normalized_rotation(call, rotation, "rotation", q)) {
            return last_status();
        }
        b.world->set_transform(b.index, Transform{capi::to_core(position), q});
        return I2D_OK;
    });
}

I2D_API i2d_vec2 i2d_body_get_linear_velocity(i2d_body_id id) {
    return guarded("i2d_body_get_linear_velocity", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? to_public(b.body().linear_velocity) : i2d_vec2{0, 0};
    });
}

I2D_API i2d_status i2d_body_set_linear_velocity(i2d_body_id id, i2d_vec2 v) {
    return guarded("i2d_body_set_linear_velocity", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(v, "velocity")) {
            return last_status();
        }
        b.world->set_linear_velocity(b.index, capi::to_core(v));
        return I2D_OK;
    });
}

I2D_API float i2d_body_get_angular_velocity(i2d_body_id id) {
    return guarded("i2d_body_get_angular_velocity", 0.0f, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? b.body().angular_velocity : 0.0f;
    });
}

I2D_API i2d_status i2d_body_set_angular_velocity(i2d_body_id id, float w) {
    return guarded("i2d_body_set_angular_velocity", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(w, "angular velocity")) {
            return last_status();
        }
        b.world->set_angular_velocity(b.index, w);
        return I2D_OK;
    });
}

I2D_API float i2d_body_get_mass(i2d_body_id id) {
    return guarded("i2d_body_get_mass", 0.0f, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? b.body().mass : 0.0f;
    });
}

I2D_API i2d_vec2 i2d_body_get_world_center_of_mass(i2d_body_id id) {
    return guarded("i2d_body_get_world_center_of_mass", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? to_public(b.body().center) : i2d_vec2{0, 0};
    });
}

I2D_API float i2d_body_get_rotational_inertia(i2d_body_id id) {
    return guarded("i2d_body_get_rotational_inertia", 0.0f, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? b.body().inertia : 0.0f;
    });
}

I2D_API i2d_vec2 i2d_body_get_local_center_of_mass(i2d_body_id id) {
    return guarded("i2d_body_get_local_center_of_mass", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? to_public(b.body().local_center) : i2d_vec2{0, 0};
    });
}

I2D_API i2d_vec2 i2d_body_get_world_point(i2d_body_id id, i2d_vec2 local_point) {
    return guarded("i2d_body_get_world_point", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        if (!call.body(id, b) || !call.coordinate(local_point, "local_point")) {
            return i2d_vec2{0, 0};
        }
        return to_public(transform_point(b.body().transform, capi::to_core(local_point)));
    });
}

I2D_API i2d_vec2 i2d_body_get_local_point(i2d_body_id id, i2d_vec2 world_point) {
    return guarded("i2d_body_get_local_point", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        if (!call.body(id, b) || !call.coordinate(world_point, "world_point")) {
            return i2d_vec2{0, 0};
        }
        return to_public(inv_transform_point(b.body().transform, capi::to_core(world_point)));
    });
}

I2D_API i2d_vec2 i2d_body_get_world_point_velocity(i2d_body_id id, i2d_vec2 world_point) {
    return guarded("i2d_body_get_world_point_velocity", i2d_vec2{0, 0}, [&](Call& call) {
        BodyRef b;
        if (!call.body(id, b) || !call.coordinate(world_point, "world_point")) {
            return i2d_vec2{0, 0};
        }
        const Body& body = b.body();
        return to_public(body.linear_velocity + cross(body.angular_velocity, capi::to_core(world_point) - body.center));
    });
}

namespace {

// The core refuses a force or impulse whose result would overflow, changing nothing.
i2d_status refused_unless(Call& call, bool applied, const char* what) {
    if (applied) {
        return I2D_OK;
    }
    call.fail(I2D_ERR_INVALID_ARGUMENT, "%s", what);
    return last_status();
}

constexpr const char* force_overflow = "the body's accumulated force or torque would overflow";
constexpr const char* impulse_overflow = "the impulse would make the body's velocity overflow";

}  // namespace

I2D_API i2d_status i2d_body_apply_force(i2d_body_id id, i2d_vec2 force, i2d_vec2 point, bool wake) {
    return guarded("i2d_body_apply_force", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(force, "force") || !call.coordinate(point, "point")) {
            return last_status();
        }
        return refused_unless(call, b.world->apply_force(b.index, capi::to_core(force), capi::to_core(point), wake),
                              force_overflow);
    });
}

I2D_API i2d_status i2d_body_apply_force_to_center(i2d_body_id id, i2d_vec2 force, bool wake) {
    return guarded("i2d_body_apply_force_to_center", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(force, "force")) {
            return last_status();
        }
        return refused_unless(call, b.world->apply_force_to_center(b.index, capi::to_core(force), wake),
                              force_overflow);
    });
}

I2D_API i2d_status i2d_body_apply_torque(i2d_body_id id, float torque, bool wake) {
    return guarded("i2d_body_apply_torque", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(torque, "torque")) {
            return last_status();
        }
        return refused_unless(call, b.world->apply_torque(b.index, torque, wake), force_overflow);
    });
}

I2D_API i2d_status i2d_body_apply_linear_impulse(i2d_body_id id, i2d_vec2 impulse, i2d_vec2 point, bool wake) {
    return guarded("i2d_body_apply_linear_impulse", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(impulse, "impulse") || !call.coordinate(point, "point")) {
            return last_status();
        }
        return refused_unless(
            call, b.world->apply_linear_impulse(b.index, capi::to_core(impulse), capi::to_core(point), wake),
            impulse_overflow);
    });
}

I2D_API i2d_status i2d_body_apply_angular_impulse(i2d_body_id id, float impulse, bool wake) {
    return guarded("i2d_body_apply_angular_impulse", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.finite(impulse, "impulse")) {
            return last_status();
        }
        return refused_unless(call, b.world->apply_angular_impulse(b.index, impulse, wake), impulse_overflow);
    });
}

I2D_API bool i2d_body_is_awake(i2d_body_id id) {
    return guarded("i2d_body_is_awake", false, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) && b.world->is_awake(b.index);
    });
}

I2D_API bool i2d_body_is_quarantined(i2d_body_id id) {
    return guarded("i2d_body_is_quarantined", false, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) && b.world->is_quarantined(b.index);
    });
}

I2D_API i2d_status i2d_body_set_awake(i2d_body_id id, bool awake) {
    return guarded("i2d_body_set_awake", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b)) {
            return last_status();
        }
        if (b.body().type == BodyType::static_body) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "a static body neither sleeps nor wakes");
            return last_status();
        }
        if (awake) {
            b.world->wake_body(b.index);
        } else {
            b.world->sleep_body(b.index);
        }
        return I2D_OK;
    });
}

I2D_API void* i2d_body_get_user_data(i2d_body_id id) {
    return guarded("i2d_body_get_user_data", static_cast<void*>(nullptr), [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? b.body().user_data : nullptr;
    });
}

// User data does not touch the simulation, so it may be set from inside a callback.
I2D_API i2d_status i2d_body_set_user_data(i2d_body_id id, void* user_data) {
    return guarded("i2d_body_set_user_data", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!call.body(id, b)) {
            return last_status();
        }
        b.world->set_user_data(b.index, user_data);
        return I2D_OK;
    });
}

I2D_API int32_t i2d_body_get_shape_count(i2d_body_id id) {
    return guarded("i2d_body_get_shape_count", int32_t(0), [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? b.body().shape_count : 0;
    });
}

I2D_API int32_t i2d_body_get_shapes(i2d_body_id id, i2d_shape_id* out, int32_t capacity) {
    return guarded("i2d_body_get_shapes", int32_t(0), [&](Call& call) -> int32_t {
        BodyRef b;
        if (!call.body(id, b)) {
            return 0;
        }
        if (capacity < 0 || (capacity > 0 && out == nullptr)) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", capacity);
            return 0;
        }
        int32_t written = 0;
        for (int32_t s = b.body().head_shape; s != null_index && written < capacity;
             s = b.world->shapes()[s].next_in_body) {
            out[written++] = make_shape_id(b.id, s, b.world->shapes().generation(s));
        }
        return b.body().shape_count;
    });
}
