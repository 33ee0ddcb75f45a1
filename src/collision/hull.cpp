// SPDX-License-Identifier: MIT
// Convex hull by gift wrapping, and polygon construction (centroid, normals, boxes).
#include "collision/hull.hpp"

#include <cmath>

#include "core/assert.hpp"

namespace i2d {

namespace {

// Drops points within linear_slop of an earlier one: such near-duplicates would make
// edges too short to have a reliable normal.
int32_t weld(const Vec2* points, int32_t count, Vec2* out) {
    int32_t n = 0;
    for (int32_t i = 0; i < count; ++i) {
        bool unique = true;
        for (int32_t j = 0; j < n && unique; ++j) {
            unique = distance_squared(points[i], out[j]) >= linear_slop * linear_slop;
        }
        if (unique) {
            out[n++] = points[i];
        }
    }
    return n;
}

// Jarvis march (gift wrapping), O(n h), ideal for n <= 8: from the lowest-leftmost point,
// repeatedly take the point that has every other point on its left; among collinear
// candidates the farthest, so that points on an edge are skipped. Returns the hull size,
// or 0 if the walk fails to close (only possible for degenerate, collinear input).
int32_t gift_wrap(const Vec2* ps, int32_t n, Vec2* out) {
    int32_t start = 0;
    for (int32_t i = 1; i < n; ++i) {
        if (ps[i].x < ps[start].x || (ps[i].x == ps[start].x && ps[i].y < ps[start].y)) {
            start = i;
        }
    }
    int32_t m = 0;
    int32_t current = start;
    for (int32_t guard = 0; guard <= n; ++guard) {
        out[m++] = ps[current];
        int32_t next = current == 0 ? 1 : 0;
        for (int32_t j = 0; j < n; ++j) {
            if (j == current || j == next) {
                continue;
            }
            const Vec2 e = ps[next] - ps[current];
            const Vec2 r = ps[j] - ps[current];
            const float c = cross(e, r);
            if (c < 0.0f || (c == 0.0f && length_squared(r) > length_squared(e))) {
                next = j;
            }
        }
        current = next;
        if (current == start) {
            return m;
        }
        if (m == n) {
            break;
        }
    }
    return 0;
}

// Removes vertices within linear_slop of the line through their neighbours, one at a
// time, since each removal changes its neighbours' lines.
int32_t remove_collinear(Vec2* v, int32_t m) {
    bool removed = true;
    while (removed && m >= 3) {
        removed = false;
        for (int32_t i = 0; i < m; ++i) {
            const Vec2 prev = v[i == 0 ? m - 1 : i - 1];
            const Vec2 next = v[i + 1 == m ? 0 : i + 1];
            const Vec2 e = next - prev;
            const float len = length(e);
            const float distance = len > 0.0f ? std::fabs(cross(e, v[i] - prev)) / len : 0.0f;
            if (distance < linear_slop) {
                for (int32_t k = i; k + 1 < m; ++k) {
                    v[k] = v[k + 1];
                }
                --m;
                removed = true;
                break;
            }
        }
    }
    return m;
}

float hull_area(const Vec2* v, int32_t m) {
    float twice = 0.0f;
    for (int32_t i = 1; i + 1 < m; ++i) {
        twice += cross(v[i] - v[0], v[i + 1] - v[0]);
    }
    return 0.5f * twice;
}

}  // namespace

HullStatus compute_hull(const Vec2* points, int32_t count, Hull& out_hull) {
    out_hull.count = 0;
    if (count < 3 || count > max_polygon_vertices) {
        return HullStatus::bad_count;
    }
    Vec2 welded[max_polygon_vertices];
    const int32_t n = weld(points, count, welded);
    if (n < 3) {
        return HullStatus::duplicate_points;
    }
    Hull hull;
    hull.count = remove_collinear(hull.points, gift_wrap(welded, n, hull.points));
    if (hull.count < 3) {
        return HullStatus::collinear_points;
    }
    if (hull_area(hull.points, hull.count) < linear_slop * linear_slop) {
        return HullStatus::area_too_small;
    }
    out_hull = hull;
    return HullStatus::ok;
}

const char* hull_status_message(HullStatus status) {
    switch (status) {
        case HullStatus::ok: return "ok";
        case HullStatus::bad_count: return "point count must be 3 to 8";
        case HullStatus::duplicate_points: return "duplicate points (fewer than 3 remain 0.005 m apart)";
        case HullStatus::collinear_points: return "points are collinear (within 0.005 m of one line)";
        case HullStatus::area_too_small: return "area too small (below 0.005^2 m^2)";
        case HullStatus::count: break;
    }
    return "invalid hull status";
}

// Triangle fan from the first vertex rather than from the origin: for points far from the
// origin the fan's cross products would otherwise cancel catastrophically.
Vec2 polygon_centroid(const Vec2* vertices, int32_t count) {
    const Vec2 origin = vertices[0];
    if (count < 3) {
        return count == 2 ? lerp(vertices[0], vertices[1], 0.5f) : origin;
    }
    Vec2 moment;
    float area = 0.0f;
    for (int32_t i = 1; i + 1 < count; ++i) {
        const Vec2 e1 = vertices[i] - origin;
        const Vec2 e2 = vertices[i + 1] - origin;
        const float a = 0.5f * cross(e1, e2);
        moment += (a / 3.0f) * (e1 + e2);
        area += a;
    }
    I2D_ASSERT(area > 0.0f);
    return origin + (1.0f / area) * moment;
}

Polygon make_polygon(const Hull& hull, float radius) {
    I2D_ASSERT(hull.count >= 3 && hull.count <= max_polygon_vertices);
    Polygon p;
    p.count = hull.count;
    p.radius = radius;
    for (int32_t i = 0; i < p.count; ++i) {
        p.vertices[i] = hull.points[i];
    }
    for (int32_t i = 0; i < p.count; ++i) {
        const Vec2 edge = p.vertices[i + 1 == p.count ? 0 : i + 1] - p.vertices[i];
        p.normals[i] = normalize(right_perp(edge));
    }
    p.centroid = polygon_centroid(p.vertices, p.count);
    return p;
}

Polygon make_box(float hx, float hy) { return make_offset_box(hx, hy, Vec2{}, Rot{}); }

Polygon make_square(float half_size) { return make_box(half_size, half_size); }

Polygon make_offset_box(float hx, float hy, Vec2 center, Rot rotation) {
    Polygon p;
    p.count = 4;
    const Vec2 corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    const Vec2 normals[4] = {{0.0f, -1.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}};
    for (int32_t i = 0; i < 4; ++i) {
        p.vertices[i] = center + rotate(rotation, corners[i]);
        p.normals[i] = rotate(rotation, normals[i]);
    }
    p.centroid = center;
    return p;
}

Polygon make_capsule_polygon(Vec2 p1, Vec2 p2, float radius) {
    Polygon p;
    p.count = 2;
    p.vertices[0] = p1;
    p.vertices[1] = p2;
    p.normals[0] = normalize(right_perp(p2 - p1));
    p.normals[1] = -p.normals[0];
    p.centroid = lerp(p1, p2, 0.5f);
    p.radius = radius;
    return p;
}

}  // namespace i2d
