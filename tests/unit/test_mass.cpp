// SPDX-License-Identifier: MIT
// Mass, centroid and rotational inertia of every kind against closed forms, the parallel
// axis theorem and a numerical integration over a fine grid.
#include <cmath>
#include <cstdio>

#include "brute_geometry.hpp"
#include "check.h"
#include "collision/geometry.hpp"
#include "collision/hull.hpp"
#include "world_fixture.hpp"

using namespace i2d;
using unit::box_geometry;
using unit::capsule_geometry;
using unit::circle_geometry;
using unit::pi_d;
using unit::polygon_geometry;
using unit::segment_geometry;

namespace {

// How close compute_mass must come to the 1500 x 1500 grid of integrate(): the grid's
// cells along the boundary are in or out whole, so mass and inertia are good to a few
// parts in a thousand, the centre to a millimetre.
constexpr double grid_mass_tolerance = 2e-3;     // share of the grid's mass
constexpr double grid_center_tolerance = 1e-3;   // m
constexpr double grid_inertia_tolerance = 3e-3;  // share of the grid's inertia
constexpr int32_t grid_cells = 1500;             // per side

struct Integrated {
    double mass = 0.0, cx = 0.0, cy = 0.0, inertia = 0.0;
};

// Midpoint rule over an n x n grid covering the shape, using the brute-force signed
// distance for membership: independent of the library's mass code.
Integrated integrate(const Geometry& g, double density, int32_t n) {
    const brute::Core core = brute::core_of(g, Transform{});
    const AABB box = compute_aabb(g, Transform{});
    const double w = double(box.upper.x) - box.lower.x, h = double(box.upper.y) - box.lower.y;
    const double dx = w / n, dy = h / n;
    double m = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0;
    for (int32_t i = 0; i < n; ++i) {
        for (int32_t j = 0; j < n; ++j) {
            const brute::P q{box.lower.x + (i + 0.5) * dx, box.lower.y + (j + 0.5) * dy};
            if (brute::signed_distance(core, q) <= 0.0) {
                m += 1.0, sx += q.x, sy += q.y, sxx += q.x * q.x + q.y * q.y;
            }
        }
    }
    Integrated out;
    const double cell = dx * dy * density;
    out.mass = m * cell;
    out.cx = sx / m, out.cy = sy / m;
    out.inertia = sxx * cell - out.mass * (out.cx * out.cx + out.cy * out.cy);
    return out;
}

// compute_mass against the grid: mass, centre and inertia.
void check_matches_integration(const MassData& m, const Integrated& grid) {
    I2D_CHECK_NEAR(m.mass, grid.mass, grid_mass_tolerance * grid.mass);
    I2D_CHECK_NEAR(m.center.x, grid.cx, grid_center_tolerance);
    I2D_CHECK_NEAR(m.center.y, grid.cy, grid_center_tolerance);
    I2D_CHECK_NEAR(m.rotational_inertia, grid.inertia, grid_inertia_tolerance * grid.inertia);
}

}  // namespace

I2D_TEST(unit_mass_box_and_disc_closed_form) {
    const MassData box = compute_mass(polygon_geometry(make_box(0.5f, 2.0f)), 2.0f);
    I2D_CHECK_NEAR(box.mass, 2.0 * 1.0 * 4.0, 1e-5);
    I2D_CHECK_NEAR(box.center.x, 0.0, 1e-6);
    I2D_CHECK_NEAR(box.center.y, 0.0, 1e-6);
    // m (w^2 + h^2) / 12 with full sizes w = 1, h = 4.
    I2D_CHECK_NEAR(box.rotational_inertia, 8.0 * (1.0 + 16.0) / 12.0, 1e-5);

    const MassData d = compute_mass(circle_geometry({0.5f, -2.0f}, 0.75f), 3.0f);
    const double m = 3.0 * pi_d * 0.75 * 0.75;
    I2D_CHECK_NEAR(d.mass, m, 1e-5);
    I2D_CHECK(d.center == (Vec2{0.5f, -2.0f}));
    I2D_CHECK_NEAR(d.rotational_inertia, 0.5 * m * 0.75 * 0.75, 1e-5);

    const MassData s = compute_mass(segment_geometry({0.0f, 0.0f}, {2.0f, 0.0f}), 5.0f);
    I2D_CHECK(s.mass == 0.0f && s.rotational_inertia == 0.0f);
}

I2D_TEST(unit_mass_offset_box_and_triangle) {
    // An offset, rotated box: same mass and inertia about its own centroid, which is the
    // offset (the parallel axis shift is the body's business).
    const float c = std::cos(0.7f), s = std::sin(0.7f);
    const MassData box = compute_mass(polygon_geometry(make_offset_box(1.5f, 0.25f, {3.0f, -2.0f}, Rot{c, s})), 2.0f);
    const double m = 2.0 * 3.0 * 0.5;
    I2D_CHECK_NEAR(box.mass, m, 1e-5);
    I2D_CHECK_NEAR(box.center.x, 3.0, 1e-5);
    I2D_CHECK_NEAR(box.center.y, -2.0, 1e-5);
    I2D_CHECK_NEAR(box.rotational_inertia, m * (9.0 + 0.25) / 12.0, 1e-5);

    // Triangle: area |cross| / 2, centroid the vertex mean, inertia about the centroid
    // m (a^2 + b^2 + c^2) / 36 with a, b, c the side lengths. Placed far from the origin.
    const Vec2 pts[3] = {{1000.0f, 500.0f}, {1004.0f, 500.0f}, {1001.0f, 503.0f}};
    Hull hull;
    I2D_REQUIRE(compute_hull(pts, 3, hull) == HullStatus::ok);
    const MassData tri = compute_mass(polygon_geometry(make_polygon(hull, 0.0f)), 1.5f);
    const double area = 0.5 * 4.0 * 3.0;
    const double sides = 16.0 + (9.0 + 9.0) + (1.0 + 9.0);
    I2D_CHECK_NEAR(tri.mass, 1.5 * area, 1e-4);
    I2D_CHECK_NEAR(tri.center.x, 1005.0 / 3.0 + 2000.0 / 3.0, 1e-3);
    I2D_CHECK_NEAR(tri.center.y, 501.0, 1e-3);
    I2D_CHECK_NEAR(tri.rotational_inertia, 1.5 * area * sides / 36.0, 1e-3);
    std::printf("triangle far from origin: inertia error %.3g (relative %.3g)\n",
                std::fabs(tri.rotational_inertia - 1.5 * area * sides / 36.0),
                std::fabs(tri.rotational_inertia - 1.5 * area * sides / 36.0) / (1.5 * area * sides / 36.0));
}

I2D_TEST(unit_mass_capsule_closed_form_and_integration) {
    // Horizontal capsule, length L = 2, radius r = 0.5, density 2:
    // rectangle 2r x L, I = m (L^2 + 4 r^2) / 12; two half discs = one disc of mass md with
    // I = md (r^2 / 2 + h^2 + 2 h (4 r / (3 pi))), h = L / 2 (parallel axis per half disc).
    Geometry g = capsule_geometry({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f);
    const double rho = 2.0, L = 2.0, r = 0.5, h = 1.0;
    const double mr = rho * 2.0 * r * L, md = rho * pi_d * r * r;
    const double expected = mr * (L * L + 4 * r * r) / 12.0 + md * (0.5 * r * r + h * h + 2.0 * h * 4.0 * r / (3.0 * pi_d));
    const MassData cap = compute_mass(g, float(rho));
    I2D_CHECK_NEAR(cap.mass, mr + md, 1e-5);
    I2D_CHECK_NEAR(cap.rotational_inertia, expected, 1e-5);
    // A turned, offset capsule against the grid.
    g.capsule = {{0.3f, -0.2f}, {1.1f, 0.9f}, 0.35f};
    const MassData m = compute_mass(g, 3.0f);
    const Integrated num = integrate(g, 3.0, grid_cells);
    check_matches_integration(m, num);
    std::printf("capsule vs grid: mass %.3g, inertia %.3g relative\n", std::fabs(m.mass - num.mass) / num.mass,
                std::fabs(m.rotational_inertia - num.inertia) / num.inertia);
}

I2D_TEST(unit_mass_rounded_polygon_matches_integration) {
    const Vec2 pts[5] = {{0.0f, 0.0f}, {1.2f, -0.1f}, {1.5f, 0.8f}, {0.6f, 1.3f}, {-0.2f, 0.7f}};
    Hull hull;
    I2D_REQUIRE(compute_hull(pts, 5, hull) == HullStatus::ok);
    for (float radius : {0.0f, 0.1f, 0.4f}) {
        const Geometry g = polygon_geometry(make_polygon(hull, radius));
        const MassData m = compute_mass(g, 2.5f);
        const Integrated num = integrate(g, 2.5, grid_cells);
        check_matches_integration(m, num);
        std::printf("rounded polygon r=%.1f vs grid: mass %.3g, inertia %.3g relative\n", double(radius),
                    std::fabs(m.mass - num.mass) / num.mass, std::fabs(m.rotational_inertia - num.inertia) / num.inertia);
        I2D_CHECK_NEAR(area(g), m.mass / 2.5, 1e-5);
    }
    // A rounded box in closed form: rectangle (w+2r) x h, w x 2r strips... simpler: box
    // of half sizes a, b rounded by r = core + 4 side slabs + one full disc.
    const float a = 1.0f, b = 0.5f, r = 0.25f;
    const MassData m = compute_mass(box_geometry(a, b, r), 1.0f);
    const double A = 4.0 * a * b + 2.0 * (2.0 * a) * r + 2.0 * (2.0 * b) * r + pi_d * r * r;
    // Inertia: core 4ab((2a)^2+(2b)^2)/12; top/bottom slabs (2a x r) at distance b + r/2;
    // left/right slabs (r x 2b) at a + r/2; four quarter discs at the corners (a, b).
    const double core = 4.0 * a * b * (4.0 * a * a + 4.0 * b * b) / 12.0;
    const double tb = 2.0 * (2.0 * a * r * ((4.0 * a * a + r * r) / 12.0 + (b + r / 2.0) * (b + r / 2.0)));
    const double lr = 2.0 * (2.0 * b * r * ((r * r + 4.0 * b * b) / 12.0 + (a + r / 2.0) * (a + r / 2.0)));
    const double lq = 4.0 * r / (3.0 * pi_d);  // quarter disc centroid offset per axis
    const double q_mass = pi_d * r * r / 4.0;
    const double q_own = q_mass * r * r / 2.0 - q_mass * 2.0 * lq * lq;  // about its own centroid
    const double qx = a + lq, qy = b + lq;
    const double quarters = 4.0 * (q_own + q_mass * (qx * qx + qy * qy));
    I2D_CHECK_NEAR(m.mass, A, 1e-5);
    I2D_CHECK_NEAR(m.rotational_inertia, core + tb + lr + quarters, 1e-5);
}
