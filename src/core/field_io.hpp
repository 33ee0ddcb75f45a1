// SPDX-License-Identifier: MIT
// SaveIo and LoadIo: one description of a struct's fields serves both directions.
//
// Design note: each saved struct has one function template listing its fields,
// `template <class Io, class T> void fields(Io& io, T& value)`, called with SaveIo and a
// const value to save, or with LoadIo and a value to fill. The two can then never
// disagree on the order or the width of a field. Every value goes as little-endian bits
// (byte_stream.hpp); a loaded float must be finite and an enum within its range, so that
// no NaN box reaches a tree build and no switch meets a kind it does not know. User data
// travels as its 64-bit value; one that does not fit this platform's pointers is refused.
#pragma once

#include <cstdint>
#include <cmath>
#include <type_traits>

#include "core/byte_stream.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// The fields of a save, each through the writer Out's encodings (LittleEndianWriter).
template <class Out>
class FieldWriter {
public:
    static constexpr bool loading = false;
    explicit FieldWriter(Out& out) : out_(out) {}

    /// Whether the bytes have the fields a format version added: a save writes the newest.
    bool has_version(uint32_t) const { return true; }

    void operator()(const float& v) { out_.f32(v); }
    void operator()(const int32_t& v) { out_.i32(v); }
    void operator()(const uint32_t& v) { out_.u32(v); }
    void operator()(const int16_t& v) { out_.u16(uint16_t(v)); }
    void operator()(const uint16_t& v) { out_.u16(v); }
    void operator()(const uint8_t& v) { out_.u8(v); }
    void operator()(const uint64_t& v) { out_.u64(v); }
    void operator()(const bool& v) { out_.boolean(v); }
    void operator()(void* const& v) { out_.u64(uint64_t(reinterpret_cast<uintptr_t>(v))); }
    template <class E, class = std::enable_if_t<std::is_enum<E>::value>>
    void operator()(const E& v) {
        out_.u8(uint8_t(v));
    }
    void operator()(const Vec2& v) {
        out_.f32(v.x);
        out_.f32(v.y);
    }
    void operator()(const Rot& v) {
        out_.f32(v.c);
        out_.f32(v.s);
    }
    void operator()(const Transform& v) {
        (*this)(v.p);
        (*this)(v.q);
    }
    void operator()(const AABB& v) {
        (*this)(v.lower);
        (*this)(v.upper);
    }
    /// A count of the items that follow.
    void count(int32_t n) { out_.i32(n); }
    /// The one check a save has: none (what a world holds is valid); for symmetry.
    bool check(bool, const char*) { return true; }
    bool failed() const { return false; }

protected:
    Out& out_;
};

class SaveIo : public FieldWriter<ByteWriter> {
public:
    explicit SaveIo(ByteWriter& out) : FieldWriter<ByteWriter>(out) {}
    ByteWriter& bytes() { return out_; }
};

/// Saves one struct of at most Capacity bytes through fields(staged_io), staged in the
/// stack (StagedBytes) and handed to `io` whole: the hot loops of a save (a contact's
/// forty fields) then keep their place in a register.
template <std::size_t Capacity, class Fields>
void save_staged(SaveIo& io, Fields&& fields) {
    StagedBytes<Capacity> staged;
    FieldWriter<StagedBytes<Capacity>> staged_io(staged);
    fields(staged_io);
    io.bytes().bytes(staged.data(), staged.size());
}

class LoadIo {
public:
    static constexpr bool loading = true;
    /// `version`: the format version of the bytes, for formats that grew fields.
    explicit LoadIo(ByteReader& in, uint32_t version = UINT32_MAX) : in_(in), version_(version) {}

    /// Whether the bytes have the fields a format version added.
    bool has_version(uint32_t version) const { return version_ >= version; }

    void operator()(float& v) {
        v = in_.f32();
        in_.check(std::isfinite(v), "a value is not finite");
    }
    void operator()(int32_t& v) { v = in_.i32(); }
    void operator()(uint32_t& v) { v = in_.u32(); }
    void operator()(int16_t& v) { v = int16_t(in_.u16()); }
    void operator()(uint16_t& v) { v = in_.u16(); }
    void operator()(uint8_t& v) { v = in_.u8(); }
    void operator()(uint64_t& v) { v = in_.u64(); }
    void operator()(bool& v) { v = in_.boolean(); }
    void operator()(void*& v) {
        const uint64_t bits = in_.u64();
        in_.check(bits == uint64_t(uintptr_t(bits)), "a user data value does not fit a pointer on this platform");
        v = reinterpret_cast<void*>(uintptr_t(bits));
    }
    /// Enums with a trailing `count` member.
    template <class E, class = std::enable_if_t<std::is_enum<E>::value>>
    void operator()(E& v) {
        const uint8_t raw = in_.u8();
        in_.check(raw < uint8_t(E::count), "a kind or type is out of range");
        v = in_.failed() ? E{} : E(raw);
    }
    void operator()(Vec2& v) {
        (*this)(v.x);
        (*this)(v.y);
    }
    void operator()(Rot& v) {
        (*this)(v.c);
        (*this)(v.s);
    }
    void operator()(Transform& v) {
        (*this)(v.p);
        (*this)(v.q);
    }
    void operator()(AABB& v) {
        (*this)(v.lower);
        (*this)(v.upper);
    }
    /// A count of items that follow, each at least min_item_bytes long, at most limit.
    int32_t count(std::size_t min_item_bytes, int32_t limit, const char* what) {
        return in_.count(min_item_bytes, limit, what);
    }
    bool check(bool ok, const char* problem) { return in_.check(ok, problem); }
    bool failed() const { return in_.failed(); }
    ByteReader& bytes() { return in_; }

private:
    ByteReader& in_;
    uint32_t version_;
};

/// A list of indices or small values: its length, then each.
template <class Io, class List>
void list_fields(Io& io, List& list, int32_t limit, const char* too_long) {
    if constexpr (!Io::loading) {
        io.count(int32_t(list.size()));
    } else {
        list.resize(std::size_t(io.count(sizeof(list[0]), limit, too_long)));
    }
    for (auto& item : list) {
        io(item);
    }
}

}  // namespace i2d
