// SPDX-License-Identifier: MIT
// Convex hulls against a brute-force hull of random point clouds, refusals of degenerate
// input, and polygon construction (normals, centroid far from the origin, boxes).
#include <cmath>
#include <string>

#include "brute_geometry.hpp"
#include "check.h"
#include "collision/hull.hpp"

using namespace i2d;
using brute::P;

namespace {

// Brute force: i is a hull vertex iff some other point j has every point on the left of
// or on the line i -> j, and i is not strictly between two points on that line.
bool is_extreme(const Vec2* pts, int32_t n, int32_t i) {
    for (int32_t j = 0; j < n; ++j) {
        if (j == i) continue;
        bool all_left = true;
        for (int32_t k = 0; k < n && all_left; ++k) {
            const double c = brute::cross(brute::p(pts[j]) - brute::p(pts[i]), brute::p(pts[k]) - brute::p(pts[i]));
            all_left = c >= -1e-9;
        }
        if (all_left) return true;
    }
    return false;
}

// Distance of p outside a CCW hull (0 inside).
double outside_distance(const Hull& h, Vec2 q) {
    double worst = 0.0;
    for (int32_t i = 0; i < h.count; ++i) {
        const P a = brute::p(h.points[i]), b = brute::p(h.points[(i + 1) % h.count]);
        worst = std::fmax(worst, brute::cross(brute::p(q) - a, b - a) / brute::len(b - a));
    }
    return worst;
}

}  // namespace

I2D_TEST(unit_hull_random_clouds_match_brute_force) {
    TestRng rng(11);
    int32_t built = 0;
    for (int32_t trial = 0; trial < 5000; ++trial) {
        const int32_t n = 3 + rng.below(6);
        Vec2 pts[8];
        const float scale = rng.uniform(0.05f, 10.0f);
        const Vec2 offset{rng.uniform(-100.0f, 100.0f), rng.uniform(-100.0f, 100.0f)};
        for (int32_t i = 0; i < n; ++i) {
            pts[i] = offset + scale * Vec2{rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)};
        }
        Hull hull;
        if (compute_hull(pts, n, hull) != HullStatus::ok) {
            continue;
        }
        ++built;
        I2D_REQUIRE(hull.count >= 3 && hull.count <= n);
        // Strictly convex and counter-clockwise, made of input points.
        for (int32_t i = 0; i < hull.count; ++i) {
            const P a = brute::p(hull.points[i]), b = brute::p(hull.points[(i + 1) % hull.count]);
            const P c = brute::p(hull.points[(i + 2) % hull.count]);
            I2D_CHECK(brute::cross(b - a, c - b) > 0.0);
            bool is_input = false;
            for (int32_t k = 0; k < n; ++k) is_input = is_input || pts[k] == hull.points[i];
            I2D_CHECK(is_input);
        }
        // Every input point inside (collinear removal may shave off less than a slop).
        for (int32_t k = 0; k < n; ++k) {
            I2D_CHECK(outside_distance(hull, pts[k]) <= linear_slop);
        }
        // Every brute-force extreme point that sticks out by more than the slop is a vertex.
        for (int32_t k = 0; k < n; ++k) {
            if (!is_extreme(pts, n, k)) continue;
            Hull without;
            Vec2 others[8];
            int32_t m = 0;
            for (int32_t j = 0; j < n; ++j) if (j != k) others[m++] = pts[j];
            if (m >= 3 && compute_hull(others, m, without) == HullStatus::ok &&
                outside_distance(without, pts[k]) > 2.0 * linear_slop) {
                bool found = false;
                for (int32_t i = 0; i < hull.count; ++i) found = found || hull.points[i] == pts[k];
                I2D_CHECK(found);
            }
        }
    }
    I2D_CHECK(built > 4000);
}

I2D_TEST(unit_hull_refuses_degenerate_input) {
    Hull hull;
    const Vec2 line[4] = {{0.0f, 0.0f}, {1.0f, 1.0f}, {2.0f, 2.0f}, {3.0f, 3.0f}};
    I2D_CHECK(compute_hull(line, 4, hull) == HullStatus::collinear_points);
    I2D_CHECK(hull.count == 0);
    // Within a slop of one line is collinear too.
    const Vec2 nearly[5] = {{0.0f, 0.0f}, {1.0f, 0.002f}, {2.0f, -0.002f}, {3.0f, 0.001f}, {4.0f, 0.0f}};
    I2D_CHECK(compute_hull(nearly, 5, hull) == HullStatus::collinear_points);
    const Vec2 dup[3] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.001f, 0.001f}};
    I2D_CHECK(compute_hull(dup, 3, hull) == HullStatus::duplicate_points);
    const Vec2 same[4] = {{2.0f, 2.0f}, {2.0f, 2.0f}, {2.0f, 2.0f}, {2.0f, 2.0f}};
    I2D_CHECK(compute_hull(same, 4, hull) == HullStatus::duplicate_points);
    // Equilateral, side 6 mm: heights above the slop, area 1.56e-5 below slop^2.
    const Vec2 tiny[3] = {{0.0f, 0.0f}, {0.006f, 0.0f}, {0.003f, 0.0051962f}};
    I2D_CHECK(compute_hull(tiny, 3, hull) == HullStatus::area_too_small);
    I2D_CHECK(compute_hull(tiny, 2, hull) == HullStatus::bad_count);
    const Vec2 nine[9] = {};
    I2D_CHECK(compute_hull(nine, 9, hull) == HullStatus::bad_count);
    // A point on an edge and a duplicate vertex are dropped, not refused.
    const Vec2 square[6] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.0f}, {1.0f, 1.001f}};
    I2D_REQUIRE(compute_hull(square, 6, hull) == HullStatus::ok);
    I2D_CHECK(hull.count == 4);
    I2D_CHECK(std::string(hull_status_message(HullStatus::collinear_points)).find("collinear") != std::string::npos);
}

I2D_TEST(unit_hull_polygon_normals_and_centroid) {
    // A triangle far from the origin: the centroid is the vertex mean.
    const Vec2 far[3] = {{10000.0f, 10000.0f}, {10003.0f, 10000.0f}, {10000.0f, 10006.0f}};
    Hull hull;
    I2D_REQUIRE(compute_hull(far, 3, hull) == HullStatus::ok);
    const Polygon p = make_polygon(hull, 0.1f);
    I2D_CHECK_NEAR(p.centroid.x, 10001.0, 2e-3);
    I2D_CHECK_NEAR(p.centroid.y, 10002.0, 2e-3);
    I2D_CHECK(p.radius == 0.1f && p.count == 3);
    for (int32_t i = 0; i < p.count; ++i) {
        const Vec2 e = p.vertices[(i + 1) % p.count] - p.vertices[i];
        I2D_CHECK_NEAR(length(p.normals[i]), 1.0, 1e-6);
        I2D_CHECK_NEAR(dot(p.normals[i], e), 0.0, 1e-3);
        I2D_CHECK(cross(e, p.normals[i]) < 0.0f);  // outward: to the right of a CCW edge
    }
    // Offset, rotated box: corners, normals and centroid.
    const float c = std::cos(0.5f), s = std::sin(0.5f);
    const Polygon box = make_offset_box(2.0f, 1.0f, {3.0f, -1.0f}, Rot{c, s});
    I2D_CHECK(box.count == 4 && box.radius == 0.0f);
    I2D_CHECK(box.centroid == (Vec2{3.0f, -1.0f}));
    I2D_CHECK_NEAR(box.vertices[2].x, 3.0 + 2.0 * c - 1.0 * s, 1e-6);
    I2D_CHECK_NEAR(box.vertices[2].y, -1.0 + 2.0 * s + 1.0 * c, 1e-6);
    I2D_CHECK_NEAR(box.normals[1].x, c, 1e-7);
    I2D_CHECK_NEAR(box.normals[1].y, s, 1e-7);
    const Polygon sq = make_square(0.5f);
    I2D_CHECK(sq.vertices[0] == (Vec2{-0.5f, -0.5f}) && sq.vertices[2] == (Vec2{0.5f, 0.5f}));
}
