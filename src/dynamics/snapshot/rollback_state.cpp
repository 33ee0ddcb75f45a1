// SPDX-License-Identifier: MIT
// World: rollback states, what a step changes, saved and restored for rollback netcode
// and reinforcement-learning resets.
//
// Design note: a state names the world it was saved from (its serial) and the world's
// structure version; restoring it anywhere else, or after a body, shape, joint, chain or
// setting was made, destroyed or changed, is refused, because the state holds only the
// fields a step moves (the rest is the world's own). It holds the whole of what a step
// rebuilds (contacts, islands, trees), so that stepping from it gives the same bits as
// stepping from the moment it was saved. A restore loads into the world itself, having
// first saved the world's present state aside: if the state turns out to be wrong (the
// checks a snapshot's load runs), that copy is loaded back, so a refused restore leaves
// the world as it was without reading the state into a second world first.
#include "core/checksum.hpp"
#include "dynamics/snapshot/snapshot_format.hpp"
#include "dynamics/snapshot/world_fields.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

namespace {

// The fields of the live items of a pool whose slots are the world's as they stand: a
// load must find exactly as many.
template <class Io, class PoolT, class Fields>
void live_fields(Io& io, PoolT& pool, Fields&& fields) {
    if constexpr (Io::loading) {
        const int32_t count = io.count(1, Pool<int32_t>::max_slots, "a rollback state holds too many items");
        if (!io.check(count == pool.count(), "the rollback state is of a world with other bodies, shapes or joints")) {
            return;
        }
    } else {
        io.count(pool.count());
    }
    for (int32_t i = 0; i < pool.capacity() && !io.failed(); ++i) {
        if (pool.is_live(i)) {
            fields(io, pool[i]);
        }
    }
}

}  // namespace

template <class Io, class Self>
void World::transfer_state(Io& io, Self& world) {
    auto& bytes = io.bytes();
    {
        SectionOf<Io> s(bytes, dynamic_bodies_section);
        live_fields(io, world.bodies_, [](auto& io_, auto& body) {
            body_fields(io_, body, SnapshotPart::state);
            if constexpr (Io::loading) {
                body.move_event = null_index;  // not saved: each step numbers its own events
            }
        });
    }
    {
        SectionOf<Io> s(bytes, dynamic_shapes_section);
        live_fields(io, world.shapes_, [](auto& io_, auto& shape) { shape_fields(io_, shape, SnapshotPart::state); });
    }
    {
        SectionOf<Io> s(bytes, dynamic_joints_section);
        live_fields(io, world.stages_->joints.pool(),
                    [](auto& io_, auto& joint) { joint_fields(io_, joint, SnapshotPart::state); });
    }
    transfer_stages(io, world);
}

std::size_t World::state_size() const {
    ByteWriter counter;
    SaveIo io(counter);
    transfer_state(io, *this);
    return snapshot_header_size + counter.size();
}

std::size_t World::save_state(void* buffer, std::size_t capacity) const {
    uint64_t checksum = 0;
    const std::size_t size = save_state_quietly(buffer, capacity, &checksum);
    if (size != 0) {
        saved_states_[next_saved_state_] = {checksum, size, structure_version_};
        next_saved_state_ = (next_saved_state_ + 1) % saved_state_marks;
    }
    return size;
}

// save_state without noting the state as one the caller holds.
std::size_t World::save_state_quietly(void* buffer, std::size_t capacity, uint64_t* checksum) const {
    unsigned char* out = static_cast<unsigned char*>(buffer);
    if (capacity < snapshot_header_size) {
        return 0;
    }
    ByteWriter writer(out + snapshot_header_size, capacity - snapshot_header_size);
    SaveIo io(writer);
    transfer_state(io, *this);
    if (writer.overflowed()) {
        return 0;
    }
    SnapshotHeader header;
    header.version = snapshot_format_version;
    header.kind = SnapshotKind::state;
    header.payload_size = writer.size();
    header.checksum = checksum64(out + snapshot_header_size, writer.size());
    header.world_serial = serial_;
    header.structure_version = structure_version_;
    write_snapshot_header(out, header);
    if (checksum != nullptr) {
        *checksum = header.checksum;
    }
    return snapshot_header_size + writer.size();
}

// Whether the state is one this world saved at its present structure: its checksum
// (which the header check verified against the bytes) and size match a save's. Such bytes
// were a world this one stood as; a change to any byte would have changed the checksum.
bool World::saved_here(const SnapshotHeader& header, std::size_t size) const {
    for (const SavedStateMark& mark : saved_states_) {
        if (mark.size == size && mark.checksum == header.checksum && mark.structure_version == structure_version_) {
            return true;
        }
    }
    return false;
}

// This world's state now, for a restore that turns out wrong to go back to; the buffer
// grows only when the state has.
void World::save_backup() {
    if (save_state_quietly(rollback_backup_.data(), rollback_backup_.size(), nullptr) == 0) {
        rollback_backup_.resize(state_size());
        save_state_quietly(rollback_backup_.data(), rollback_backup_.size(), nullptr);
    }
}

// A state this world saved, loaded without the checks a stranger's needs.
void World::load_state_unchecked(const void* data, std::size_t size) {
    ByteReader reader(static_cast<const unsigned char*>(data) + snapshot_header_size, size - snapshot_header_size);
    LoadIo io(reader);
    transfer_state(io, *this);
}

// Loads a state whose header was checked into the world; returns what is wrong, or null.
const char* World::load_state(const void* data, std::size_t size) {
    ByteReader reader(static_cast<const unsigned char*>(data) + snapshot_header_size, size - snapshot_header_size);
    LoadIo io(reader);
    transfer_state(io, *this);
    if (!reader.failed() && reader.remaining() != 0) {
        reader.check(false, "the rollback state holds more than its sections");
    }
    return reader.failed() ? reader.error() : check_loaded();
}

const char* World::restore_state(const void* data, std::size_t size, FunctionRef<bool(const World&)> values_valid) {
    SnapshotHeader header;
    if (const char* problem = read_snapshot_header(data, size, SnapshotKind::state, header)) {
        return problem;
    }
    if (header.world_serial != serial_) {
        return "the rollback state was saved from another world";
    }
    if (header.structure_version != structure_version_) {
        return "the world's structure changed since the rollback state was saved (a body, shape, joint or chain was "
               "made, destroyed or changed, or a setting was)";
    }
    if (saved_here(header, size)) {
        load_state_unchecked(data, size);
    } else {
        save_backup();
        const char* problem = load_state(data, size);
        if (problem == nullptr && !values_valid(*this)) {
            problem = state_values_refused;
        }
        if (problem != nullptr) {
            load_state(rollback_backup_.data(), rollback_backup_.size());  // what was saved from this world loads
            stages_->solver.forget_caches();
            return problem;
        }
    }
    stages_->events.current.clear();
    stages_->solver.forget_caches();
    profile_ = StepProfile{};
    record_snapshot();
    return nullptr;
}

}  // namespace i2d
