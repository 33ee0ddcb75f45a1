// SPDX-License-Identifier: MIT
// World::validate: cross-checks bodies, shapes and their links (I2D_VALIDATE builds).
#include <cmath>

#include "core/assert.hpp"
#include "dynamics/world.hpp"
#include "math/math.hpp"

namespace i2d {

void World::validate() const {
#if defined(I2D_VALIDATE)
    int32_t shapes_seen = 0;
    for (int32_t i = 0; i < bodies.capacity(); ++i) {
        if (!bodies.is_live(i)) {
            continue;
        }
        const Body& b = bodies[i];
        I2D_ASSERT(is_finite(b.transform.p) && is_finite(b.center) && is_finite(b.linear_velocity));
        I2D_ASSERT(std::isfinite(b.mass) && std::isfinite(b.inv_mass));
        I2D_ASSERT(b.type == BodyType::dynamic ? b.mass > 0.0f : b.inv_mass == 0.0f);
        int32_t count = 0;
        int32_t prev = null_index;
        for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
            I2D_ASSERT(shapes.is_live(s));
            I2D_ASSERT(shapes[s].body == i);
            I2D_ASSERT(shapes[s].prev_in_body == prev);
            I2D_ASSERT(count <= b.shape_count);  // no cycle
            prev = s;
            ++count;
        }
        I2D_ASSERT(count == b.shape_count);
        shapes_seen += count;
    }
    I2D_ASSERT(shapes_seen == shapes.count());
    for (int32_t i = 0; i < shapes.capacity(); ++i) {
        if (shapes.is_live(i)) {
            const AABB& box = shapes[i].aabb;
            I2D_ASSERT(is_finite(box.lower) && is_finite(box.upper));
            I2D_ASSERT(box.lower.x <= box.upper.x && box.lower.y <= box.upper.y);
        }
    }
#endif
}

}  // namespace i2d
