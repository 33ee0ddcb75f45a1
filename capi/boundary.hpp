// SPDX-License-Identifier: MIT
// The entry-point helper every i2d_ function goes through: id decoding, the lock check,
// argument checks with field-naming messages, and exceptions turned into statuses.
//
// Every entry point follows one order: decode ids, check the world is not locked,
// validate every argument, and only then call the core, so a refused call changes
// nothing.
#pragma once

#include <cstdint>
#include <new>

#include <impulse2d/impulse2d.h>

#include "dynamics/world/world.hpp"
#include "handles.hpp"
#include "status.hpp"

namespace i2d::capi {

/// The value default functions put in a def's internal_cookie.
constexpr uint32_t def_cookie = 0x1D2D0C1Eu;

struct WorldRef {
    World* world = nullptr;
    IdFields id;
};

struct BodyRef {
    World* world = nullptr;
    int32_t index = -1;
    IdFields id;
    const Body& body() const { return world->bodies()[index]; }
};

struct ShapeRef {
    World* world = nullptr;
    int32_t index = -1;
    IdFields id;
    const Shape& shape() const { return world->shapes()[index]; }
};

struct JointRef {
    World* world = nullptr;
    int32_t index = -1;
    IdFields id;
    const Joint& joint() const { return world->joints()[index]; }
};

struct ChainRef {
    World* world = nullptr;
    int32_t index = -1;
    IdFields id;
};

class Call {
public:
    explicit Call(const char* function) : function_(function) {
        detail_[0] = '\0';  // not the whole buffer: every entry point makes a Call
        set_ok();
    }

    /// Records the failure; always returns false so that checks read `if (!ok) return`.
    bool fail(i2d_status status, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 3, 4)))
#endif
        ;

    bool world(i2d_world_id id, WorldRef& out);
    bool body(i2d_body_id id, BodyRef& out);
    /// The same, with the failure's message naming the field that held the id.
    bool body(i2d_body_id id, BodyRef& out, const char* field);
    bool shape(i2d_shape_id id, ShapeRef& out);
    bool joint(i2d_joint_id id, JointRef& out);
    bool chain(i2d_chain_id id, ChainRef& out);
    /// The last failure again, its message starting with the field that held the value.
    bool fail_in(const char* field);
    /// Fails with I2D_ERR_WORLD_LOCKED inside a query or draw callback.
    bool unlocked(const World& world);

    bool finite(float v, const char* what);
    bool finite(i2d_vec2 v, const char* what);
    /// Finite and within max_coordinate.
    bool coordinate(i2d_vec2 v, const char* what);
    /// A cast's translation: finite and at most max_cast_length long (its length, in
    /// double: a component bound would let a diagonal reach 1.41 times as far).
    bool cast_translation(i2d_vec2 v, const char* what);
    /// A point of a shape in its body's frame: finite and within max_shape_extent.
    bool local_point(i2d_vec2 v, const char* what);
    /// Finite and lo <= v <= hi.
    bool in_range(float v, float lo, float hi, const char* what);
    /// A radius or half extent: finite, positive, at most max_shape_extent.
    bool extent(float v, const char* what);
    bool cookie(uint32_t cookie, const char* def_name);
    bool not_null(const void* p, const char* what);

private:
    bool decode(uint64_t bits, IdKind kind, const char* kind_name, IdFields& fields, World*& world);

    const char* function_;
    char detail_[400];  // the last failure's detail, for body(id, out, field)
};

/// Runs an entry point's body; a failure to allocate becomes I2D_ERR_OUT_OF_MEMORY, any
/// other exception (a defect: the core throws nothing else on purpose) I2D_ERR_INTERNAL.
template <class R, class F>
R guarded(const char* function, R on_failure, F&& body) {
    Call call(function);
    try {
        return body(call);
    } catch (const std::bad_alloc&) {
        call.fail(I2D_ERR_OUT_OF_MEMORY, "out of memory");
    } catch (...) {
        call.fail(I2D_ERR_INTERNAL, "internal error (an unexpected exception); please report it");
    }
    return on_failure;
}

/// The prologue of calls that change something: a live id and an unlocked world.
inline bool mutable_body(Call& call, i2d_body_id id, BodyRef& b) { return call.body(id, b) && call.unlocked(*b.world); }
inline bool mutable_shape(Call& call, i2d_shape_id id, ShapeRef& s) {
    return call.shape(id, s) && call.unlocked(*s.world);
}
inline bool mutable_world(Call& call, i2d_world_id id, WorldRef& w) {
    return call.world(id, w) && call.unlocked(*w.world);
}

/// Public id of a core object.
i2d_world_id make_world_id(const IdFields& world);
i2d_body_id make_body_id(const IdFields& world, int32_t index, uint16_t generation);
i2d_shape_id make_shape_id(const IdFields& world, int32_t index, uint16_t generation);
i2d_joint_id make_joint_id(const IdFields& world, int32_t index, uint16_t generation);
i2d_chain_id make_chain_id(const IdFields& world, int32_t index, uint16_t generation);

}  // namespace i2d::capi
