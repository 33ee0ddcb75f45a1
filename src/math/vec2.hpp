// SPDX-License-Identifier: MIT
// Vec2, Rot, Transform and AABB: the engine's own small value types and their operators.
#pragma once

#include <cmath>

#include "math/trig.hpp"

namespace i2d {

struct Vec2 {
    float x = 0.0f, y = 0.0f;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
inline Vec2 operator*(float s, Vec2 a) { return {s * a.x, s * a.y}; }
inline Vec2 operator*(Vec2 a, float s) { return {s * a.x, s * a.y}; }
inline Vec2& operator+=(Vec2& a, Vec2 b) { a.x += b.x; a.y += b.y; return a; }
inline Vec2& operator-=(Vec2& a, Vec2 b) { a.x -= b.x; a.y -= b.y; return a; }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

inline float dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline float cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// The vector turned a quarter turn counter-clockwise.
inline Vec2 left_perp(Vec2 a) { return {-a.y, a.x}; }
/// The vector turned a quarter turn clockwise (the outward normal of a CCW edge).
inline Vec2 right_perp(Vec2 a) { return {a.y, -a.x}; }
inline float length_squared(Vec2 a) { return dot(a, a); }
inline float length(Vec2 a) { return std::sqrt(dot(a, a)); }
inline float distance_squared(Vec2 a, Vec2 b) { return length_squared(b - a); }
inline Vec2 min(Vec2 a, Vec2 b) { return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y}; }
inline Vec2 max(Vec2 a, Vec2 b) { return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y}; }
inline Vec2 lerp(Vec2 a, Vec2 b, float t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }
/// Unit vector along a, or zero for a (near-)zero vector.
inline Vec2 normalize(Vec2 a) {
    const float len = length(a);
    return len > 1e-30f ? (1.0f / len) * a : Vec2{};
}

/// Unit vector along a however short or long a is: scaled by its largest component
/// first, so that the square neither underflows (normalize gives zero below 1e-30) nor
/// overflows. Zero for zero.
inline Vec2 unit_direction(Vec2 a) {
    const float ax = std::fabs(a.x), ay = std::fabs(a.y);
    const float scale = ax > ay ? ax : ay;
    if (!(scale > 0.0f)) {
        return Vec2{};
    }
    const Vec2 scaled{a.x / scale, a.y / scale};  // largest component +-1: length in [1, sqrt 2]
    return (1.0f / length(scaled)) * scaled;
}

/// (x, y), computed in double, scaled down to at most max_length and returned in float:
/// no finite float sum that overflows float (a gravity near the float range times a
/// step) reaches the caller as infinity.
inline Vec2 held_to_length(double x, double y, float max_length) {
    const double len = std::sqrt(x * x + y * y);
    const double scale = len > double(max_length) ? double(max_length) / len : 1.0;
    return {float(x * scale), float(y * scale)};
}

/// Rotation as cosine and sine; kept normalised.
struct Rot {
    float c = 1.0f, s = 0.0f;
};

/// Cross product of a spin (scalar, about z) with a vector: w x r.
inline Vec2 cross(float w, Vec2 r) { return {-w * r.y, w * r.x}; }

/// The engine's own trigonometry (trig.hpp), never libm: the same bits on every build.
inline Rot make_rot(float angle) {
    const SinCos sc = sin_cos(angle);
    return {sc.c, sc.s};
}
inline float get_angle(Rot q) { return i2d::atan2(q.s, q.c); }
inline Rot normalize(Rot q) {
    const float len = std::sqrt(q.c * q.c + q.s * q.s);
    return len > 0.0f ? Rot{q.c / len, q.s / len} : Rot{};
}
/// Turns q by a small angle (rad) and renormalises: the first-order update of the
/// rotation's cosine and sine, exact to second order for the small angles of a substep.
inline Rot integrate_rotation(Rot q, float angle) {
    return normalize(Rot{q.c - angle * q.s, q.s + angle * q.c});
}

inline Vec2 rotate(Rot q, Vec2 v) { return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; }
inline Vec2 inv_rotate(Rot q, Vec2 v) { return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y}; }

struct Transform {
    Vec2 p;
    Rot q;
};

inline Vec2 transform_point(const Transform& xf, Vec2 v) { return rotate(xf.q, v) + xf.p; }
inline Vec2 inv_transform_point(const Transform& xf, Vec2 v) { return inv_rotate(xf.q, v - xf.p); }
/// q * r: turn by r, then by q.
inline Rot mul_rot(Rot q, Rot r) { return {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s}; }
/// q^T * r: the rotation r seen from the frame q.
inline Rot inv_mul_rot(Rot q, Rot r) { return {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c}; }
/// A^-1 * B: frame B expressed in frame A.
/// a then b: b's frame placed by a (b given in a's frame).
inline Transform mul_transforms(const Transform& a, const Transform& b) {
    return {rotate(a.q, b.p) + a.p, mul_rot(a.q, b.q)};
}
inline Transform inv_mul_transforms(const Transform& a, const Transform& b) {
    return {inv_rotate(a.q, b.p - a.p), inv_mul_rot(a.q, b.q)};
}

/// Axis-aligned box; lower is the lower-left corner (y up).
struct AABB {
    Vec2 lower, upper;
};

inline bool overlaps(const AABB& a, const AABB& b) {
    // Closed intervals: touching boxes overlap, as touching shapes are in contact.
    return !(a.upper.x < b.lower.x || b.upper.x < a.lower.x || a.upper.y < b.lower.y || b.upper.y < a.lower.y);
}
/// 2D's surface area: what the cost of a box in a tree query grows with.
inline float perimeter(const AABB& a) { return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y)); }
/// Whether inner lies within outer (boundary included).
inline bool contains(const AABB& outer, const AABB& inner) {
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
           inner.upper.y <= outer.upper.y;
}
/// The smallest box holding both.
inline AABB union_of(const AABB& a, const AABB& b) { return {min(a.lower, b.lower), max(a.upper, b.upper)}; }
/// The box grown by margin (>= 0) on every side.
inline AABB grown(const AABB& a, float margin) { return {a.lower - Vec2{margin, margin}, a.upper + Vec2{margin, margin}}; }
/// The smallest box holding the box at its start and moved by translation.
inline AABB swept(const AABB& a, Vec2 translation) {
    return union_of(a, {a.lower + translation, a.upper + translation});
}
inline bool contains_point(const AABB& a, Vec2 p) {
    return p.x >= a.lower.x && p.x <= a.upper.x && p.y >= a.lower.y && p.y <= a.upper.y;
}
inline Vec2 center(const AABB& a) { return 0.5f * (a.lower + a.upper); }
inline Vec2 extents(const AABB& a) { return 0.5f * (a.upper - a.lower); }
inline Vec2 clamp_to(const AABB& a, Vec2 p) { return max(a.lower, min(a.upper, p)); }
/// The box seen from another origin: each bound less `origin`. Subtraction rounds
/// monotonically, so boxes that held one another, or were the union of others, still are.
inline AABB relative_to(const AABB& a, Vec2 origin) { return {a.lower - origin, a.upper - origin}; }

}  // namespace i2d
