// SPDX-License-Identifier: MIT
// i2d_shape_distance and i2d_shape_get_closest_point: the closest points of two proxies,
// and of a world's shape to a point, checked and handed to the core.
#include "boundary.hpp"
#include "collision/shape_proxy.hpp"
#include "convert.hpp"
#include "geometry_checks.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// A transform as the pure functions take it (valid_transform), its rotation then made
// exactly unit so that rounding in the caller's cos and sin never scales the shape.
bool placement(Call& call, const i2d_transform& xf, const char* what, Transform& out) {
    if (!valid_transform(call, xf, what)) {
        return false;
    }
    out = {to_core(xf.p), normalize(to_core(xf.q))};
    return true;
}

}  // namespace

I2D_API i2d_distance_result i2d_shape_distance(const i2d_shape_proxy* a, i2d_transform xa, const i2d_shape_proxy* b,
                                               i2d_transform xb) {
    return guarded("i2d_shape_distance", i2d_distance_result{}, [&](Call& call) {
        ShapeProxy core_a, core_b;
        Transform place_a, place_b;
        if (!core_proxy(call, a, core_a, "proxy a") || !placement(call, xa, "xa", place_a) ||
            !core_proxy(call, b, core_b, "proxy b") || !placement(call, xb, "xb", place_b)) {
            return i2d_distance_result{};
        }
        const SurfaceDistance d = surface_distance(core_a, place_a, core_b, place_b);
        return i2d_distance_result{to_public(d.point_a), to_public(d.point_b), to_public(d.normal), d.distance};
    });
}

// A getter: it reads the shape where the last step or call left it, and works inside
// query callbacks.
I2D_API i2d_vec2 i2d_shape_get_closest_point(i2d_shape_id id, i2d_vec2 target) {
    return guarded("i2d_shape_get_closest_point", i2d_vec2{}, [&](Call& call) {
        ShapeRef s;
        if (!call.shape(id, s) || !call.coordinate(target, "target")) {
            return i2d_vec2{};
        }
        const Shape& shape = s.shape();
        const Transform& xf = s.world->bodies()[shape.body].transform;
        return to_public(closest_point(make_shape_proxy(shape.geometry), xf, to_core(target)));
    });
}
