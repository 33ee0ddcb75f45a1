// SPDX-License-Identifier: MIT
// The snapshot format: a header that says what the bytes are, then sections.
//
// Every value is little-endian (core/byte_stream.hpp); nothing is a pointer or depends on
// the platform's struct layout, so a snapshot saved on x86-64 restores on AArch64 or in
// WebAssembly.
//
//   offset  size  field
//        0     8  magic "i2dsnap", then 0x1a
//        8     4  format version (format_version)
//       12     4  kind: 1 a full snapshot, 2 a rollback state
//       16     8  payload size, bytes
//       24     8  checksum64 of the payload (core/checksum.hpp)
//       32     8  rollback state: the serial of the world it was saved from; 0 otherwise
//       40     8  rollback state: that world's structure version; 0 otherwise
//       48        payload: sections, each a tag (4 ASCII bytes), its size (8 bytes) and
//                 its content, in a fixed order (world_snapshot.cpp)
//
// A reader refuses a buffer that is shorter than its header says, has another magic, a
// newer version, another kind or a checksum that does not match; then every section's
// tag and size must be what it expects, and what a section holds must make a world it can
// step (snapshot_checks.hpp). A version adds to the format: a reader keeps reading every
// version up to its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "core/byte_stream.hpp"

namespace i2d {

enum class SnapshotKind : uint32_t { snapshot = 1, state = 2 };

struct SnapshotHeader {
    uint32_t version = 0;
    SnapshotKind kind = SnapshotKind::snapshot;
    uint64_t payload_size = 0;
    uint64_t checksum = 0;
    uint64_t world_serial = 0;
    uint64_t structure_version = 0;
};

// 2 added the world's length unit and each body's sleep threshold, enabled flag and mass
// override; a version 1 snapshot loads with the values a world then had. 3 added each
// shape's opt-ins to the contact hooks (off in older snapshots). 4 added the world's
// enable_impact_chains (on in older snapshots, as in a new world). 5 gives static bodies
// extents of 0 (older snapshots hold the ones their shapes gave, which nothing read: they
// load as 0). 6 keeps a contact's points, feature ids and base separations only up to its
// point count (the rest were never read; they load as a fresh contact's), and leaves out
// its edges' bodies and its mixed material, which its shapes give.
constexpr uint32_t snapshot_format_version = 6;
constexpr std::size_t snapshot_header_size = 48;

/// Writes the header into the first snapshot_header_size bytes of `out`.
void write_snapshot_header(unsigned char* out, const SnapshotHeader& header);
/// Reads and checks the header and the payload's checksum; returns null, or what is wrong.
const char* read_snapshot_header(const void* data, std::size_t size, SnapshotKind kind, SnapshotHeader& out);

/// A section's tag: four ASCII letters.
constexpr uint32_t section_tag(const char (&name)[5]) {
    return uint32_t(uint8_t(name[0])) | uint32_t(uint8_t(name[1])) << 8 | uint32_t(uint8_t(name[2])) << 16 |
           uint32_t(uint8_t(name[3])) << 24;
}

/// Writes a section's tag and, once its content is written, its size.
class SectionWriter {
public:
    SectionWriter(ByteWriter& out, uint32_t tag);
    ~SectionWriter();
    SectionWriter(const SectionWriter&) = delete;
    SectionWriter& operator=(const SectionWriter&) = delete;

private:
    ByteWriter& out_;
    std::size_t size_at_;
};

/// Reads a section's tag and size, and at the end checks that its content took exactly
/// that size.
class SectionReader {
public:
    SectionReader(ByteReader& in, uint32_t tag);
    ~SectionReader();
    SectionReader(const SectionReader&) = delete;
    SectionReader& operator=(const SectionReader&) = delete;

private:
    ByteReader& in_;
    std::size_t end_ = 0;
};

// A snapshot's sections, in their order; a rollback state has the dynamic_* ones in
// place of settings, bodies, shapes, chains and joints.
constexpr uint32_t settings_section = section_tag("SETT");
constexpr uint32_t bodies_section = section_tag("BODY");
constexpr uint32_t shapes_section = section_tag("SHAP");
constexpr uint32_t chains_section = section_tag("CHAN");
constexpr uint32_t joints_section = section_tag("JOIN");
constexpr uint32_t contacts_section = section_tag("CONT");
constexpr uint32_t islands_section = section_tag("ISLD");
constexpr uint32_t broadphase_section = section_tag("BRPH");
constexpr uint32_t events_section = section_tag("EVNT");
constexpr uint32_t world_section = section_tag("WRLD");
constexpr uint32_t dynamic_bodies_section = section_tag("BODS");
constexpr uint32_t dynamic_shapes_section = section_tag("SHPS");
constexpr uint32_t dynamic_joints_section = section_tag("JOIS");

/// The section's reader when loading, its writer when saving.
template <class Io>
using SectionOf = std::conditional_t<Io::loading, SectionReader, SectionWriter>;

/// A module's own save or load, whichever way the Io goes.
template <class Io, class Module>
inline void move_module(Io& io, Module& module) {
    if constexpr (Io::loading) {
        module.load(io);
    } else {
        module.save(io);
    }
}

}  // namespace i2d
