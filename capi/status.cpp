// SPDX-License-Identifier: MIT
// Thread-local last status and message; i2d_status_string and the status getters.
#include "status.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace i2d::capi {

namespace {
thread_local i2d_status t_status = I2D_OK;
thread_local char t_message[512] = "";
}  // namespace

void set_ok() {
    t_status = I2D_OK;
    t_message[0] = '\0';
}

void set_error(i2d_status status, const char* function, const char* format, ...) {
    t_status = status;
    int used = std::snprintf(t_message, sizeof t_message, "%s: ", function);
    if (used < 0 || used >= static_cast<int>(sizeof t_message)) {
        return;
    }
    va_list args;
    va_start(args, format);
    std::vsnprintf(t_message + used, sizeof t_message - static_cast<size_t>(used), format, args);
    va_end(args);
}

i2d_status last_status() { return t_status; }

}  // namespace i2d::capi

using namespace i2d::capi;

// Read as an integer: C callers can pass any int (139, -1), and switching on an
// out-of-range value loaded as the C++ enum type is undefined behaviour.
I2D_API const char* i2d_status_string(i2d_status status) {
    static_assert(sizeof(i2d_status) == sizeof(int32_t), "enums are 32-bit");
    int32_t value = 0;
    std::memcpy(&value, &status, sizeof value);
    switch (value) {
        case I2D_OK: return "I2D_OK";
        case I2D_ERR_INVALID_ARGUMENT: return "I2D_ERR_INVALID_ARGUMENT";
        case I2D_ERR_INVALID_HANDLE: return "I2D_ERR_INVALID_HANDLE";
        case I2D_ERR_WORLD_LOCKED: return "I2D_ERR_WORLD_LOCKED";
        case I2D_ERR_CAPACITY: return "I2D_ERR_CAPACITY";
        case I2D_ERR_OUT_OF_MEMORY: return "I2D_ERR_OUT_OF_MEMORY";
        case I2D_ERR_INTERNAL: return "I2D_ERR_INTERNAL";
        case I2D_ERR_INVALID_SNAPSHOT: return "I2D_ERR_INVALID_SNAPSHOT";
        default: return "I2D_UNKNOWN_STATUS";
    }
}

// These two report on the previous call, so they leave the status as it is.
I2D_API i2d_status i2d_last_status(void) { return t_status; }
I2D_API const char* i2d_last_error_message(void) { return t_message; }

I2D_API uint32_t i2d_version(void) {
    set_ok();
    return I2D_VERSION;
}
