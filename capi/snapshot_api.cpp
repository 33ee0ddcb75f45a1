// SPDX-License-Identifier: MIT
// i2d_world_*_snapshot, i2d_world_*_state, i2d_world_create_from_snapshot and i2d_*_in_world.
//
// A restore reads the snapshot into a world of its own first (World::from_snapshot), then
// checks the settings and every value it holds against the rules of the calls that set
// them (loaded_values.hpp), and only then swaps it in: a refused buffer leaves the world
// untouched.
#include <cstdio>
#include <cstring>
#include <memory>

#include "boundary.hpp"
#include "dynamics/snapshot/snapshot_format.hpp"
#include "loaded_values.hpp"
#include "world_def.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// A world that only holds a snapshot while it is checked: no workers of its own.
WorldDef holder_of(const WorldDef& host) {
    WorldDef holder = host;
    holder.worker_count = 1;
    holder.tasks = TaskCallbacks{};
    return holder;
}

// Turns the failure a value check left (I2D_ERR_INVALID_ARGUMENT, naming the field) into
// the snapshot's refusal, keeping its message.
void refuse_values(Call& call, const char* buffer_kind, const char* what) {
    // The message starts with this call's name; it is said once.
    const char* message = i2d_last_error_message();
    const char* after_name = std::strstr(message, ": ");
    char detail[256];
    std::snprintf(detail, sizeof detail, "%s", after_name != nullptr ? after_name + 2 : message);
    call.fail(I2D_ERR_INVALID_SNAPSHOT, "%s refused: %s (%s)", buffer_kind, what, detail);
}

// Every body, shape and joint under the rules of the calls that make and change them.
bool valid_loaded_values(Call& call, const World& world) {
    // Shapes before bodies: a body's mass follows from its shapes.
    for (int32_t i = 0; i < world.shapes().capacity(); ++i) {
        if (world.shapes().is_live(i) && !valid_loaded_shape(call, world, i)) {
            return false;
        }
    }
    for (int32_t i = 0; i < world.bodies().capacity(); ++i) {
        if (world.bodies().is_live(i) && !valid_loaded_body(call, world, i)) {
            return false;
        }
    }
    for (int32_t i = 0; i < world.joints().capacity(); ++i) {
        if (world.joints().is_live(i) && !valid_loaded_joint(call, world, i)) {
            return false;
        }
    }
    return true;
}

// Reads and checks a snapshot; null, with the status set, when it is refused.
std::unique_ptr<World> load_checked(Call& call, const void* buffer, std::size_t size, const WorldDef& runtime) {
    if (buffer == nullptr && size != 0) {
        call.fail(I2D_ERR_INVALID_ARGUMENT, "buffer is NULL and size is %zu", size);
        return nullptr;
    }
    const char* problem = nullptr;
    std::unique_ptr<World> loaded = World::from_snapshot(buffer, size, runtime, &problem);
    if (loaded == nullptr) {
        call.fail(I2D_ERR_INVALID_SNAPSHOT, "snapshot refused: %s", problem);
        return nullptr;
    }
    const i2d_world_def settings = to_public(loaded->settings());
    if (!validate_world_def(call, &settings)) {
        refuse_values(call, "snapshot", "its settings are out of range");
        return nullptr;
    }
    if (!valid_loaded_values(call, *loaded)) {
        refuse_values(call, "snapshot", World::state_values_refused);
        return nullptr;
    }
    return loaded;
}

// The object of `bits` (of `kind`) in `world`, if that world has it.
template <class Id, class PoolT>
Id in_world(const char* function, uint64_t bits, IdKind kind, const char* kind_name, i2d_world_id world,
            const PoolT& (World::*pool)() const) {
    return guarded(function, Id{0}, [&](Call& call) -> Id {
        const IdFields f = decode_id(bits);
        if (bits == 0 || f.kind != kind) {
            call.fail(I2D_ERR_INVALID_HANDLE, "id 0x%016llx is not a %s id", static_cast<unsigned long long>(bits),
                      kind_name);
            return Id{0};
        }
        WorldRef w;
        if (!call.world(world, w)) {
            return Id{0};
        }
        if (!(w.world->*pool)().is_live(f.index, f.generation)) {
            return Id{0};
        }
        IdFields out = w.id;
        out.kind = kind;
        out.index = f.index;
        out.generation = f.generation;
        return Id{encode_id(out)};
    });
}

// Saves a snapshot or a rollback state into the caller's buffer, or says the size needed.
i2d_status save_into(Call& call, i2d_world_id world, void* buffer, size_t capacity, size_t* written, const char* what,
                     std::size_t (World::*size_of)() const, std::size_t (World::*save)(void*, std::size_t) const) {
    WorldRef w;
    if (!call.world(world, w)) {
        return last_status();
    }
    // One pass: the size is counted (a second pass) only when the buffer proves too small.
    const std::size_t size = buffer != nullptr ? (w.world->*save)(buffer, capacity) : 0;
    if (size == 0) {
        const std::size_t needed = (w.world->*size_of)();
        if (buffer != nullptr && capacity >= snapshot_header_size) {
            std::memset(buffer, 0, snapshot_header_size);  // what was written is no snapshot
        }
        if (written != nullptr) {
            *written = needed;
        }
        call.fail(I2D_ERR_INVALID_ARGUMENT, "the buffer holds %zu bytes and the %s needs %zu%s",
                  buffer == nullptr ? size_t(0) : capacity, what, needed, buffer == nullptr ? "; buffer is NULL" : "");
        return last_status();
    }
    if (written != nullptr) {
        *written = size;
    }
    return I2D_OK;
}

}  // namespace

I2D_API size_t i2d_world_get_snapshot_size(i2d_world_id world) {
    return guarded("i2d_world_get_snapshot_size", size_t(0), [&](Call& call) -> size_t {
        WorldRef w;
        return call.world(world, w) ? w.world->snapshot_size() : 0;
    });
}

I2D_API i2d_status i2d_world_save_snapshot(i2d_world_id world, void* buffer, size_t capacity, size_t* written) {
    return guarded("i2d_world_save_snapshot", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        return save_into(call, world, buffer, capacity, written, "snapshot", &World::snapshot_size,
                         &World::save_snapshot);
    });
}

I2D_API i2d_status i2d_world_restore_snapshot(i2d_world_id world, const void* buffer, size_t size) {
    return guarded("i2d_world_restore_snapshot", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.unlocked(*w.world)) {
            return last_status();
        }
        std::unique_ptr<World> loaded = load_checked(call, buffer, size, holder_of(w.world->settings()));
        if (loaded == nullptr) {
            return last_status();
        }
        w.world->take_state_of(*loaded);
        return I2D_OK;
    });
}

I2D_API i2d_world_id i2d_world_create_from_snapshot(const void* buffer, size_t size, const i2d_world_def* runtime) {
    return guarded("i2d_world_create_from_snapshot", I2D_NULL_WORLD_ID, [&](Call& call) -> i2d_world_id {
        const i2d_world_def defaults = i2d_default_world_def();
        const i2d_world_def* def = runtime != nullptr ? runtime : &defaults;
        if (!validate_world_def(call, def)) {
            return I2D_NULL_WORLD_ID;
        }
        std::unique_ptr<World> loaded = load_checked(call, buffer, size, to_core(*def));
        if (loaded == nullptr) {
            return I2D_NULL_WORLD_ID;
        }
        return register_new_world(call, std::move(loaded));
    });
}

I2D_API size_t i2d_world_get_state_size(i2d_world_id world) {
    return guarded("i2d_world_get_state_size", size_t(0), [&](Call& call) -> size_t {
        WorldRef w;
        return call.world(world, w) ? w.world->state_size() : 0;
    });
}

I2D_API i2d_status i2d_world_save_state(i2d_world_id world, void* buffer, size_t capacity, size_t* written) {
    return guarded("i2d_world_save_state", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        return save_into(call, world, buffer, capacity, written, "rollback state", &World::state_size,
                         &World::save_state);
    });
}

I2D_API i2d_status i2d_world_restore_state(i2d_world_id world, const void* buffer, size_t size) {
    return guarded("i2d_world_restore_state", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.unlocked(*w.world)) {
            return last_status();
        }
        if (buffer == nullptr && size != 0) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "buffer is NULL and size is %zu", size);
            return last_status();
        }
        const char* problem =
            w.world->restore_state(buffer, size, [&](const World& loaded) { return valid_loaded_values(call, loaded); });
        if (problem == World::state_values_refused) {
            refuse_values(call, "rollback state", problem);
        } else if (problem != nullptr) {
            call.fail(I2D_ERR_INVALID_SNAPSHOT, "rollback state refused: %s", problem);
        }
        if (problem != nullptr) {
            return last_status();
        }
        return I2D_OK;
    });
}

I2D_API i2d_body_id i2d_body_in_world(i2d_body_id body, i2d_world_id world) {
    return in_world<i2d_body_id>("i2d_body_in_world", body.bits, IdKind::body, "body", world, &World::bodies);
}

I2D_API i2d_shape_id i2d_shape_in_world(i2d_shape_id shape, i2d_world_id world) {
    return in_world<i2d_shape_id>("i2d_shape_in_world", shape.bits, IdKind::shape, "shape", world, &World::shapes);
}

I2D_API i2d_joint_id i2d_joint_in_world(i2d_joint_id joint, i2d_world_id world) {
    return in_world<i2d_joint_id>("i2d_joint_in_world", joint.bits, IdKind::joint, "joint", world, &World::joints);
}

I2D_API i2d_chain_id i2d_chain_in_world(i2d_chain_id chain, i2d_world_id world) {
    return in_world<i2d_chain_id>("i2d_chain_in_world", chain.bits, IdKind::chain, "chain", world, &World::chains);
}
