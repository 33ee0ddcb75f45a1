// SPDX-License-Identifier: MIT
// i2d_collide_*: the pure collision functions, checked and handed to the core.
#include <cmath>

#include "boundary.hpp"
#include "collision/manifold.hpp"
#include "convert.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

bool valid_circle(Call& call, const i2d_circle& c, const char* what) {
    if (!call.finite(c.center, what) || !call.finite(c.radius, what)) {
        return false;
    }
    if (c.radius < 0.0f) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s radius is %g; it must be >= 0", what,
                         static_cast<double>(c.radius));
    }
    return true;
}

bool valid_aabb(Call& call, const i2d_aabb& a, const char* what) {
    if (!call.finite(a.min, what) || !call.finite(a.max, what)) {
        return false;
    }
    if (a.min.x > a.max.x || a.min.y > a.max.y) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s has min above or right of max", what);
    }
    return true;
}

i2d_manifold to_public(const Manifold& m) {
    i2d_manifold out{};
    out.normal = capi::to_public(m.normal);
    out.point_count = m.point_count;
    for (int32_t i = 0; i < m.point_count; ++i) {
        out.points[i].point = capi::to_public(m.points[i].point);
        out.points[i].penetration = m.points[i].penetration;
        out.points[i].id = m.points[i].id;
    }
    return out;
}

}  // namespace

I2D_API i2d_manifold i2d_collide_circles(i2d_circle a, i2d_circle b) {
    return guarded("i2d_collide_circles", i2d_manifold{}, [&](Call& call) {
        if (!valid_circle(call, a, "circle a") || !valid_circle(call, b, "circle b")) {
            return i2d_manifold{};
        }
        return to_public(collide_circles(capi::to_core(a.center), a.radius, capi::to_core(b.center), b.radius));
    });
}

I2D_API i2d_manifold i2d_collide_aabbs(i2d_aabb a, i2d_aabb b) {
    return guarded("i2d_collide_aabbs", i2d_manifold{}, [&](Call& call) {
        if (!valid_aabb(call, a, "aabb a") || !valid_aabb(call, b, "aabb b")) {
            return i2d_manifold{};
        }
        return to_public(collide_aabbs(capi::to_core(a), capi::to_core(b)));
    });
}

I2D_API i2d_manifold i2d_collide_aabb_circle(i2d_aabb a, i2d_circle b) {
    return guarded("i2d_collide_aabb_circle", i2d_manifold{}, [&](Call& call) {
        if (!valid_aabb(call, a, "aabb a") || !valid_circle(call, b, "circle b")) {
            return i2d_manifold{};
        }
        return to_public(collide_aabb_circle(capi::to_core(a), capi::to_core(b.center), b.radius));
    });
}
