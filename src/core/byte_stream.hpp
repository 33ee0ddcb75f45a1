// SPDX-License-Identifier: MIT
// ByteWriter and ByteReader: values as little-endian bytes, the same on every platform,
// for snapshots of a world.
//
// Design note: the writer either writes into a caller's buffer or only counts, so that
// the size a save will need comes from the very code that saves (no second description
// of the format to fall out of step). The reader never reads past its end and never
// throws: the first problem (too few bytes, a count larger than the bytes left could
// hold, a value out of its range) is kept with a message, and every read after it gives
// zero, so that a loader can read on to its end and check once. Floats travel as their
// bits: a snapshot restores the exact values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/assert.hpp"

namespace i2d {

/// An unsigned integer's bytes in little-endian order, as the host holds them: unchanged
/// on a little-endian host, swapped on a big-endian one (the swap is its own inverse).
template <class U>
U to_little_endian(U v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    U swapped = 0;
    for (std::size_t i = 0; i < sizeof v; ++i) {
        swapped = U(swapped << 8) | U(v & 0xff);
        v = U(v >> 8);
    }
    return swapped;
#else
    return v;
#endif
}

/// The encodings a writer offers, each value as its little-endian bytes, over the
/// derived writer's put(data, size).
template <class Derived>
class LittleEndianWriter {
public:
    void u8(uint8_t v) { self().put(&v, 1); }
    void u16(uint16_t v) { put_little_endian(v); }
    void u32(uint32_t v) { put_little_endian(v); }
    void u64(uint64_t v) { put_little_endian(v); }
    void i32(int32_t v) { u32(uint32_t(v)); }
    void f32(float v) {
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    void boolean(bool v) { u8(v ? 1 : 0); }
    void bytes(const void* data, std::size_t size) { self().put(data, size); }

private:
    Derived& self() { return static_cast<Derived&>(*this); }
    template <class U>
    void put_little_endian(U v) {
        v = to_little_endian(v);
        self().put(&v, sizeof v);
    }
};

class ByteWriter : public LittleEndianWriter<ByteWriter> {
public:
    /// Counts the bytes only.
    ByteWriter() = default;
    /// Writes into [buffer, buffer + capacity); past the end it only counts, and
    /// overflowed() says so.
    ByteWriter(void* buffer, std::size_t capacity) : out_(static_cast<unsigned char*>(buffer)), capacity_(capacity) {}
    /// Appends to `grow`, which grows as needed (a recording's records).
    explicit ByteWriter(std::vector<unsigned char>& grow) : grow_(&grow) {}

    /// Bytes written (or counted) so far.
    std::size_t size() const { return size_; }
    bool overflowed() const { return grow_ == nullptr && size_ > capacity_; }
    /// Where byte `offset` went, for patching a length written before its content.
    unsigned char* at(std::size_t offset) const {
        if (grow_ != nullptr) {
            return offset < grow_->size() ? grow_->data() + offset : nullptr;
        }
        return out_ != nullptr && offset < capacity_ ? out_ + offset : nullptr;
    }

    void put(const void* data, std::size_t size) {
        if (out_ != nullptr && size_ + size <= capacity_) {
            std::memcpy(out_ + size_, data, size);
        } else if (grow_ != nullptr) {
            const auto* bytes = static_cast<const unsigned char*>(data);
            grow_->insert(grow_->end(), bytes, bytes + size);
        }
        size_ += size;
    }

private:
    unsigned char* out_ = nullptr;
    std::vector<unsigned char>* grow_ = nullptr;
    std::size_t capacity_ = 0;
    std::size_t size_ = 0;
};

/// Up to Capacity bytes kept in the writer itself, for one struct's fields, handed on
/// whole. A byte written through ByteWriter's pointer may, for all the compiler knows,
/// change the writer's own size, so each field reloaded it; bytes written into this
/// writer's own array cannot, and its size stays in a register.
template <std::size_t Capacity>
class StagedBytes : public LittleEndianWriter<StagedBytes<Capacity>> {
public:
    void put(const void* data, std::size_t size) {
        I2D_ASSERT(size <= Capacity - size_);
        std::memcpy(bytes_ + size_, data, size);
        size_ += size;
    }
    const unsigned char* data() const { return bytes_; }
    std::size_t size() const { return size_; }

private:
    unsigned char bytes_[Capacity];
    std::size_t size_ = 0;
};

class ByteReader {
public:
    ByteReader(const void* data, std::size_t size) : in_(static_cast<const unsigned char*>(data)), size_(size) {}

    uint8_t u8() {
        unsigned char b[1] = {};
        take(b, 1);
        return b[0];
    }
    uint16_t u16() { return take_little_endian<uint16_t>(); }
    uint32_t u32() { return take_little_endian<uint32_t>(); }
    uint64_t u64() { return take_little_endian<uint64_t>(); }
    int32_t i32() { return int32_t(u32()); }
    float f32() {
        const uint32_t bits = u32();
        float v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    /// A bool must be 0 or 1.
    bool boolean() {
        const uint8_t v = u8();
        check(v <= 1, "a flag is neither 0 nor 1");
        return v == 1;
    }
    void bytes(void* out, std::size_t size) { take(out, size); }
    /// A count of items that take at least min_item_bytes each, at most `limit`: one that
    /// the bytes left cannot hold is refused before anything is sized by it.
    int32_t count(std::size_t min_item_bytes, int32_t limit, const char* what);

    /// Records the problem, unless one was recorded already; returns `ok`.
    bool check(bool ok, const char* problem) {
        if (!ok && error_ == nullptr) {
            error_ = problem;
        }
        return ok;
    }
    bool failed() const { return error_ != nullptr; }
    const char* error() const { return error_; }
    std::size_t position() const { return position_; }
    std::size_t remaining() const { return size_ - position_; }

private:
    template <class U>
    U take_little_endian() {
        U v = 0;
        take(&v, sizeof v);
        return to_little_endian(v);
    }

    void take(void* out, std::size_t size) {
        if (failed() || size > remaining()) {
            check(false, "the data ends early (truncated)");
            std::memset(out, 0, size);
            return;
        }
        std::memcpy(out, in_ + position_, size);
        position_ += size;
    }

    const unsigned char* in_;
    std::size_t size_;
    std::size_t position_ = 0;
    const char* error_ = nullptr;
};

inline int32_t ByteReader::count(std::size_t min_item_bytes, int32_t limit, const char* what) {
    const int32_t n = i32();
    const bool fits = n >= 0 && n <= limit && (min_item_bytes == 0 || std::size_t(n) <= remaining() / min_item_bytes);
    return check(fits, what) ? n : 0;
}

}  // namespace i2d
