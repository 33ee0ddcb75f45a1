// SPDX-License-Identifier: MIT
// The C boundary's exception guard (capi/boundary.hpp): an allocation failure is
// I2D_ERR_OUT_OF_MEMORY, any other exception, a defect no caller can cause or cure, is
// I2D_ERR_INTERNAL with its own message, and neither escapes.
#include <cstring>
#include <new>
#include <stdexcept>

#include "boundary.hpp"
#include "check.h"

using i2d::capi::Call;
using i2d::capi::guarded;

I2D_TEST(unit_guard_bad_alloc_is_out_of_memory) {
    const int result = guarded("i2d_test_call", -1, [](Call&) -> int { throw std::bad_alloc(); });
    I2D_CHECK(result == -1);
    I2D_CHECK(i2d_last_status() == I2D_ERR_OUT_OF_MEMORY);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "out of memory") != nullptr);
}

I2D_TEST(unit_guard_unknown_exception_is_internal_error) {
    const int from_std = guarded("i2d_test_call", -1, [](Call&) -> int { throw std::logic_error("defect"); });
    I2D_CHECK(from_std == -1);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INTERNAL);
    I2D_CHECK(std::strstr(i2d_last_error_message(), "i2d_test_call: internal error") != nullptr);
    const int from_int = guarded("i2d_test_call", -2, [](Call&) -> int { throw 42; });
    I2D_CHECK(from_int == -2);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INTERNAL);
}

I2D_TEST(unit_guard_success_is_ok) {
    const int result = guarded("i2d_test_call", -1, [](Call&) { return 7; });
    I2D_CHECK(result == 7);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(i2d_last_error_message()[0] == '\0');
}
