// SPDX-License-Identifier: MIT
// Chain segments from a chain's points.
#include "dynamics/body/chain.hpp"

namespace i2d {

// An open chain's segment i runs from point i + 1 to point i + 2 (point 0 and the last
// point are ghosts); a loop's from point i to point i + 1, wrapping around.
ChainSegment chain_segment_geometry(const ChainDef& def, int32_t segment) {
    const int32_t n = def.count;
    const int32_t first = def.is_loop ? segment : segment + 1;
    auto at = [&](int32_t i) { return def.points[((i % n) + n) % n]; };
    return ChainSegment{at(first - 1), at(first), at(first + 1), at(first + 2)};
}

}  // namespace i2d
