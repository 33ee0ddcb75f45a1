// SPDX-License-Identifier: MIT
// Event records the step fills and the C API hands out as arrays.
//
// Design note: they are laid out exactly like the public event structs (the C boundary
// checks that with static_asserts), so the public arrays are these arrays: no copy per
// read. Ids inside them are the public 64-bit ids, made by the encoder the C boundary
// installs in the world; without one (core tests) an id is index | generation << 32.
#pragma once

#include <cstdint>
#include <vector>

#include "collision/shapes.hpp"
#include "math/vec2.hpp"

namespace i2d {

struct ShapePairEvent {
    uint64_t shape_a;  // contact events: the two shapes; sensor events: sensor, visitor
    uint64_t shape_b;
};

struct ContactBeginEvent {
    uint64_t shape_a, shape_b;
    Manifold manifold;  // world points, penetration at the start of the step
};

struct ContactHitEvent {
    uint64_t shape_a, shape_b;
    Vec2 point;
    Vec2 normal;
    float approach_speed;
};

struct BodyMoveEvent {
    Transform transform;
    uint64_t body;
    void* user_data;
    bool fell_asleep;
};

/// A body frozen because its state stopped being finite (world_step.cpp, quarantine).
struct BodyQuarantineEvent {
    Transform transform;
    uint64_t body;
    void* user_data;
    int32_t former_type;  // BodyType, as the public enum's value
};

struct JointEvent {
    uint64_t joint;
    void* user_data;
};

/// Turns a pool slot into the id callers see.
struct IdEncoder {
    uint64_t (*body)(uint64_t tag, int32_t index, uint16_t generation) = nullptr;
    uint64_t (*shape)(uint64_t tag, int32_t index, uint16_t generation) = nullptr;
    uint64_t tag = 0;
    uint64_t (*joint)(uint64_t tag, int32_t index, uint16_t generation) = nullptr;

    uint64_t body_id(int32_t index, uint16_t generation) const {
        return body ? body(tag, index, generation) : (uint64_t(generation) << 32) | uint32_t(index);
    }
    uint64_t shape_id(int32_t index, uint16_t generation) const {
        return shape ? shape(tag, index, generation) : (uint64_t(generation) << 32) | uint32_t(index);
    }
    uint64_t joint_id(int32_t index, uint16_t generation) const {
        return joint ? joint(tag, index, generation) : (uint64_t(generation) << 32) | uint32_t(index);
    }
};

struct WorldEvents {
    std::vector<ContactBeginEvent> contact_begin;
    std::vector<ShapePairEvent> contact_end;
    std::vector<ShapePairEvent> sensor_begin, sensor_end;
    std::vector<BodyMoveEvent> body_moves;
    std::vector<BodyQuarantineEvent> body_quarantines;
    std::vector<JointEvent> joint_events;
    std::vector<ContactHitEvent> contact_hits;

    void clear() {
        contact_begin.clear(), contact_end.clear(), sensor_begin.clear(), sensor_end.clear();
        contact_hits.clear();
        body_moves.clear(), body_quarantines.clear(), joint_events.clear();
    }
};

/// A pair of shapes whose end waits for the next step's arrays, by index and generation:
/// encoded as ids only when it reaches them, so that a world restored from a snapshot
/// names them with its own ids.
struct PendingEnd {
    int32_t shape_a = 0, shape_b = 0;  // as the event names them (a sensor first)
    uint16_t generation_a = 0, generation_b = 0;
};

/// The events of the last step, and the ends caused between steps, which wait for the
/// next step's arrays so that the arrays a caller holds stay valid until then.
struct EventRecorder {
    WorldEvents current;
    std::vector<PendingEnd> pending_contact_ends;
    std::vector<PendingEnd> pending_sensor_ends;
    IdEncoder ids;

    void begin_step() {
        current.clear();
        take_pending(pending_contact_ends, 0, current.contact_end);
        take_pending(pending_sensor_ends, 0, current.sensor_end);
    }
    /// Moves the pending ends from `first` on into `out`, as ids.
    void take_pending(std::vector<PendingEnd>& pending, std::size_t first, std::vector<ShapePairEvent>& out) const {
        for (std::size_t k = first; k < pending.size(); ++k) {
            const PendingEnd& e = pending[k];
            out.push_back({ids.shape_id(e.shape_a, e.generation_a), ids.shape_id(e.shape_b, e.generation_b)});
        }
        pending.resize(first);
    }
};

}  // namespace i2d
