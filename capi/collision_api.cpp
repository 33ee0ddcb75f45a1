// SPDX-License-Identifier: MIT
// i2d_collide_*, i2d_make_*, i2d_compute_*_mass, i2d_ray_cast_*: the pure collision
// functions, checked and handed to the core.
#include <cmath>
#include <type_traits>

#include "boundary.hpp"
#include "geometry_checks.hpp"
#include "collision/collision_constants.hpp"
#include "collision/geometry.hpp"
#include "collision/hull.hpp"
#include "collision/manifold.hpp"
#include "convert.hpp"
#include "limits.hpp"

using namespace i2d;
using namespace i2d::capi;

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
        if (!valid_collide_aabb(call, a, "aabb a") || !valid_collide_aabb(call, b, "aabb b")) {
            return i2d_manifold{};
        }
        return to_public(collide_aabbs(capi::to_core(a), capi::to_core(b)));
    });
}

I2D_API i2d_manifold i2d_collide_aabb_circle(i2d_aabb a, i2d_circle b) {
    return guarded("i2d_collide_aabb_circle", i2d_manifold{}, [&](Call& call) {
        if (!valid_collide_aabb(call, a, "aabb a") || !valid_circle(call, b, "circle b")) {
            return i2d_manifold{};
        }
        return to_public(collide_aabb_circle(capi::to_core(a), capi::to_core(b.center), b.radius));
    });
}

// ---- Polygons and boxes ------------------------------------------------------------

I2D_API i2d_status i2d_make_polygon(const i2d_vec2* points, int32_t count, float radius, i2d_polygon* out) {
    return guarded("i2d_make_polygon", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        if (!call.not_null(points, "points") || !call.not_null(out, "out")) {
            return last_status();
        }
        if (count < 3 || count > max_polygon_vertices) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "count is %d; it must be 3 to 8", static_cast<int>(count));
            return last_status();
        }
        Vec2 core[max_polygon_vertices];
        for (int32_t i = 0; i < count; ++i) {
            if (!call.coordinate(points[i], "points")) {
                return last_status();
            }
            core[i] = capi::to_core(points[i]);
        }
        if (!valid_radius(call, radius, "polygon")) {
            return last_status();
        }
        Hull hull;
        const HullStatus status = compute_hull(core, count, hull);
        if (status != HullStatus::ok) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "polygon: %s", hull_status_message(status));
            return last_status();
        }
        *out = to_public(make_polygon(hull, radius));
        return I2D_OK;
    });
}

I2D_API i2d_polygon i2d_make_box(float half_width, float half_height) {
    return guarded("i2d_make_box", i2d_polygon{}, [&](Call& call) {
        if (!call.extent(half_width, "half_width") || !call.extent(half_height, "half_height")) {
            return i2d_polygon{};
        }
        return to_public(make_box(half_width, half_height));
    });
}

I2D_API i2d_polygon i2d_make_offset_box(float half_width, float half_height, i2d_vec2 center, i2d_rot rotation) {
    return guarded("i2d_make_offset_box", i2d_polygon{}, [&](Call& call) {
        if (!call.extent(half_width, "half_width") || !call.extent(half_height, "half_height") ||
            !call.coordinate(center, "center") || !valid_transform(call, i2d_transform{center, rotation}, "offset box")) {
            return i2d_polygon{};
        }
        return to_public(make_offset_box(half_width, half_height, capi::to_core(center), capi::to_core(rotation)));
    });
}

// ---- Mass ---------------------------------------------------------------------------

namespace {

bool valid_density(Call& call, float density) { return call.in_range(density, 0.0f, max_density, "density"); }

Geometry geometry_of(const Circle& c) { Geometry g; g.type = ShapeType::circle; g.circle = c; return g; }
Geometry geometry_of(const Capsule& c) { Geometry g; g.type = ShapeType::capsule; g.capsule = c; return g; }
Geometry geometry_of(const Segment& s) { Geometry g; g.type = ShapeType::segment; g.segment = s; return g; }
Geometry geometry_of(const Polygon& p) { Geometry g; g.type = ShapeType::polygon; g.polygon = p; return g; }

}  // namespace

I2D_API i2d_mass_data i2d_compute_circle_mass(const i2d_circle* shape, float density) {
    return guarded("i2d_compute_circle_mass", i2d_mass_data{}, [&](Call& call) {
        if (!valid_circle_ptr(call, shape, "circle") || !valid_density(call, density)) {
            return i2d_mass_data{};
        }
        return to_public(compute_mass(geometry_of(to_core(*shape)), density));
    });
}

I2D_API i2d_mass_data i2d_compute_capsule_mass(const i2d_capsule* shape, float density) {
    return guarded("i2d_compute_capsule_mass", i2d_mass_data{}, [&](Call& call) {
        if (!valid_capsule(call, shape, "capsule") || !valid_density(call, density)) {
            return i2d_mass_data{};
        }
        return to_public(compute_mass(geometry_of(to_core(*shape)), density));
    });
}

I2D_API i2d_mass_data i2d_compute_polygon_mass(const i2d_polygon* shape, float density) {
    return guarded("i2d_compute_polygon_mass", i2d_mass_data{}, [&](Call& call) {
        if (!valid_polygon(call, shape, "polygon") || !valid_density(call, density)) {
            return i2d_mass_data{};
        }
        return to_public(compute_mass(geometry_of(to_core(*shape)), density));
    });
}

// ---- Ray casts ----------------------------------------------------------------------

namespace {

template <class Shape>
i2d_cast_output cast_checked(Call& call, const Shape& shape, i2d_transform xf, i2d_vec2 origin, i2d_vec2 translation) {
    if (!valid_transform(call, xf, "transform") || !call.finite(origin, "origin") ||
        !call.finite(translation, "translation")) {
        return i2d_cast_output{};
    }
    return to_public(ray_cast(geometry_of(to_core(shape)), to_core(xf), capi::to_core(origin),
                              capi::to_core(translation), 1.0f));
}

}  // namespace

I2D_API i2d_cast_output i2d_ray_cast_circle(const i2d_circle* shape, i2d_transform xf, i2d_vec2 origin,
                                            i2d_vec2 translation) {
    return guarded("i2d_ray_cast_circle", i2d_cast_output{}, [&](Call& call) {
        return valid_circle_ptr(call, shape, "circle") ? cast_checked(call, *shape, xf, origin, translation)
                                                       : i2d_cast_output{};
    });
}

I2D_API i2d_cast_output i2d_ray_cast_capsule(const i2d_capsule* shape, i2d_transform xf, i2d_vec2 origin,
                                             i2d_vec2 translation) {
    return guarded("i2d_ray_cast_capsule", i2d_cast_output{}, [&](Call& call) {
        return valid_capsule(call, shape, "capsule") ? cast_checked(call, *shape, xf, origin, translation)
                                                     : i2d_cast_output{};
    });
}

I2D_API i2d_cast_output i2d_ray_cast_segment(const i2d_segment* shape, i2d_transform xf, i2d_vec2 origin,
                                             i2d_vec2 translation) {
    return guarded("i2d_ray_cast_segment", i2d_cast_output{}, [&](Call& call) {
        return valid_segment(call, shape, "segment") ? cast_checked(call, *shape, xf, origin, translation)
                                                     : i2d_cast_output{};
    });
}

I2D_API i2d_cast_output i2d_ray_cast_polygon(const i2d_polygon* shape, i2d_transform xf, i2d_vec2 origin,
                                             i2d_vec2 translation) {
    return guarded("i2d_ray_cast_polygon", i2d_cast_output{}, [&](Call& call) {
        return valid_polygon(call, shape, "polygon") ? cast_checked(call, *shape, xf, origin, translation)
                                                     : i2d_cast_output{};
    });
}

// ---- Manifolds of placed shapes -----------------------------------------------------

namespace {

// Shared body of the typed entry points: check both shapes and transforms, then collide
// in the core. These functions know no world: they work in metres, with the default
// speculative distance and (for the pairs whose tie-breaks need one) linear slop.
template <class A, class B, class ValidA, class ValidB, class Collide>
i2d_manifold collide_checked(const char* name, const A* a, i2d_transform xfa, const B* b, i2d_transform xfb,
                             ValidA valid_a, ValidB valid_b, Collide collide) {
    return guarded(name, i2d_manifold{}, [&](Call& call) {
        if (!valid_a(call, a, "shape a") || !valid_transform(call, xfa, "xfa") || !valid_b(call, b, "shape b") ||
            !valid_transform(call, xfb, "xfb")) {
            return i2d_manifold{};
        }
        const auto ca = to_core(*a);
        const auto cb = to_core(*b);
        const Transform ta = to_core(xfa), tb = to_core(xfb);
        if constexpr (std::is_invocable_v<Collide, decltype(ca), Transform, decltype(cb), Transform, float, float>) {
            return to_public(collide(ca, ta, cb, tb, speculative_distance, linear_slop));
        } else {
            return to_public(collide(ca, ta, cb, tb, speculative_distance));
        }
    });
}

}  // namespace

I2D_API i2d_manifold i2d_collide_capsule_circle(const i2d_capsule* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb) {
    return collide_checked("i2d_collide_capsule_circle", a, xfa, b, xfb, valid_capsule, valid_circle_ptr, collide_capsule_circle);
}

I2D_API i2d_manifold i2d_collide_segment_circle(const i2d_segment* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb) {
    return collide_checked("i2d_collide_segment_circle", a, xfa, b, xfb, valid_segment, valid_circle_ptr, collide_segment_circle);
}

I2D_API i2d_manifold i2d_collide_polygon_circle(const i2d_polygon* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb) {
    return collide_checked("i2d_collide_polygon_circle", a, xfa, b, xfb, valid_polygon, valid_circle_ptr, collide_polygon_circle);
}

I2D_API i2d_manifold i2d_collide_capsules(const i2d_capsule* a, i2d_transform xfa, const i2d_capsule* b,
                                          i2d_transform xfb) {
    return collide_checked("i2d_collide_capsules", a, xfa, b, xfb, valid_capsule, valid_capsule, collide_capsules);
}

I2D_API i2d_manifold i2d_collide_segment_capsule(const i2d_segment* a, i2d_transform xfa, const i2d_capsule* b,
                                                 i2d_transform xfb) {
    return collide_checked("i2d_collide_segment_capsule", a, xfa, b, xfb, valid_segment, valid_capsule, collide_segment_capsule);
}

I2D_API i2d_manifold i2d_collide_polygon_capsule(const i2d_polygon* a, i2d_transform xfa, const i2d_capsule* b,
                                                 i2d_transform xfb) {
    return collide_checked("i2d_collide_polygon_capsule", a, xfa, b, xfb, valid_polygon, valid_capsule, collide_polygon_capsule);
}

I2D_API i2d_manifold i2d_collide_segment_polygon(const i2d_segment* a, i2d_transform xfa, const i2d_polygon* b,
                                                 i2d_transform xfb) {
    return collide_checked("i2d_collide_segment_polygon", a, xfa, b, xfb, valid_segment, valid_polygon, collide_segment_polygon);
}

I2D_API i2d_manifold i2d_collide_polygons(const i2d_polygon* a, i2d_transform xfa, const i2d_polygon* b,
                                          i2d_transform xfb) {
    return collide_checked("i2d_collide_polygons", a, xfa, b, xfb, valid_polygon, valid_polygon, collide_polygons);
}
