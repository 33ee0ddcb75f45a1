// SPDX-License-Identifier: MIT
// Shape geometry: mass against closed form, bounds, point and box overlap, and ray casts
// against dense sampling along the ray.
#include <cmath>
#include <cstring>

#include "check.h"
#include "collision/geometry.hpp"
#include "collision/hull.hpp"
#include "math/math.hpp"
#include "test_rng.hpp"
#include "world_fixture.hpp"

using namespace i2d;
using unit::box_geometry;
using unit::circle_geometry;
using unit::pi_d;

namespace {

Transform at(float x, float y) { return {{x, y}, Rot{}}; }

// First sample along the ray that lies inside the shape, as a fraction; -1 if none.
float sampled_entry(const Geometry& g, const Transform& xf, Vec2 origin, Vec2 translation, int32_t samples) {
    for (int32_t i = 0; i <= samples; ++i) {
        const float t = float(i) / float(samples);
        if (contains_point(g, xf, origin + t * translation)) {
            return t;
        }
    }
    return -1.0f;
}

}  // namespace

I2D_TEST(unit_geometry_mass_closed_form) {
    const MassData disc = compute_mass(circle_geometry({0.5f, -2.0f}, 0.75f), 3.0f);
    I2D_CHECK_NEAR(disc.mass, 3.0 * pi_d * 0.75 * 0.75, 1e-5);
    I2D_CHECK(disc.center == (Vec2{0.5f, -2.0f}));
    const MassData box = compute_mass(box_geometry(0.5f, 2.0f), 2.0f);
    I2D_CHECK_NEAR(box.mass, 2.0 * 1.0 * 4.0, 1e-6);
    I2D_CHECK(box.center == (Vec2{0.0f, 0.0f}));
}

I2D_TEST(unit_geometry_aabb_is_tight) {
    const AABB c = compute_aabb(circle_geometry({1.0f, 0.0f}, 0.5f), at(2.0f, 3.0f));
    I2D_CHECK(c.lower == (Vec2{2.5f, 2.5f}) && c.upper == (Vec2{3.5f, 3.5f}));
    const AABB b = compute_aabb(box_geometry(1.0f, 0.25f), at(-1.0f, 1.0f));
    I2D_CHECK(b.lower == (Vec2{-2.0f, 0.75f}) && b.upper == (Vec2{0.0f, 1.25f}));
}

namespace {

// The bounds of a polygon by the plain formula: each vertex turned and moved, the lower
// and upper corners kept vertex by vertex. compute_aabb may use SIMD lanes (SSE2), which
// must give these very bits, or a world's trees, and so its steps, would depend on the
// target it was built for.
AABB scalar_polygon_bounds(const Polygon& polygon, const Transform& xf) {
    Vec2 lower = transform_point(xf, polygon.vertices[0]), upper = lower;
    for (int32_t i = 1; i < polygon.count; ++i) {
        const Vec2 p = transform_point(xf, polygon.vertices[i]);
        lower = min(lower, p);
        upper = max(upper, p);
    }
    const Vec2 r{polygon.radius, polygon.radius};
    return {lower - r, upper + r};
}

}  // namespace

I2D_TEST(unit_geometry_polygon_aabb_bits_match_the_scalar_formula) {
    TestRng rng(2024);
    // Quarter turns and zero coordinates give products and sums of zero, whose sign the
    // minima must keep as the scalar code does; -0 positions included.
    const Rot exact_turns[] = {Rot{1.0f, 0.0f}, Rot{0.0f, 1.0f}, Rot{-1.0f, 0.0f}, Rot{0.0f, -1.0f}};
    const float zeros[] = {0.0f, -0.0f};
    int32_t compared = 0, mismatches = 0;
    for (int32_t trial = 0; trial < 4000; ++trial) {
        Geometry g;
        g.type = ShapeType::polygon;
        if (trial % 4 == 0) {
            g.polygon = make_box(rng.uniform(0.01f, 3.0f), rng.uniform(0.01f, 3.0f));
        } else {
            Vec2 points[max_polygon_vertices];
            const int32_t count = 3 + rng.below(max_polygon_vertices - 2);
            for (int32_t i = 0; i < count; ++i) {
                points[i] = {rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f)};
            }
            if (trial % 3 == 0) {  // corners on the axes: turned coordinates of exact zero
                points[0] = {0.0f, 1.5f};
                points[1].y = 0.0f;
            }
            Hull hull;
            if (compute_hull(points, count, hull) != HullStatus::ok) {
                continue;
            }
            g.polygon = make_polygon(hull, trial % 5 == 0 ? rng.uniform(0.0f, 0.2f) : 0.0f);
        }
        Transform xf;
        if (trial % 7 == 0) {
            xf = {{zeros[rng.below(2)], zeros[rng.below(2)]}, exact_turns[rng.below(4)]};
        } else {
            const float angle = rng.uniform(-3.2f, 3.2f);
            const Vec2 origin{rng.uniform(-1000.0f, 1000.0f), rng.uniform(-1000.0f, 1000.0f)};
            xf = {origin, Rot{std::cos(angle), std::sin(angle)}};
        }
        const AABB fast = compute_aabb(g, xf);
        const AABB plain = scalar_polygon_bounds(g.polygon, xf);
        ++compared;
        mismatches += std::memcmp(&fast, &plain, sizeof fast) != 0 ? 1 : 0;
    }
    // Ties between +0 and -0 at the extremes, where only the order of the minima decides
    // the sign: triangles with two corners on an axis (at +0) either side of the origin,
    // turned by exact quarter turns to origins of either sign of zero.
    const Vec2 triangles[4][3] = {{{-1.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}},
                                  {{-1.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, -1.0f}},
                                  {{0.0f, -1.0f}, {0.0f, 1.0f}, {1.0f, 0.0f}},
                                  {{0.0f, -1.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}}};
    for (const auto& triangle : triangles) {
        for (int32_t first = 0; first < 3; ++first) {
            Geometry g;
            g.type = ShapeType::polygon;
            g.polygon.count = 3;
            for (int32_t i = 0; i < 3; ++i) {
                g.polygon.vertices[i] = triangle[(first + i) % 3];
            }
            for (const Rot& q : exact_turns) {
                for (const float x : zeros) {
                    for (const float y : zeros) {
                        const Transform xf{{x, y}, q};
                        const AABB fast = compute_aabb(g, xf);
                        const AABB plain = scalar_polygon_bounds(g.polygon, xf);
                        ++compared;
                        mismatches += std::memcmp(&fast, &plain, sizeof fast) != 0 ? 1 : 0;
                    }
                }
            }
        }
    }
    I2D_CHECK(compared > 3000);
    I2D_CHECK(mismatches == 0);
}

I2D_TEST(unit_geometry_contains_point_includes_boundary) {
    const Geometry circle = circle_geometry({0.0f, 0.0f}, 1.0f);
    I2D_CHECK(contains_point(circle, at(0, 0), {1.0f, 0.0f}));
    I2D_CHECK(!contains_point(circle, at(0, 0), {1.0001f, 0.0f}));
    I2D_CHECK(!contains_point(circle, at(0, 0), {0.71f, 0.71f}));
    const Geometry box = box_geometry(1.0f, 2.0f);
    I2D_CHECK(contains_point(box, at(1, 1), {2.0f, 3.0f}));
    I2D_CHECK(!contains_point(box, at(1, 1), {2.0f, 3.001f}));
}

I2D_TEST(unit_geometry_circle_overlaps_box_only_near_corner_arc) {
    const Geometry circle = circle_geometry({0.0f, 0.0f}, 1.0f);
    // The query box's corner (0.75, 0.75) is outside the circle although the bounds overlap.
    I2D_CHECK(!overlaps_aabb(circle, at(0, 0), {{0.75f, 0.75f}, {2.0f, 2.0f}}));
    I2D_CHECK(overlaps_aabb(circle, at(0, 0), {{0.7f, 0.7f}, {2.0f, 2.0f}}));
    I2D_CHECK(overlaps_aabb(circle, at(0, 0), {{1.0f, -5.0f}, {2.0f, 5.0f}}));  // touching
}

I2D_TEST(unit_geometry_ray_cast_matches_sampling) {
    TestRng rng(7);
    const int32_t samples = 20000;
    int32_t hits = 0;
    for (int32_t trial = 0; trial < 400; ++trial) {
        const bool circle = trial % 2 == 0;
        const Geometry g = circle ? circle_geometry({rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)},
                                                rng.uniform(0.2f, 2.0f))
                                  : box_geometry(rng.uniform(0.2f, 2.0f), rng.uniform(0.2f, 2.0f));
        const Transform xf = at(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f));
        const Vec2 origin{rng.uniform(-8.0f, 8.0f), rng.uniform(-8.0f, 8.0f)};
        // Aim near the shape, and stop short of or past it, so that hits, misses and
        // rays too short to reach all occur.
        const Vec2 target = xf.p + Vec2{rng.uniform(-2.5f, 2.5f), rng.uniform(-2.5f, 2.5f)};
        const Vec2 translation = rng.uniform(0.3f, 1.6f) * (target - origin);
        const RayHit hit = ray_cast(g, xf, origin, translation, 1.0f);
        const float entry = sampled_entry(g, xf, origin, translation, samples);
        if (contains_point(g, xf, origin)) {
            I2D_CHECK(!hit.hit);  // starts inside: no hit
            continue;
        }
        // A grazing ray may touch between samples; allow one sample step either way.
        const float step = 1.0f / float(samples);
        if (entry < 0.0f) {
            I2D_CHECK(!hit.hit || hit.fraction >= 0.0f);
            continue;
        }
        I2D_REQUIRE(hit.hit);
        ++hits;
        I2D_CHECK(hit.fraction <= entry + step && hit.fraction >= entry - 2.0f * step);
        I2D_CHECK_NEAR(length(hit.normal), 1.0, 1e-5);
        // The normal faces the incoming ray and the point lies on the surface.
        I2D_CHECK(dot(hit.normal, translation) <= 0.0f);
        I2D_CHECK(contains_point(g, xf, hit.point + 1e-4f * -hit.normal) || !circle);
    }
    I2D_CHECK(hits > 100);  // the scene generator must actually produce hits
}

I2D_TEST(unit_geometry_ray_cast_box_face_normals) {
    const Geometry box = box_geometry(1.0f, 1.0f);
    const RayHit from_left = ray_cast(box, at(0, 0), {-3.0f, 0.5f}, {4.0f, 0.0f}, 1.0f);
    I2D_REQUIRE(from_left.hit);
    I2D_CHECK_NEAR(from_left.fraction, 0.5, 1e-6);
    I2D_CHECK(from_left.normal == (Vec2{-1.0f, 0.0f}));
    const RayHit from_above = ray_cast(box, at(0, 0), {0.25f, 5.0f}, {0.0f, -8.0f}, 1.0f);
    I2D_REQUIRE(from_above.hit);
    I2D_CHECK_NEAR(from_above.fraction, 0.5, 1e-6);
    I2D_CHECK(from_above.normal == (Vec2{0.0f, 1.0f}));
    // Too short to reach, and clipped by max_fraction.
    I2D_CHECK(!ray_cast(box, at(0, 0), {-3.0f, 0.0f}, {1.9f, 0.0f}, 1.0f).hit);
    I2D_CHECK(!ray_cast(box, at(0, 0), {-3.0f, 0.0f}, {4.0f, 0.0f}, 0.4f).hit);
    // Zero translation hits nothing.
    I2D_CHECK(!ray_cast(box, at(0, 0), {-3.0f, 0.0f}, {0.0f, 0.0f}, 1.0f).hit);
}
