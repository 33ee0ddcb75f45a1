// SPDX-License-Identifier: MIT
// Chain: a polyline of one-sided segments (level geometry), each a shape of its body.
//
// Design note: a chain owns no geometry of its own; its segments are ordinary shapes of
// kind chain_segment, each knowing its neighbours (collision/shapes.hpp, ghost points),
// so the broadphase, the narrowphase, queries and events treat them like any shape. The
// chain only keeps the list of its segment shapes, so that it is created and destroyed
// as one. The list is allocated once at creation, never in a step.
#pragma once

#include <cstdint>
#include <vector>

#include "dynamics/body/shape.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// Material of one chain segment (the C API's i2d_surface_material).
struct SurfaceMaterial {
    float friction = 0.6f;
    float restitution = 0.0f;
    float rolling_resistance = 0.0f;
    float tangent_speed = 0.0f;
};

struct ChainDef {
    const Vec2* points = nullptr;  // open: the first and last are ghosts only
    int32_t count = 0;
    bool is_loop = false;
    const SurfaceMaterial* materials = nullptr;  // none, one for all, or one per segment
    int32_t material_count = 0;
    Filter filter;
    bool enable_sensor_events = true;
    void* user_data = nullptr;
};

struct Chain {
    int32_t body = null_index;
    std::vector<int32_t> shapes;  // the segments, in chain order
    bool is_loop = false;
    void* user_data = nullptr;
};

/// Segments a chain of `count` points has: count - 3 open (the ends are ghosts), count
/// closed.
inline int32_t chain_segment_count(int32_t count, bool is_loop) { return is_loop ? count : count - 3; }

/// The geometry of segment i: points i, i + 1 of the segment list with their neighbours.
ChainSegment chain_segment_geometry(const ChainDef& def, int32_t segment);

}  // namespace i2d
