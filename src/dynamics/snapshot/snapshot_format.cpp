// SPDX-License-Identifier: MIT
// The snapshot header and sections.
#include "dynamics/snapshot/snapshot_format.hpp"

#include <cstring>

#include "core/checksum.hpp"

namespace i2d {

namespace {

constexpr unsigned char magic[8] = {'i', '2', 'd', 's', 'n', 'a', 'p', 0x1a};

}  // namespace

void write_snapshot_header(unsigned char* out, const SnapshotHeader& header) {
    ByteWriter w(out, snapshot_header_size);
    w.bytes(magic, sizeof magic);
    w.u32(header.version);
    w.u32(uint32_t(header.kind));
    w.u64(header.payload_size);
    w.u64(header.checksum);
    w.u64(header.world_serial);
    w.u64(header.structure_version);
}

const char* read_snapshot_header(const void* data, std::size_t size, SnapshotKind kind, SnapshotHeader& out) {
    if (size < snapshot_header_size) {
        return "the buffer is shorter than a snapshot's header (truncated)";
    }
    ByteReader r(data, snapshot_header_size);
    unsigned char read_magic[8];
    r.bytes(read_magic, sizeof read_magic);
    if (std::memcmp(read_magic, magic, sizeof magic) != 0) {
        return "the buffer is not an impulse2d snapshot (its first bytes are not the format's magic)";
    }
    out.version = r.u32();
    const uint32_t read_kind = r.u32();
    out.payload_size = r.u64();
    out.checksum = r.u64();
    out.world_serial = r.u64();
    out.structure_version = r.u64();
    if (out.version == 0 || out.version > snapshot_format_version) {
        return "the snapshot is of a newer format than this library reads";
    }
    if (read_kind != uint32_t(kind)) {
        return kind == SnapshotKind::snapshot ? "the buffer is a rollback state, not a snapshot"
                                              : "the buffer is a snapshot, not a rollback state";
    }
    out.kind = kind;
    if (kind == SnapshotKind::snapshot && (out.world_serial != 0 || out.structure_version != 0)) {
        return "the snapshot's header is corrupted (a field that must be zero is not)";
    }
    if (out.payload_size != size - snapshot_header_size) {
        return out.payload_size > size - snapshot_header_size ? "the snapshot is truncated"
                                                             : "the buffer is longer than its snapshot";
    }
    const unsigned char* payload = static_cast<const unsigned char*>(data) + snapshot_header_size;
    if (checksum64(payload, std::size_t(out.payload_size)) != out.checksum) {
        return "the snapshot is corrupted (its checksum does not match)";
    }
    return nullptr;
}

SectionWriter::SectionWriter(ByteWriter& out, uint32_t tag) : out_(out) {
    out_.u32(tag);
    size_at_ = out_.size();
    out_.u64(0);  // the size, patched when the section ends
}

SectionWriter::~SectionWriter() {
    const uint64_t size = out_.size() - size_at_ - 8;
    for (int i = 0; i < 8; ++i) {
        if (unsigned char* byte = out_.at(size_at_ + std::size_t(i))) {
            *byte = uint8_t(size >> (8 * i));
        }
    }
}

SectionReader::SectionReader(ByteReader& in, uint32_t tag) : in_(in) {
    const uint32_t read_tag = in_.u32();
    const uint64_t size = in_.u64();
    in_.check(read_tag == tag, "a snapshot section is missing or out of order");
    in_.check(size <= in_.remaining(), "a snapshot section is longer than the snapshot");
    end_ = in_.failed() ? in_.position() : in_.position() + std::size_t(size);
}

SectionReader::~SectionReader() { in_.check(in_.position() == end_, "a snapshot section holds more or less than it says"); }

}  // namespace i2d
