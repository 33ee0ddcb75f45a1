// SPDX-License-Identifier: MIT
// Pool: slots are reused through the free list, generations make old handles stale,
// and a slot whose generation is used up is retired.
#include "check.h"
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
