// SPDX-License-Identifier: MIT
// World: full snapshots saved, restored in place and made into new worlds.
//
// A restore never changes the world until the whole snapshot has been read into a world
// of its own and checked; then the two swap their state (every swap is of containers
// and cannot fail). A world made from a snapshot is that second world itself.
#include <cstring>

#include "core/checksum.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/snapshot/snapshot_format.hpp"
#include "dynamics/snapshot/world_fields.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

template <class Io, class Self>
void World::transfer(Io& io, Self& world) {
    auto& bytes = io.bytes();
    {
        SectionOf<Io> s(bytes, settings_section);
        settings_fields(io, world.settings_, snapshot_settings_versions);
    }
    {
        SectionOf<Io> s(bytes, bodies_section);
        if constexpr (Io::loading) {
            const float world_sleep_threshold = world.settings_.sleep_speed_threshold;
            world.bodies_.load(io, [world_sleep_threshold](LoadIo& in, Body& b) {
                if (!in.has_version(2)) {
                    b.sleep_threshold = world_sleep_threshold;  // before version 2 every body had the world's
                }
                body_fields(in, b, SnapshotPart::whole);
                b.move_event = null_index;  // not saved: each step numbers its own events
            });
        } else {
            world.bodies_.save(io, [](SaveIo& out, const Body& b) { body_fields(out, b, SnapshotPart::whole); });
        }
    }
    {
        SectionOf<Io> s(bytes, shapes_section);
        const auto fields = [](auto& io_, auto& shape) { shape_fields(io_, shape, SnapshotPart::whole); };
        if constexpr (Io::loading) {
            world.shapes_.load(io, fields);
        } else {
            world.shapes_.save(io, fields);
        }
    }
    {
        SectionOf<Io> s(bytes, chains_section);
        const auto fields = [](auto& io_, auto& chain) { chain_fields(io_, chain); };
        if constexpr (Io::loading) {
            world.chains_.load(io, fields);
        } else {
            world.chains_.save(io, fields);
        }
    }
    WorldStages& stages = *world.stages_;
    {
        SectionOf<Io> s(bytes, joints_section);
        move_module(io, stages.joints);
    }
    transfer_stages(io, world);
}

// What a step changes besides bodies, shapes and joints: contacts, islands, the
// broadphase, the ends waiting for the next step, the boxes to cover. A snapshot and a
// rollback state hold them alike.
template <class Io, class Self>
void World::transfer_stages(Io& io, Self& world) {
    auto& bytes = io.bytes();
    WorldStages& stages = *world.stages_;
    {
        SectionOf<Io> s(bytes, contacts_section);
        move_module(io, stages.contacts);
    }
    {
        SectionOf<Io> s(bytes, islands_section);
        move_module(io, stages.islands);
    }
    {
        SectionOf<Io> s(bytes, broadphase_section);
        move_module(io, stages.broad_phase);
    }
    {
        SectionOf<Io> s(bytes, events_section);
        if constexpr (Io::loading) {
            stages.events.current.clear();
        }
        const auto end_fields = [](auto& io_, auto& end) { pending_end_fields(io_, end); };
        struct_list_fields(io, stages.events.pending_contact_ends, 12, Pool<Contact>::max_slots,
                           "more ended contacts than the bytes left could hold", end_fields);
        struct_list_fields(io, stages.events.pending_sensor_ends, 12, Pool<Contact>::max_slots,
                           "more ended sensor visits than the bytes left could hold", end_fields);
    }
    {
        SectionOf<Io> s(bytes, world_section);
        list_fields(io, world.to_cover_, Pool<Body>::max_slots, "more bodies to cover than the bytes left could hold");
        io(world.covered_time_step_);
    }
}

template void World::transfer_stages<SaveIo, const World>(SaveIo&, const World&);
template void World::transfer_stages<LoadIo, World>(LoadIo&, World&);

std::size_t World::snapshot_size() const {
    ByteWriter counter;
    SaveIo io(counter);
    transfer(io, *this);
    return snapshot_header_size + counter.size();
}

std::size_t World::save_snapshot(void* buffer, std::size_t capacity) const {
    unsigned char* out = static_cast<unsigned char*>(buffer);
    if (capacity < snapshot_header_size) {
        return 0;
    }
    ByteWriter writer(out + snapshot_header_size, capacity - snapshot_header_size);
    SaveIo io(writer);
    transfer(io, *this);
    if (writer.overflowed()) {
        return 0;
    }
    SnapshotHeader header;
    header.version = snapshot_format_version;
    header.kind = SnapshotKind::snapshot;
    header.payload_size = writer.size();
    header.checksum = checksum64(out + snapshot_header_size, writer.size());
    write_snapshot_header(out, header);
    return snapshot_header_size + writer.size();
}

const char* World::load_snapshot(const void* data, std::size_t size) {
    SnapshotHeader header;
    if (const char* problem = read_snapshot_header(data, size, SnapshotKind::snapshot, header)) {
        return problem;
    }
    ByteReader reader(static_cast<const unsigned char*>(data) + snapshot_header_size, std::size_t(header.payload_size));
    LoadIo io(reader, header.version);
    transfer(io, *this);
    if (!reader.failed() && reader.remaining() != 0) {
        reader.check(false, "the snapshot holds more than its sections");
    }
    if (reader.failed()) {
        return reader.error();
    }
    return check_loaded();
}

std::unique_ptr<World> World::from_snapshot(const void* data, std::size_t size, const WorldDef& runtime,
                                            const char** problem) {
    auto world = std::make_unique<World>(runtime);
    *problem = world->load_snapshot(data, size);
    if (*problem != nullptr) {
        return nullptr;
    }
    return world;
}

void World::take_state_of(World& loaded) noexcept {
    ++structure_version_;
    // The simulation's settings come from the snapshot; the host's wiring stays.
    const WorldDef host = settings_;
    settings_ = loaded.settings_;
    settings_.worker_count = host.worker_count;
    settings_.tasks = host.tasks;
    settings_.simd_path = host.simd_path;
    settings_.enable_profile = host.enable_profile;
    bodies_.swap(loaded.bodies_);
    shapes_.swap(loaded.shapes_);
    chains_.swap(loaded.chains_);
    WorldStages& mine = *stages_;
    WorldStages& theirs = *loaded.stages_;
    mine.joints.swap_state(theirs.joints);
    mine.contacts.swap_state(theirs.contacts);
    mine.islands.swap_state(theirs.islands);
    std::swap(mine.broad_phase, theirs.broad_phase);
    mine.events.current.clear();
    mine.events.pending_contact_ends.swap(theirs.events.pending_contact_ends);
    mine.events.pending_sensor_ends.swap(theirs.events.pending_sensor_ends);
    mine.solver.forget_caches();
    to_cover_.swap(loaded.to_cover_);
    std::swap(covered_time_step_, loaded.covered_time_step_);
    profile_ = StepProfile{};
    if (recorder_ != nullptr) {
        // A recording goes on from what the world became; one that cannot be written
        // (no memory for the snapshot) stops rather than leave the world half restored.
        try {
            record_snapshot();
        } catch (...) {
            recorder_.reset();
        }
    }
}

const char* World::restore_snapshot(const void* data, std::size_t size) {
    // The world that reads the snapshot is only a holder: no workers of its own.
    WorldDef holder = settings_;
    holder.worker_count = 1;
    holder.tasks = TaskCallbacks{};
    const char* problem = nullptr;
    std::unique_ptr<World> loaded = from_snapshot(data, size, holder, &problem);
    if (loaded == nullptr) {
        return problem;
    }
    take_state_of(*loaded);
    return nullptr;
}

}  // namespace i2d
