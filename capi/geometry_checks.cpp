// SPDX-License-Identifier: MIT
// Checks of shape geometry passed through the C API. The pure functions' documented
// range: every coordinate (centres, corners, vertices, transform positions) and radius
// within max_coordinate (1e9 m), where their products stay far from float overflow;
// beyond it (around 1e19) they used to return NaN points and zero normals.
#include "geometry_checks.hpp"

#include <cmath>

#include "collision/collision_constants.hpp"
#include "convert.hpp"
#include "limits.hpp"
#include "math/math.hpp"

namespace i2d::capi {

// A caller's rotation must be nearly unit length; it is stored exactly normalised so
// that rounding in the caller's cos/sin never scales a body.
bool normalized_rotation(Call& call, i2d_rot q, const char* what, Rot& out) {
    if (!call.finite(q.c, what) || !call.finite(q.s, what)) {
        return false;
    }
    const float length_sq = q.c * q.c + q.s * q.s;
    if (!(std::fabs(length_sq - 1.0f) <= rotation_normalization_tolerance)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "%s (c=%g, s=%g) is not a unit rotation (c^2 + s^2 = %g); build it with i2d_make_rot", what,
                         static_cast<double>(q.c), static_cast<double>(q.s), static_cast<double>(length_sq));
    }
    out = normalize(capi::to_core(q));
    return true;
}

bool valid_circle(Call& call, const i2d_circle& c, const char* what) {
    return call.coordinate(c.center, what) && valid_radius(call, c.radius, what);
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

bool valid_collide_aabb(Call& call, const i2d_aabb& a, const char* what) {
    return valid_aabb(call, a, what) && call.coordinate(a.min, what) && call.coordinate(a.max, what);
}

bool valid_radius(Call& call, float radius, const char* what) {
    if (!call.finite(radius, what)) {
        return false;
    }
    if (radius < 0.0f) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s radius is %g; it must be >= 0", what, static_cast<double>(radius));
    }
    if (radius > max_coordinate) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s radius is %g; it must be at most %g", what,
                         static_cast<double>(radius), static_cast<double>(max_coordinate));
    }
    return true;
}

bool valid_transform(Call& call, const i2d_transform& xf, const char* what) {
    if (!call.coordinate(xf.p, what) || !call.finite(xf.q.c, what) || !call.finite(xf.q.s, what)) {
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
    return call.not_null(c, what) && call.coordinate(c->center1, what) && call.coordinate(c->center2, what) &&
           valid_radius(call, c->radius, what) && valid_core_length(call, c->center1, c->center2, what);
}

bool valid_segment(Call& call, const i2d_segment* s, const char* what) {
    return call.not_null(s, what) && call.coordinate(s->point1, what) && call.coordinate(s->point2, what) &&
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
        if (!call.coordinate(p->vertices[i], what) || !call.finite(p->normals[i], what)) {
            return false;
        }
        const float len_sq = p->normals[i].x * p->normals[i].x + p->normals[i].y * p->normals[i].y;
        if (std::fabs(len_sq - 1.0f) > 1e-3f) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s normals[%d] is not unit length", what, static_cast<int>(i));
        }
    }
    return call.coordinate(p->centroid, what) && valid_radius(call, p->radius, what);
}

// What a polygon made by i2d_make_polygon or i2d_make_box looks like: counter-clockwise,
// convex (every turn to the left), edges longer than the slop, and each normal the
// outward unit normal of its edge. A caller's hand-edited polygon must still be one.
bool valid_convex_polygon(Call& call, const i2d_polygon* p, const char* what, float min_edge) {
    if (!valid_polygon(call, p, what)) {
        return false;
    }
    const int32_t n = p->count;
    for (int32_t i = 0; i < n; ++i) {
        const i2d_vec2 a = p->vertices[i], b = p->vertices[(i + 1) % n], c = p->vertices[(i + 2) % n];
        const float ex = b.x - a.x, ey = b.y - a.y;
        const float length = std::sqrt(ex * ex + ey * ey);
        if (!(length >= min_edge)) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s edge %d is shorter than %g m", what, static_cast<int>(i),
                             static_cast<double>(min_edge));
        }
        const float outward = (ey * p->normals[i].x - ex * p->normals[i].y) / length;
        if (!(outward >= 1.0f - 1.0e-3f)) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT,
                             "%s normals[%d] is not the outward normal of its edge (is the polygon clockwise?)", what,
                             static_cast<int>(i));
        }
        const float turn = ex * (c.y - b.y) - ey * (c.x - b.x);
        if (!(turn > 0.0f)) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s is not convex and counter-clockwise at vertex %d", what,
                             static_cast<int>((i + 1) % n));
        }
    }
    return true;
}

bool valid_proxy_input(Call& call, const i2d_vec2* points, int32_t count, float radius, const char* what) {
    if (!call.not_null(points, what)) {
        return false;
    }
    if (count < 1 || count > max_polygon_vertices) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s: count is %d; it must be in [1, %d]", what, int(count),
                         int(max_polygon_vertices));
    }
    for (int32_t i = 0; i < count; ++i) {
        if (!call.coordinate(points[i], what)) {
            return false;
        }
    }
    return call.in_range(radius, 0.0f, max_shape_extent, what);
}

bool core_proxy(Call& call, const i2d_shape_proxy* proxy, ShapeProxy& out, const char* what) {
    if (!call.not_null(proxy, what) || !valid_proxy_input(call, proxy->points, proxy->count, proxy->radius, what)) {
        return false;
    }
    Vec2 points[max_polygon_vertices];
    for (int32_t i = 0; i < proxy->count; ++i) {
        points[i] = to_core(proxy->points[i]);
    }
    out = make_query_proxy(points, proxy->count, proxy->radius);
    return true;
}

}  // namespace i2d::capi
