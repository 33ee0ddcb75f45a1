// SPDX-License-Identifier: MIT
// The element checks that the bulk state calls share (bulk_state_api.cpp for one world,
// batch_state_api.cpp across worlds): the elements' names are formatted only once one is
// known to be bad, since formatting costs far more than checking.
#pragma once

#include <cmath>
#include <cstdio>

#include "boundary.hpp"

namespace i2d::capi {

/// "<array>[i]", for messages.
struct ElementName {
    char text[48];
    ElementName(const char* array, int32_t i) { std::snprintf(text, sizeof text, "%s[%d]", array, i); }
};

/// A count of at least 0, with its array when it is above 0.
inline bool valid_count(Call& call, int32_t count, const void* items, const char* items_name) {
    if (count < 0) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "count is %d; it must be >= 0", count);
    }
    return count == 0 || call.not_null(items, items_name);
}

/// Every given velocity finite (either array may be NULL).
inline bool valid_velocities(Call& call, int32_t count, const i2d_vec2* linear, const float* angular) {
    for (int32_t i = 0; linear != nullptr && i < count; ++i) {
        if (!(std::isfinite(linear[i].x) && std::isfinite(linear[i].y))) {
            return call.finite(linear[i], ElementName("linear", i).text);
        }
    }
    for (int32_t i = 0; angular != nullptr && i < count; ++i) {
        if (!std::isfinite(angular[i])) {
            return call.finite(angular[i], ElementName("angular", i).text);
        }
    }
    return true;
}

}  // namespace i2d::capi
