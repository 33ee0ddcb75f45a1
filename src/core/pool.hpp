// SPDX-License-Identifier: MIT
// Pool: objects in one contiguous array, reused through a free list, with a generation
// per slot so that stale handles are detected.
//
// Design note: handles carry (index, generation). Freeing a slot bumps its generation,
// so every handle to the old object stops matching. A slot whose generation would wrap
// is retired for good rather than reused (reuse after a wrap would let a very old handle
// match again). The alternative, a plain vector with erase, would move objects and
// invalidate indices held by other objects.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace i2d {

constexpr int32_t null_index = -1;

template <class T>
class Pool {
public:
    /// Largest number of slots; keeps index + 1 within the 24 bits a handle has for it.
    static constexpr int32_t max_slots = (1 << 24) - 1;
    static constexpr uint16_t last_generation = 0xFFFF;

    /// Returns the new slot or null_index when the pool is full. May throw bad_alloc.
    int32_t allocate() {
        if (!free_.empty()) {
            int32_t index = free_.back();
            free_.pop_back();
            alive_[index] = 1;
            items_[index] = T{};
            ++count_;
            return index;
        }
        if (static_cast<int32_t>(items_.size()) >= max_slots) {
            return null_index;
        }
        // Grow all arrays geometrically, and before changing any, so that a bad_alloc
        // leaves the pool as it was; the free list gets room for every slot now so that
        // free() never allocates.
        if (items_.size() == items_.capacity()) {
            const std::size_t grown = items_.capacity() < 16 ? 16 : 2 * items_.capacity();
            const std::size_t capacity = grown < std::size_t(max_slots) ? grown : std::size_t(max_slots);
            items_.reserve(capacity);
            generations_.reserve(capacity);
            alive_.reserve(capacity);
            free_.reserve(capacity);
        }
        items_.emplace_back();
        generations_.push_back(1);
        alive_.push_back(1);
        ++count_;
        return static_cast<int32_t>(items_.size()) - 1;
    }

    /// Frees a live slot; its generation moves on so that old handles go stale.
    void free(int32_t index) {
        alive_[index] = 0;
        --count_;
        if (generations_[index] == last_generation) {
            return;  // retired: never handed out again
        }
        ++generations_[index];
        free_.push_back(index);
    }

    bool is_live(int32_t index) const {
        return index >= 0 && index < static_cast<int32_t>(items_.size()) && alive_[index] != 0;
    }
    bool is_live(int32_t index, uint16_t generation) const {
        return is_live(index) && generations_[index] == generation;
    }
    uint16_t generation(int32_t index) const { return generations_[index]; }

    T& operator[](int32_t index) { return items_[index]; }
    const T& operator[](int32_t index) const { return items_[index]; }

    /// Slots ever used (live or not): iterate 0..capacity() and skip dead ones.
    int32_t capacity() const { return static_cast<int32_t>(items_.size()); }
    int32_t count() const { return count_; }

    /// Saves the pool to a SaveIo (core/field_io.hpp): every slot's generation and
    /// liveness, each live item through fields(io, item), and the free list in its order,
    /// so that the slots handed out after a load are the same.
    template <class Io, class Fields>
    void save(Io& io, Fields&& fields) const;
    /// Loads what save wrote from a LoadIo; refuses (io.check) a slot count past
    /// max_slots, a live slot of generation 0 and a free list that names a live slot,
    /// names one twice or leaves the range.
    template <class Io, class Fields>
    void load(Io& io, Fields&& fields);
    void swap(Pool& other) noexcept {
        items_.swap(other.items_);
        generations_.swap(other.generations_);
        alive_.swap(other.alive_);
        free_.swap(other.free_);
        std::swap(count_, other.count_);
    }

private:
    std::vector<T> items_;
    std::vector<uint16_t> generations_;
    std::vector<uint8_t> alive_;
    std::vector<int32_t> free_;
    int32_t count_ = 0;
};

template <class T>
template <class Io, class Fields>
void Pool<T>::save(Io& io, Fields&& fields) const {
    io.count(capacity());
    for (int32_t i = 0; i < capacity(); ++i) {
        io(generations_[std::size_t(i)]);
        io(alive_[std::size_t(i)]);
        if (alive_[std::size_t(i)] != 0) {
            fields(io, items_[std::size_t(i)]);
        }
    }
    io.count(int32_t(free_.size()));
    for (const int32_t index : free_) {
        io(index);
    }
}

template <class T>
template <class Io, class Fields>
void Pool<T>::load(Io& io, Fields&& fields) {
    const int32_t slots = io.count(3, max_slots, "a pool has more slots than the bytes left could hold");
    // Resized, not emptied: a pool loaded again and again (a rollback) neither allocates
    // nor builds every slot afresh. A live slot's item is wholly written as it loads (by
    // fields, or by what its owner derives from the rest); a free slot is never read
    // (allocate() makes it afresh).
    free_.clear();
    count_ = 0;
    items_.resize(std::size_t(slots));
    generations_.resize(std::size_t(slots));
    alive_.resize(std::size_t(slots));
    free_.reserve(std::size_t(slots));
    for (int32_t i = 0; i < slots && !io.failed(); ++i) {
        io(generations_[std::size_t(i)]);
        uint8_t& alive = alive_[std::size_t(i)];
        io(alive);
        io.check(alive <= 1, "a pool slot is neither live nor free");
        if (alive == 1) {
            io.check(generations_[std::size_t(i)] != 0, "a live pool slot has generation 0");
            fields(io, items_[std::size_t(i)]);
            ++count_;
        }
    }
    const int32_t free_count = io.count(4, slots, "a pool's free list is longer than its slots");
    // A listed slot is marked in alive_ while the list is read (no table of its own).
    constexpr uint8_t listed = 2;
    for (int32_t k = 0; k < free_count && !io.failed(); ++k) {
        int32_t index = 0;
        io(index);
        if (!io.check(index >= 0 && index < slots, "a pool's free list names a slot out of range") ||
            !io.check(alive_[std::size_t(index)] == 0, "a pool's free list names a live slot or one slot twice")) {
            break;
        }
        alive_[std::size_t(index)] = listed;
        free_.push_back(index);
    }
    for (const int32_t index : free_) {
        alive_[std::size_t(index)] = 0;
    }
}

}  // namespace i2d
