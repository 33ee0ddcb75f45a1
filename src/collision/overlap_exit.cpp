// SPDX-License-Identifier: MIT
// The least exit of two overlapping proxies over candidate directions, and a point they
// share (overlap_exit.hpp).
#include "collision/overlap_exit.hpp"

#include <cfloat>

#include "math/math.hpp"

namespace i2d {

namespace {

/// Most points a core clipped by a polygon can have: each clipping edge adds at most one
/// to the subject's (at most 8).
constexpr int32_t max_clip_points = 2 * max_polygon_vertices;

// How far B's core must move along unit n to clear A's: A's reach along n less B's,
// both measured from `origin` (a point of B) so that the products stay small.
float core_clearance(const ShapeProxy& a, const ShapeProxy& b, Vec2 n, Vec2 origin) {
    float reach_a = -FLT_MAX, reach_b = FLT_MAX;
    for (int32_t i = 0; i < a.count; ++i) {
        reach_a = max_of(reach_a, dot(a.points[i] - origin, n));
    }
    for (int32_t j = 0; j < b.count; ++j) {
        reach_b = min_of(reach_b, dot(b.points[j] - origin, n));
    }
    return reach_a - reach_b;
}

// The least clearance over the directions tried, the first of equals kept.
struct LeastExit {
    Vec2 normal;
    float clearance = FLT_MAX;
    bool found = false;
};

// Across and along every pair of points of the core: the candidates of the design note.
template <class Try>
void try_pair_directions(const ShapeProxy& p, Try&& try_direction) {
    for (int32_t i = 0; i < p.count; ++i) {
        for (int32_t j = i + 1; j < p.count; ++j) {
            const Vec2 along = unit_direction(p.points[j] - p.points[i]);
            if (along.x == 0.0f && along.y == 0.0f) {
                continue;
            }
            try_direction(left_perp(along));
            try_direction(right_perp(along));
            try_direction(along);
            try_direction(-along);
        }
    }
}

LeastExit least_exit(const ShapeProxy& a, const ShapeProxy& b, const ProxyDistance& closest) {
    const Vec2 origin = b.points[0];
    LeastExit least;
    auto try_direction = [&](Vec2 n) {
        const float clearance = core_clearance(a, b, n, origin);
        if (clearance < least.clearance) {
            least = {n, clearance, true};
        }
    };
    // Cores apart: their closest points' direction, tried first so that it wins ties.
    if (!(closest.point_a == closest.point_b)) {
        try_direction(unit_direction(closest.point_b - closest.point_a));
    }
    try_pair_directions(a, try_direction);
    try_pair_directions(b, try_direction);
    return least;
}

// The part of `subject` (a segment or polygon) inside the convex counter-clockwise
// polygon `clip`, by Sutherland-Hodgman (a segment as a two-sided loop), boundaries
// included. Returns the count of points written to out (room for max_clip_points).
int32_t clip_by_polygon(const ShapeProxy& subject, const ShapeProxy& clip, Vec2* out) {
    Vec2 buffers[2][max_clip_points];
    int32_t count = subject.count;
    for (int32_t i = 0; i < count; ++i) {
        buffers[0][i] = subject.points[i];
    }
    int32_t from = 0;
    for (int32_t e = 0; e < clip.count && count > 0; ++e) {
        const Vec2 v = clip.points[e];
        const Vec2 edge = clip.points[e + 1 == clip.count ? 0 : e + 1] - v;
        const Vec2* in = buffers[from];
        Vec2* kept = buffers[1 - from];
        int32_t kept_count = 0;
        auto keep = [&](Vec2 p) {
            if (kept_count < max_clip_points) {
                kept[kept_count++] = p;
            }
        };
        for (int32_t k = 0; k < count; ++k) {
            const Vec2 s = in[k], t = in[k + 1 == count ? 0 : k + 1];
            const float side_s = cross(edge, s - v), side_t = cross(edge, t - v);  // >= 0: inside
            if ((side_s >= 0.0f) != (side_t >= 0.0f)) {
                keep(s + (side_s / (side_s - side_t)) * (t - s));
            }
            if (side_t >= 0.0f) {
                keep(t);
            }
        }
        count = kept_count;
        from = 1 - from;
    }
    for (int32_t i = 0; i < count; ++i) {
        out[i] = buffers[from][i];
    }
    return count;
}

// The mean of the points, taken from the first so that far coordinates keep their digits.
Vec2 mean_of(const Vec2* points, int32_t count) {
    Vec2 sum;
    for (int32_t i = 1; i < count; ++i) {
        sum += points[i] - points[0];
    }
    return points[0] + (1.0f / float(count)) * sum;
}

// B's core point deepest along -n: where it reaches into A.
Vec2 deepest_point(const ShapeProxy& b, Vec2 n) {
    int32_t deepest = 0;
    for (int32_t j = 1; j < b.count; ++j) {
        if (dot(b.points[j] - b.points[0], n) < dot(b.points[deepest] - b.points[0], n)) {
            deepest = j;
        }
    }
    return b.points[deepest];
}

// A point of both cores, which overlap: a single point of one of them, the crossing of
// two segments, or the mean of one core clipped by the other (a polygon), convex and so
// inside the overlap. A clip that rounding leaves empty (cores that only touch) falls
// back to B's deepest point along -n, on the touching boundary.
Vec2 shared_core_point(const ShapeProxy& a, const ShapeProxy& b, const ProxyDistance& closest, Vec2 n) {
    if (a.count == 1) {
        return a.points[0];
    }
    if (b.count == 1) {
        return b.points[0];
    }
    if (a.count == 2 && b.count == 2) {
        return lerp(closest.point_a, closest.point_b, 0.5f);
    }
    const bool a_clips = a.count >= 3;
    Vec2 overlap[max_clip_points];
    const int32_t count = clip_by_polygon(a_clips ? b : a, a_clips ? a : b, overlap);
    return count > 0 ? mean_of(overlap, count) : deepest_point(b, n);
}

// Cores apart, radii overlapping: on the segment between the closest points, in the
// middle of the stretch both radii cover (A's reaches r_a from point_a, B's r_b back from
// point_b).
Vec2 point_between_cores(const ShapeProxy& a, const ShapeProxy& b, const ProxyDistance& closest) {
    const float gap = closest.distance;
    const float from = max_of(0.0f, gap - b.radius), to = min_of(a.radius, gap);
    return lerp(closest.point_a, closest.point_b, clamp(0.5f * (from + to) / gap, 0.0f, 1.0f));
}

}  // namespace

OverlapExit overlap_exit(const ShapeProxy& a, const ShapeProxy& b, Vec2 fallback) {
    const ProxyDistance closest = core_distance(a, b);
    LeastExit least = least_exit(a, b, closest);
    if (!least.found) {
        // Both cores one point, the same: every direction is as short.
        const Vec2 n = unit_direction(fallback);
        least.normal = n.x == 0.0f && n.y == 0.0f ? Vec2{0.0f, 1.0f} : n;
    }
    OverlapExit exit;
    exit.normal = least.normal;
    exit.point = closest.distance > 0.0f ? point_between_cores(a, b, closest)
                                         : shared_core_point(a, b, closest, least.normal);
    return exit;
}

}  // namespace i2d
