// SPDX-License-Identifier: MIT
// Id decoding and argument checks for the entry points.
#include "boundary.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "limits.hpp"
#include "registry.hpp"

namespace i2d::capi {

namespace {

// "NaN", "inf" or the number, for messages.
const char* describe(float v, char (&buffer)[32]) {
    if (std::isnan(v)) {
        return "NaN";
    }
    if (std::isinf(v)) {
        return v > 0 ? "+inf" : "-inf";
    }
    std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(v));
    return buffer;
}

}  // namespace

bool Call::fail(i2d_status status, const char* format, ...) {
    va_list args;
    va_start(args, format);
    std::vsnprintf(detail_, sizeof detail_, format, args);
    va_end(args);
    set_error(status, function_, "%s", detail_);
    return false;
}

// Checks in Box2D's order: never read a slot before its range is known good.
bool Call::decode(uint64_t bits, IdKind kind, const char* kind_name, IdFields& fields, World*& world) {
    if (bits == 0) {
        return fail(I2D_ERR_INVALID_HANDLE, "%s id is null", kind_name);
    }
    fields = decode_id(bits);
    if (fields.kind != kind) {
        return fail(I2D_ERR_INVALID_HANDLE, "id 0x%016llx is not a %s id", static_cast<unsigned long long>(bits),
                    kind_name);
    }
    world = find_world(fields.world_slot, fields.world_generation);
    if (world == nullptr) {
        return kind == IdKind::world ? fail(I2D_ERR_INVALID_HANDLE, "world id is stale: the world was destroyed")
                                     : fail(I2D_ERR_INVALID_HANDLE, "the %s's world was destroyed", kind_name);
    }
    // Inside a step only a job system's callbacks and the contact hooks run user code,
    // while the world's other workers may be changing any of it: nothing of the world may
    // be read or changed.
    if (world->is_stepping()) {
        return fail(I2D_ERR_WORLD_LOCKED,
                    "called from inside the world's step (a contact hook, or its job system's enqueue_task or "
                    "finish_task); make this call after i2d_world_step returns");
    }
    return true;
}

bool Call::world(i2d_world_id id, WorldRef& out) {
    if (!decode(id.bits, IdKind::world, "world", out.id, out.world)) {
        return false;
    }
    if (out.id.index != -1 || out.id.generation != 0) {
        return fail(I2D_ERR_INVALID_HANDLE, "world id has object bits set: not a world id");
    }
    return true;
}

bool Call::body(i2d_body_id id, BodyRef& out) {
    if (!decode(id.bits, IdKind::body, "body", out.id, out.world)) {
        return false;
    }
    if (!out.world->bodies().is_live(out.id.index, out.id.generation)) {
        return fail(I2D_ERR_INVALID_HANDLE, "body id is stale: the body was destroyed");
    }
    out.index = out.id.index;
    return true;
}

bool Call::body(i2d_body_id id, BodyRef& out, const char* field) {
    return body(id, out) || fail_in(field);
}

bool Call::fail_in(const char* field) {
    char detail[sizeof detail_];
    std::snprintf(detail, sizeof detail, "%s", detail_);
    return fail(last_status(), "%s: %s", field, detail);
}

bool Call::shape(i2d_shape_id id, ShapeRef& out) {
    if (!decode(id.bits, IdKind::shape, "shape", out.id, out.world)) {
        return false;
    }
    if (!out.world->shapes().is_live(out.id.index, out.id.generation)) {
        return fail(I2D_ERR_INVALID_HANDLE, "shape id is stale: the shape or its body was destroyed");
    }
    out.index = out.id.index;
    return true;
}

bool Call::joint(i2d_joint_id id, JointRef& out) {
    if (!decode(id.bits, IdKind::joint, "joint", out.id, out.world)) {
        return false;
    }
    if (!out.world->joints().is_live(out.id.index, out.id.generation)) {
        return fail(I2D_ERR_INVALID_HANDLE, "joint id is stale: the joint or one of its bodies was destroyed");
    }
    out.index = out.id.index;
    return true;
}

bool Call::chain(i2d_chain_id id, ChainRef& out) {
    if (!decode(id.bits, IdKind::chain, "chain", out.id, out.world)) {
        return false;
    }
    if (!out.world->chains().is_live(out.id.index, out.id.generation)) {
        return fail(I2D_ERR_INVALID_HANDLE, "chain id is stale: the chain or its body was destroyed");
    }
    out.index = out.id.index;
    return true;
}

bool Call::unlocked(const World& world) {
    if (world.is_locked()) {
        return fail(I2D_ERR_WORLD_LOCKED,
                    "called from inside a query callback or a draw callback; make this call after it returns");
    }
    return true;
}

bool Call::finite(float v, const char* what) {
    char buffer[32];
    if (!std::isfinite(v)) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s is %s", what, describe(v, buffer));
    }
    return true;
}

bool Call::finite(i2d_vec2 v, const char* what) {
    char buffer[32];
    if (!std::isfinite(v.x)) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s.x is %s", what, describe(v.x, buffer));
    }
    if (!std::isfinite(v.y)) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s.y is %s", what, describe(v.y, buffer));
    }
    return true;
}

bool Call::coordinate(i2d_vec2 v, const char* what) {
    if (!finite(v, what)) {
        return false;
    }
    if (std::fabs(v.x) > max_coordinate || std::fabs(v.y) > max_coordinate) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s (%g, %g) is beyond %g m from the origin", what,
                    static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(max_coordinate));
    }
    return true;
}

bool Call::cast_translation(i2d_vec2 v, const char* what) {
    if (!finite(v, what)) {
        return false;
    }
    const double length = std::hypot(double(v.x), double(v.y));
    if (length > double(max_cast_length)) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s (%g, %g) is %g m long; a cast goes at most %g m", what,
                    static_cast<double>(v.x), static_cast<double>(v.y), length,
                    static_cast<double>(max_cast_length));
    }
    return true;
}

bool Call::local_point(i2d_vec2 v, const char* what) {
    if (!finite(v, what)) {
        return false;
    }
    if (std::fabs(v.x) > max_shape_extent || std::fabs(v.y) > max_shape_extent) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s (%g, %g) is beyond %g m from the body origin", what,
                    static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(max_shape_extent));
    }
    return true;
}

bool Call::in_range(float v, float lo, float hi, const char* what) {
    char buffer[32];
    if (!(v >= lo && v <= hi)) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s is %s; it must be in [%g, %g]", what, describe(v, buffer),
                    static_cast<double>(lo), static_cast<double>(hi));
    }
    return true;
}

bool Call::extent(float v, const char* what) {
    char buffer[32];
    if (!(v >= min_shape_extent && v <= max_shape_extent)) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s is %s; it must be in [%g, %g] m", what, describe(v, buffer),
                    static_cast<double>(min_shape_extent), static_cast<double>(max_shape_extent));
    }
    return true;
}

bool Call::cookie(uint32_t cookie, const char* def_name) {
    if (cookie != def_cookie) {
        return fail(I2D_ERR_INVALID_ARGUMENT,
                    "%s was not initialised: start from i2d_default_%s() and edit its fields", def_name, def_name);
    }
    return true;
}

bool Call::not_null(const void* p, const char* what) {
    if (p == nullptr) {
        return fail(I2D_ERR_INVALID_ARGUMENT, "%s is NULL", what);
    }
    return true;
}

i2d_world_id make_world_id(const IdFields& world) {
    IdFields f = world;
    f.kind = IdKind::world;
    f.index = -1;
    f.generation = 0;
    return {encode_id(f)};
}

i2d_body_id make_body_id(const IdFields& world, int32_t index, uint16_t generation) {
    IdFields f = world;
    f.kind = IdKind::body;
    f.index = index;
    f.generation = generation;
    return {encode_id(f)};
}

i2d_chain_id make_chain_id(const IdFields& world, int32_t index, uint16_t generation) {
    IdFields f = world;
    f.kind = IdKind::chain;
    f.index = index;
    f.generation = generation;
    return {encode_id(f)};
}

i2d_shape_id make_shape_id(const IdFields& world, int32_t index, uint16_t generation) {
    IdFields f = world;
    f.kind = IdKind::shape;
    f.index = index;
    f.generation = generation;
    return {encode_id(f)};
}

i2d_joint_id make_joint_id(const IdFields& world, int32_t index, uint16_t generation) {
    IdFields f = world;
    f.kind = IdKind::joint;
    f.index = index;
    f.generation = generation;
    return {encode_id(f)};
}

}  // namespace i2d::capi
