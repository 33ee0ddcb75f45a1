// SPDX-License-Identifier: MIT
// A recorded call being replayed: its arguments and the replay's world, with a member per
// family of records (replay.cpp, replayed_settings.cpp). Internal to the replay.
#pragma once

#include "boundary.hpp"
#include "core/field_io.hpp"
#include "dynamics/recording/recording_format.hpp"

namespace i2d::capi {

// The id of a pool slot in the replay's world: the slot's generation if it is in range,
// else an id that no live object has, which the call then refuses.
template <class T>
inline uint16_t generation_of(const Pool<T>& pool, int32_t index) {
    return index >= 0 && index < pool.capacity() ? pool.generation(index) : uint16_t(0);
}

inline bool malformed(Call& call) {
    return call.fail(I2D_ERR_INVALID_SNAPSHOT, "a record's arguments do not read whole");
}

// The arguments were read to the last byte and no further.
inline bool read_whole(const ByteReader& in) { return !in.failed() && in.remaining() == 0; }

inline bool passed(i2d_status status) { return status == I2D_OK; }

inline bool live(Call& call, bool is_live, const char* what) {
    return is_live || call.fail(I2D_ERR_INVALID_SNAPSHOT, "a record names a %s that does not exist", what);
}

// A record being applied: its arguments, and the replay's world with ids for its slots.
// Each family of records has its own member.
struct Replayed {
    Call& call;
    World& world;
    IdFields ids;
    i2d_world_id world_id;
    ByteReader& in;
    LoadIo& io;

    i2d_body_id body(int32_t i) const { return make_body_id(ids, i, generation_of(world.bodies(), i)); }
    i2d_shape_id shape(int32_t i) const { return make_shape_id(ids, i, generation_of(world.shapes(), i)); }
    i2d_joint_id joint(int32_t i) const { return make_joint_id(ids, i, generation_of(world.joints(), i)); }
    i2d_chain_id chain(int32_t i) const { return make_chain_id(ids, i, generation_of(world.chains(), i)); }
    // Every record kind is one family's; a kind no family takes is refused.
    bool unknown() const {
        return call.fail(I2D_ERR_INVALID_SNAPSHOT, "a record is of a kind this library does not know");
    }

    bool body_call(RecordedOp op) const;
    bool shape_call(RecordedOp op) const;
    bool joint_call(RecordedOp op) const;
    bool world_call(RecordedOp op) const;
    bool settings_call(RecordedOp op) const;
};

}  // namespace i2d::capi
