// SPDX-License-Identifier: MIT
// LinkChange: a contact that began or stopped linking two bodies into one island, as the
// contact set hands it to the islands (island.hpp).
#pragma once

#include <cstdint>

namespace i2d {

struct LinkChange {
    int32_t body_a = -1, body_b = -1;
    bool links = false;  // true: began linking the two; false: body_a's island lost a link
};

}  // namespace i2d
