// SPDX-License-Identifier: MIT
// Pool: slots are reused through the free list, generations make old handles stale,
// a slot whose generation is used up is retired, and a load gives back what a save held.
#include <initializer_list>
#include <vector>

#include "check.h"
#include "core/field_io.hpp"
#include "core/pool.hpp"

using i2d::Pool;

I2D_TEST(unit_pool_allocate_reuses_freed_slots) {
    Pool<int> pool;
    const int32_t a = pool.allocate();
    const int32_t b = pool.allocate();
    I2D_CHECK(a == 0 && b == 1);
    I2D_CHECK(pool.count() == 2);
    pool[a] = 42;
    pool.free(a);
    I2D_CHECK(pool.count() == 1);
    I2D_CHECK(!pool.is_live(a));
    const int32_t c = pool.allocate();
    I2D_CHECK(c == a);
    I2D_CHECK(pool[c] == 0);  // a reused slot starts from a fresh value
    I2D_CHECK(pool.capacity() == 2);
}

I2D_TEST(unit_pool_generation_makes_old_handles_stale) {
    Pool<int> pool;
    const int32_t a = pool.allocate();
    const uint16_t first = pool.generation(a);
    I2D_CHECK(pool.is_live(a, first));
    pool.free(a);
    I2D_CHECK(!pool.is_live(a, first));
    const int32_t again = pool.allocate();
    I2D_CHECK(again == a);
    I2D_CHECK(pool.generation(again) != first);
    I2D_CHECK(!pool.is_live(again, first));
    I2D_CHECK(pool.is_live(again, pool.generation(again)));
}

I2D_TEST(unit_pool_out_of_range_is_not_live) {
    Pool<int> pool;
    I2D_CHECK(!pool.is_live(-1));
    I2D_CHECK(!pool.is_live(0));
    pool.allocate();
    I2D_CHECK(!pool.is_live(1));
    I2D_CHECK(!pool.is_live(123456, 1));
}

I2D_TEST(unit_pool_retires_slot_when_generation_is_used_up) {
    Pool<int> pool;
    const int32_t a = pool.allocate();
    // Cycle the slot until its generation reaches the last value.
    while (pool.generation(a) != Pool<int>::last_generation) {
        pool.free(a);
        I2D_REQUIRE(pool.allocate() == a);
    }
    const uint16_t last = pool.generation(a);
    pool.free(a);
    const int32_t next = pool.allocate();
    I2D_CHECK(next != a);  // retired, never handed out again
    I2D_CHECK(!pool.is_live(a, last));
    I2D_CHECK(pool.count() == 1);
}

namespace {

// A pool of int32_t saved and loaded through field_io, as the snapshots do.
const auto int_fields = [](auto& io, auto& value) { io(value); };

std::vector<unsigned char> saved(const Pool<int32_t>& pool) {
    std::vector<unsigned char> bytes;
    i2d::ByteWriter writer(bytes);
    i2d::SaveIo io(writer);
    pool.save(io, int_fields);
    return bytes;
}

const char* load(Pool<int32_t>& pool, const std::vector<unsigned char>& bytes) {
    i2d::ByteReader reader(bytes.data(), bytes.size());
    i2d::LoadIo io(reader);
    pool.load(io, int_fields);
    return reader.error();
}

// Three slots, the middle one free: (generation, alive, value) each, then the free list.
std::vector<unsigned char> three_slots(std::initializer_list<int32_t> free_list) {
    std::vector<unsigned char> bytes;
    i2d::ByteWriter writer(bytes);
    i2d::SaveIo io(writer);
    io.count(3);
    io(uint16_t(1)), io(uint8_t(1)), io(int32_t(10));
    io(uint16_t(2)), io(uint8_t(0));
    io(uint16_t(1)), io(uint8_t(1)), io(int32_t(30));
    io.count(int32_t(free_list.size()));
    for (const int32_t index : free_list) {
        io(index);
    }
    return bytes;
}

}  // namespace

// A load into a pool that held other items gives the saved slots back, generations and
// free list in order, and the slots it hands out next start from fresh values.
I2D_TEST(unit_pool_load_gives_back_the_saved_slots_over_what_the_pool_held) {
    Pool<int32_t> saved_pool;
    for (int32_t i = 0; i < 4; ++i) {
        saved_pool[saved_pool.allocate()] = 100 + i;
    }
    saved_pool.free(1);
    saved_pool.free(3);
    Pool<int32_t> pool;
    for (int32_t i = 0; i < 6; ++i) {
        pool[pool.allocate()] = -7;
    }
    I2D_REQUIRE(load(pool, saved(saved_pool)) == nullptr);
    I2D_CHECK(pool.capacity() == 4 && pool.count() == 2);
    I2D_CHECK(pool.is_live(0, saved_pool.generation(0)) && pool[0] == 100);
    I2D_CHECK(pool.is_live(2, saved_pool.generation(2)) && pool[2] == 102);
    I2D_CHECK(!pool.is_live(1) && !pool.is_live(3));
    // The free list keeps its order: the last freed is handed out first, as in the saved pool.
    const int32_t next = pool.allocate(), after = pool.allocate();
    I2D_CHECK(next == saved_pool.allocate() && after == saved_pool.allocate());
    I2D_CHECK(next == 3 && after == 1);
    I2D_CHECK(pool[next] == 0 && pool[after] == 0);
    I2D_CHECK(pool.generation(next) == saved_pool.generation(next));
}

I2D_TEST(unit_pool_load_refuses_a_free_list_naming_a_live_slot_or_one_twice) {
    Pool<int32_t> pool;
    I2D_CHECK(load(pool, three_slots({1})) == nullptr);
    I2D_CHECK(pool.count() == 2 && pool.allocate() == 1);
    I2D_CHECK(load(pool, three_slots({1, 1})) != nullptr);
    I2D_CHECK(load(pool, three_slots({0})) != nullptr);
    I2D_CHECK(load(pool, three_slots({3})) != nullptr);
    // A refused list leaves no slot marked: the good bytes load as before.
    I2D_CHECK(load(pool, three_slots({1})) == nullptr);
    I2D_CHECK(pool.count() == 2 && !pool.is_live(1) && pool.allocate() == 1);
}
