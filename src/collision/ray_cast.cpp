// SPDX-License-Identifier: MIT
// Ray casts against every shape kind, in the shape's local frame.
#include <cfloat>
#include <cmath>

#include "collision/geometry.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// A local ray: origin o, translation d, accepted fractions [0, max_fraction].
struct LocalRay {
    Vec2 o, d;
    float max_fraction;
};

struct LocalHit {
    float fraction = FLT_MAX;
    Vec2 normal;
    bool hit = false;
    void keep_first(float t, Vec2 n) {
        if (t < fraction) {
            fraction = t, normal = n, hit = true;
        }
    }
};

// Entry into a disc. Projects the centre onto the ray rather than solving the quadratic
// directly: the quadratic's cancellation loses digits for long rays. No entry when the
// origin is strictly inside.
void cast_disc(const LocalRay& ray, Vec2 c, float radius, LocalHit& out) {
    const Vec2 s = ray.o - c;
    const float r_sq = radius * radius;
    if (length_squared(s) < r_sq) {
        return;
    }
    const float len = length(ray.d);
    const Vec2 dir = (1.0f / len) * ray.d;
    const float along = -dot(s, dir);
    const Vec2 closest = s + along * dir;
    const float half_chord_sq = r_sq - length_squared(closest);
    if (half_chord_sq < 0.0f) {
        return;
    }
    const float t = along - std::sqrt(half_chord_sq);
    if (t < 0.0f || t > ray.max_fraction * len) {
        return;
    }
    const Vec2 radial = s + t * dir;
    const float radial_len = length(radial);
    out.keep_first(t / len, radial_len > 0.0f ? (1.0f / radial_len) * radial : -dir);
}

// Crossing of the segment a-b: o + t d = a + s e. Crossing with e and with d gives
// t = (a - o) x e / (d x e) and s = (a - o) x d / (d x e). Parallel rays miss.
bool cross_segment(const LocalRay& ray, Vec2 a, Vec2 b, float& out_t) {
    const Vec2 e = b - a;
    const float denom = cross(ray.d, e);
    if (denom == 0.0f) {
        return false;
    }
    const Vec2 ao = a - ray.o;
    const float t = cross(ao, e) / denom;
    const float s = cross(ao, ray.d) / denom;
    if (t < 0.0f || t > ray.max_fraction || s < 0.0f || s > 1.0f) {
        return false;
    }
    out_t = t;
    return true;
}

// Cyrus-Beck clipping against the half planes of a sharp convex polygon: the ray is
// inside between the last entry and the first exit. An origin inside (no entering face
// ahead of it) is not a hit; an origin on an entering face hits at fraction 0.
void cast_sharp_polygon(const LocalRay& ray, const Polygon& poly, LocalHit& out) {
    float lower = 0.0f, upper = ray.max_fraction;
    int32_t entry = -1;
    for (int32_t i = 0; i < poly.count; ++i) {
        const float numerator = dot(poly.normals[i], poly.vertices[i] - ray.o);
        const float denominator = dot(poly.normals[i], ray.d);
        if (denominator == 0.0f) {
            if (numerator < 0.0f) {
                return;  // parallel to this face and outside it
            }
        } else if (denominator < 0.0f && numerator <= lower * denominator) {
            lower = numerator / denominator;  // entering this face later than the others
            entry = i;
        } else if (denominator > 0.0f && numerator < upper * denominator) {
            upper = numerator / denominator;
        }
        if (upper < lower) {
            return;
        }
    }
    if (entry >= 0) {
        out.keep_first(lower, poly.normals[entry]);
    }
}

// A rounded core (polygon or capsule) is its core, an r-thick slab on each edge and a
// disc at each vertex. With the origin outside, the first entry into the union is the
// first entry into one of the outer edge faces or one of the discs.
void cast_rounded(const LocalRay& ray, const Vec2* v, const Vec2* normals, int32_t count, float r, LocalHit& out) {
    for (int32_t i = 0; i < count; ++i) {
        cast_disc(ray, v[i], r, out);
        const Vec2 n = normals[i];
        float t = 0.0f;
        if (dot(n, ray.d) < 0.0f &&
            cross_segment(ray, v[i] + r * n, v[i + 1 == count ? 0 : i + 1] + r * n, t)) {
            out.keep_first(t, n);
        }
    }
}

LocalHit cast_local(const Geometry& g, const LocalRay& ray) {
    LocalHit out;
    switch (g.type) {
        case ShapeType::circle: cast_disc(ray, g.circle.center, g.circle.radius, out); break;
        case ShapeType::capsule: {
            const Capsule& c = g.capsule;
            const Vec2 n = normalize(right_perp(c.center2 - c.center1));
            const Vec2 v[2] = {c.center1, c.center2};
            const Vec2 normals[2] = {n, -n};
            cast_rounded(ray, v, normals, 2, c.radius, out);
            break;
        }
        case ShapeType::segment: {
            float t = 0.0f;
            if (cross_segment(ray, g.segment.point1, g.segment.point2, t)) {
                const Vec2 n = normalize(right_perp(g.segment.point2 - g.segment.point1));
                out.keep_first(t, dot(n, ray.d) > 0.0f ? -n : n);  // two-sided: face the ray
            }
            break;
        }
        case ShapeType::chain_segment: {
            // One-sided: only a ray coming from the solid side's outside (the right) hits.
            const ChainSegment& c = g.chain_segment;
            const Vec2 n = normalize(right_perp(c.point2 - c.point1));
            float t = 0.0f;
            if (dot(n, ray.d) < 0.0f && cross_segment(ray, c.point1, c.point2, t)) {
                out.keep_first(t, n);
            }
            break;
        }
        case ShapeType::polygon:
            if (g.polygon.radius > 0.0f) {
                cast_rounded(ray, g.polygon.vertices, g.polygon.normals, g.polygon.count, g.polygon.radius, out);
            } else {
                cast_sharp_polygon(ray, g.polygon, out);
            }
            break;
        case ShapeType::count: break;
    }
    return out;
}

}  // namespace

RayHit ray_cast(const Geometry& g, const Transform& xf, Vec2 origin, Vec2 translation, float max_fraction) {
    RayHit out;
    if (length_squared(translation) == 0.0f) {
        return out;
    }
    // Rounded shapes are unions whose pieces do not know about each other: an origin
    // inside one piece must not report the entry into another.
    const bool rounded = g.type == ShapeType::capsule || (g.type == ShapeType::polygon && g.polygon.radius > 0.0f);
    if (rounded && contains_point(g, xf, origin)) {
        return out;
    }
    const LocalRay ray{inv_transform_point(xf, origin), inv_rotate(xf.q, translation), max_fraction};
    const LocalHit local = cast_local(g, ray);
    if (!local.hit) {
        return out;
    }
    out.hit = true;
    out.fraction = local.fraction;
    out.point = origin + local.fraction * translation;
    out.normal = rotate(xf.q, local.normal);
    return out;
}

}  // namespace i2d
