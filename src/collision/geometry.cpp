// SPDX-License-Identifier: MIT
// Mass, bounds, overlap tests and ray casts of circles and boxes.
#include "collision/geometry.hpp"

#include <cmath>
#include <limits>

#include "math/math.hpp"

namespace i2d {

float area(const Geometry& g) {
    switch (g.type) {
        case ShapeType::circle: return pi * g.circle.radius * g.circle.radius;
        case ShapeType::box: return 4.0f * g.box.half_extents.x * g.box.half_extents.y;
        case ShapeType::count: break;
    }
    return 0.0f;
}

MassData compute_mass(const Geometry& g, float density) {
    MassData md;
    md.mass = density * area(g);
    md.center = g.type == ShapeType::circle ? g.circle.center : Vec2{};
    return md;
}

AABB compute_aabb(const Geometry& g, const Transform& xf) {
    if (g.type == ShapeType::circle) {
        const Vec2 c = transform_point(xf, g.circle.center);
        const Vec2 r{g.circle.radius, g.circle.radius};
        return {c - r, c + r};
    }
    // A box turned by q reaches |R| * h from its centre on each axis.
    const Vec2 h = g.box.half_extents;
    const float ex = std::fabs(xf.q.c) * h.x + std::fabs(xf.q.s) * h.y;
    const float ey = std::fabs(xf.q.s) * h.x + std::fabs(xf.q.c) * h.y;
    return {xf.p - Vec2{ex, ey}, xf.p + Vec2{ex, ey}};
}

bool contains_point(const Geometry& g, const Transform& xf, Vec2 p) {
    if (g.type == ShapeType::circle) {
        const float r = g.circle.radius;
        return distance_squared(transform_point(xf, g.circle.center), p) <= r * r;
    }
    const Vec2 local = inv_rotate(xf.q, p - xf.p);
    const Vec2 h = g.box.half_extents;
    return std::fabs(local.x) <= h.x && std::fabs(local.y) <= h.y;
}

bool overlaps_aabb(const Geometry& g, const Transform& xf, const AABB& box) {
    if (g.type == ShapeType::circle) {
        const Vec2 c = transform_point(xf, g.circle.center);
        const float r = g.circle.radius;
        return distance_squared(clamp_to(box, c), c) <= r * r;
    }
    // Exact while bodies do not rotate: the box is its own bounding box.
    return overlaps(compute_aabb(g, xf), box);
}

namespace {

// Projects the centre onto the ray rather than solving the quadratic directly: the
// quadratic's cancellation loses digits for long rays.
RayHit ray_cast_circle(const Circle& circle, const Transform& xf, Vec2 origin, Vec2 translation, float max_fraction) {
    RayHit out;
    const Vec2 c = transform_point(xf, circle.center);
    const Vec2 s = origin - c;
    const float r_sq = circle.radius * circle.radius;
    if (length_squared(s) < r_sq) {
        return out;  // starts inside
    }
    const float len = length(translation);
    const Vec2 dir = (1.0f / len) * translation;
    const float along = -dot(s, dir);                 // distance to the centre's projection
    const Vec2 closest = s + along * dir;             // from centre to nearest ray point
    const float half_chord_sq = r_sq - length_squared(closest);
    if (half_chord_sq < 0.0f) {
        return out;
    }
    const float t = along - std::sqrt(half_chord_sq);
    if (t < 0.0f || t > max_fraction * len) {
        return out;
    }
    out.fraction = t / len;
    out.point = origin + t * dir;
    const Vec2 radial = out.point - c;
    const float radial_len = length(radial);
    out.normal = radial_len > 0.0f ? (1.0f / radial_len) * radial : -dir;
    out.hit = true;
    return out;
}

// Slab test in the box's frame: the ray is inside the box between the last entry and
// the first exit over both axes.
RayHit ray_cast_box(const Box& box, const Transform& xf, Vec2 origin, Vec2 translation, float max_fraction) {
    RayHit out;
    const Vec2 o = inv_rotate(xf.q, origin - xf.p);
    const Vec2 d = inv_rotate(xf.q, translation);
    const float h[2] = {box.half_extents.x, box.half_extents.y};
    const float oc[2] = {o.x, o.y};
    const float dc[2] = {d.x, d.y};
    float enter = -std::numeric_limits<float>::infinity();
    float exit = std::numeric_limits<float>::infinity();
    Vec2 enter_normal;
    for (int axis = 0; axis < 2; ++axis) {
        if (dc[axis] == 0.0f) {
            if (oc[axis] < -h[axis] || oc[axis] > h[axis]) {
                return out;  // parallel to this slab and outside it
            }
            continue;
        }
        const float inv = 1.0f / dc[axis];
        float t_near = (-h[axis] - oc[axis]) * inv;
        float t_far = (h[axis] - oc[axis]) * inv;
        float sign = -1.0f;  // entering through the lower face
        if (t_near > t_far) {
            const float tmp = t_near;
            t_near = t_far, t_far = tmp, sign = 1.0f;
        }
        if (t_near > enter) {
            enter = t_near;
            enter_normal = axis == 0 ? Vec2{sign, 0.0f} : Vec2{0.0f, sign};
        }
        exit = std::fmin(exit, t_far);
    }
    // enter < 0 means the origin is inside the box (or the box is behind it).
    if (enter > exit || enter < 0.0f || enter > max_fraction) {
        return out;
    }
    out.fraction = enter;
    out.point = origin + enter * translation;
    out.normal = rotate(xf.q, enter_normal);
    out.hit = true;
    return out;
}

}  // namespace

RayHit ray_cast(const Geometry& g, const Transform& xf, Vec2 origin, Vec2 translation, float max_fraction) {
    if (length_squared(translation) == 0.0f) {
        return {};
    }
    if (g.type == ShapeType::circle) {
        return ray_cast_circle(g.circle, xf, origin, translation, max_fraction);
    }
    return ray_cast_box(g.box, xf, origin, translation, max_fraction);
}

}  // namespace i2d
