// SPDX-License-Identifier: MIT
// i2d_collide_*, i2d_make_*, i2d_compute_*_mass, i2d_ray_cast_*: the pure collision
// functions, checked and handed to the core.
#include <cmath>

#include "boundary.hpp"
#include "collision/geometry.hpp"
#include "collision/hull.hpp"
#include "collision/manifold.hpp"
#include "convert.hpp"
#include "dynamics/constants.hpp"

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

bool valid_radius(Call& call, float radius, const char* what) {
    if (!call.finite(radius, what)) {
        return false;
    }
    if (radius < 0.0f) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s radius is %g; it must be >= 0", what, static_cast<double>(radius));
    }
    return true;
}

bool valid_transform(Call& call, const i2d_transform& xf, const char* what) {
    if (!call.finite(xf.p, what) || !call.finite(xf.q.c, what) || !call.finite(xf.q.s, what)) {
        return false;
    }
    const float norm_sq = xf.q.c * xf.q.c + xf.q.s * xf.q.s;
    if (std::fabs(norm_sq - 1.0f) > 1e-3f) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s rotation (c, s) = (%g, %g) is not normalised", what,
                         static_cast<double>(xf.q.c), static_cast<double>(xf.q.s));
    }
    return true;
}

bool valid_circle_ptr(Call& call, const i2d_circle* c, const char* what) {
    return call.not_null(c, what) && valid_circle(call, *c, what);
}

// A core shorter than the slop has no reliable direction for its side normals.
bool valid_core_length(Call& call, i2d_vec2 p1, i2d_vec2 p2, const char* what) {
    const float dx = p2.x - p1.x, dy = p2.y - p1.y;
    if (!(dx * dx + dy * dy >= linear_slop * linear_slop)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s is shorter than 0.005 m", what);
    }
    return true;
}

bool valid_capsule(Call& call, const i2d_capsule* c, const char* what) {
    return call.not_null(c, what) && call.finite(c->center1, what) && call.finite(c->center2, what) &&
           valid_radius(call, c->radius, what) && valid_core_length(call, c->center1, c->center2, what);
}

bool valid_segment(Call& call, const i2d_segment* s, const char* what) {
    return call.not_null(s, what) && call.finite(s->point1, what) && call.finite(s->point2, what) &&
           valid_core_length(call, s->point1, s->point2, what);
}

bool valid_polygon(Call& call, const i2d_polygon* p, const char* what) {
    if (!call.not_null(p, what)) {
        return false;
    }
    if (p->count < 3 || p->count > max_polygon_vertices) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s count is %d; it must be 3 to 8", what, static_cast<int>(p->count));
    }
    for (int32_t i = 0; i < p->count; ++i) {
        if (!call.finite(p->vertices[i], what) || !call.finite(p->normals[i], what)) {
            return false;
        }
        const float len_sq = p->normals[i].x * p->normals[i].x + p->normals[i].y * p->normals[i].y;
        if (std::fabs(len_sq - 1.0f) > 1e-3f) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s normals[%d] is not unit length", what, static_cast<int>(i));
        }
    }
    return call.finite(p->centroid, what) && valid_radius(call, p->radius, what);
}

Transform to_core(const i2d_transform& xf) { return {capi::to_core(xf.p), capi::to_core(xf.q)}; }
Circle to_core(const i2d_circle& c) { return {capi::to_core(c.center), c.radius}; }
Capsule to_core(const i2d_capsule& c) { return {capi::to_core(c.center1), capi::to_core(c.center2), c.radius}; }
Segment to_core(const i2d_segment& s) { return {capi::to_core(s.point1), capi::to_core(s.point2)}; }

Polygon to_core(const i2d_polygon& p) {
    Polygon out;
    out.count = p.count;
    out.radius = p.radius;
    out.centroid = capi::to_core(p.centroid);
    for (int32_t i = 0; i < p.count; ++i) {
        out.vertices[i] = capi::to_core(p.vertices[i]);
        out.normals[i] = capi::to_core(p.normals[i]);
    }
    return out;
}

i2d_polygon to_public(const Polygon& p) {
    i2d_polygon out{};
    out.count = p.count;
    out.radius = p.radius;
    out.centroid = capi::to_public(p.centroid);
    for (int32_t i = 0; i < p.count; ++i) {
        out.vertices[i] = capi::to_public(p.vertices[i]);
        out.normals[i] = capi::to_public(p.normals[i]);
    }
    return out;
}

i2d_mass_data to_public(const MassData& md) {
    return {md.mass, capi::to_public(md.center), md.rotational_inertia};
}

i2d_cast_output to_public(const RayHit& hit) {
    i2d_cast_output out{};
    if (hit.hit) {
        out.point = capi::to_public(hit.point);
        out.normal = capi::to_public(hit.normal);
        out.fraction = hit.fraction;
        out.hit = true;
    }
    return out;
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
// in the core.
template <class A, class B, class ValidA, class ValidB, class Collide>
i2d_manifold collide_checked(const char* name, const A* a, i2d_transform xfa, const B* b, i2d_transform xfb,
                             ValidA valid_a, ValidB valid_b, Collide collide) {
    return guarded(name, i2d_manifold{}, [&](Call& call) {
        if (!valid_a(call, a, "shape a") || !valid_transform(call, xfa, "xfa") || !valid_b(call, b, "shape b") ||
            !valid_transform(call, xfb, "xfb")) {
            return i2d_manifold{};
        }
        return to_public(collide(to_core(*a), to_core(xfa), to_core(*b), to_core(xfb)));
    });
}

}  // namespace

I2D_API i2d_manifold i2d_collide_capsule_circle(const i2d_capsule* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb) {
    return collide_checked("i2d_collide_capsule_circle", a, xfa, b, xfb, valid_capsule, valid_circle_ptr,
                           [](const Capsule& ca, const Transform& xa, const Circle& cb, const Transform& xb) {
                               return collide_capsule_circle(ca, xa, cb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_segment_circle(const i2d_segment* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb) {
    return collide_checked("i2d_collide_segment_circle", a, xfa, b, xfb, valid_segment, valid_circle_ptr,
                           [](const Segment& sa, const Transform& xa, const Circle& cb, const Transform& xb) {
                               return collide_segment_circle(sa, xa, cb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_polygon_circle(const i2d_polygon* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb) {
    return collide_checked("i2d_collide_polygon_circle", a, xfa, b, xfb, valid_polygon, valid_circle_ptr,
                           [](const Polygon& pa, const Transform& xa, const Circle& cb, const Transform& xb) {
                               return collide_polygon_circle(pa, xa, cb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_capsules(const i2d_capsule* a, i2d_transform xfa, const i2d_capsule* b,
                                          i2d_transform xfb) {
    return collide_checked("i2d_collide_capsules", a, xfa, b, xfb, valid_capsule, valid_capsule,
                           [](const Capsule& ca, const Transform& xa, const Capsule& cb, const Transform& xb) {
                               return collide_capsules(ca, xa, cb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_segment_capsule(const i2d_segment* a, i2d_transform xfa, const i2d_capsule* b,
                                                 i2d_transform xfb) {
    return collide_checked("i2d_collide_segment_capsule", a, xfa, b, xfb, valid_segment, valid_capsule,
                           [](const Segment& sa, const Transform& xa, const Capsule& cb, const Transform& xb) {
                               return collide_segment_capsule(sa, xa, cb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_polygon_capsule(const i2d_polygon* a, i2d_transform xfa, const i2d_capsule* b,
                                                 i2d_transform xfb) {
    return collide_checked("i2d_collide_polygon_capsule", a, xfa, b, xfb, valid_polygon, valid_capsule,
                           [](const Polygon& pa, const Transform& xa, const Capsule& cb, const Transform& xb) {
                               return collide_polygon_capsule(pa, xa, cb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_segment_polygon(const i2d_segment* a, i2d_transform xfa, const i2d_polygon* b,
                                                 i2d_transform xfb) {
    return collide_checked("i2d_collide_segment_polygon", a, xfa, b, xfb, valid_segment, valid_polygon,
                           [](const Segment& sa, const Transform& xa, const Polygon& pb, const Transform& xb) {
                               return collide_segment_polygon(sa, xa, pb, xb);
                           });
}

I2D_API i2d_manifold i2d_collide_polygons(const i2d_polygon* a, i2d_transform xfa, const i2d_polygon* b,
                                          i2d_transform xfb) {
    return collide_checked("i2d_collide_polygons", a, xfa, b, xfb, valid_polygon, valid_polygon,
                           [](const Polygon& pa, const Transform& xa, const Polygon& pb, const Transform& xb) {
                               return collide_polygons(pa, xa, pb, xb);
                           });
}
