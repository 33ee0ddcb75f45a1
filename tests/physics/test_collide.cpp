// SPDX-License-Identifier: MIT
// The pure collision functions (circles, AABBs, AABB against circle) on every case of the
// seed's ERRATA, checked against hand-worked numbers and a double-precision reference.
//
// Every expected value below is worked out by hand from the geometry (comments show the
// arithmetic) or computed by the reference functions in this file; none is copied from
// the library's output. Coordinates are chosen exactly representable in float so that
// "touching" really means distance 0.
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "check.h"
#include "physics_fixture.hpp"

using phys::deepest_penetration;
using phys::report_case;

namespace {

// Tolerance for hand-worked values: a few float ulps of coordinates up to ~10.
constexpr double tol = 1e-5;

i2d_vec2 v2(double x, double y) { return i2d_vec2{float(x), float(y)}; }
i2d_circle circle(double x, double y, double r) { return i2d_circle{v2(x, y), float(r)}; }
i2d_aabb aabb(double x0, double y0, double x1, double y1) { return i2d_aabb{v2(x0, y0), v2(x1, y1)}; }
i2d_aabb moved(i2d_aabb b, double dx, double dy) {
    return aabb(b.min.x + dx, b.min.y + dy, b.max.x + dx, b.max.y + dy);
}
i2d_circle moved(i2d_circle c, double dx, double dy) { return circle(c.center.x + dx, c.center.y + dy, c.radius); }
i2d_vec2 center_of(i2d_aabb b) { return v2(0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)); }
i2d_vec2 center_of(i2d_circle c) { return c.center; }

// ---- Double-precision geometry: the brute-force reference ---------------------------

// Signed gap between two circles: > 0 apart, 0 touching, < 0 overlapping.
double gap(i2d_circle a, i2d_circle b) {
    return std::hypot(double(b.center.x) - a.center.x, double(b.center.y) - a.center.y) - a.radius - b.radius;
}

// Signed gap between two boxes: the larger of the two per-axis interval gaps. The boxes
// share a point iff neither axis separates them, i.e. iff this is <= 0.
double gap(i2d_aabb a, i2d_aabb b) {
    double gx = std::max(double(a.min.x) - b.max.x, double(b.min.x) - a.max.x);
    double gy = std::max(double(a.min.y) - b.max.y, double(b.min.y) - a.max.y);
    return std::max(gx, gy);
}

// Signed distance from a point to a box: Euclidean outside, minus the distance to the
// nearest face inside.
double signed_distance(i2d_aabb b, double px, double py) {
    double dx = std::max({double(b.min.x) - px, px - double(b.max.x), 0.0});
    double dy = std::max({double(b.min.y) - py, py - double(b.max.y), 0.0});
    if (dx > 0 || dy > 0) {
        return std::hypot(dx, dy);
    }
    return -std::min({px - double(b.min.x), double(b.max.x) - px, py - double(b.min.y), double(b.max.y) - py});
}

double gap(i2d_aabb a, i2d_circle b) { return signed_distance(a, b.center.x, b.center.y) - b.radius; }

// ---- Checks shared by every case ------------------------------------------------------

struct Expected {
    i2d_vec2 normal;
    double penetration;
    int count;
    i2d_vec2 points[2];
};

// Contract properties that hold for every touching pair: the normal is unit and points
// from A to B (never against the centre difference), and moving B along the normal by the
// largest penetration leaves the shapes touching or apart.
template <class A, class B>
void check_properties(A a, B b, const i2d_manifold& m, double gap_tol) {
    if (m.point_count <= 0) {
        return;
    }
    I2D_CHECK_NEAR(std::hypot(m.normal.x, m.normal.y), 1.0, 1e-6);
    i2d_vec2 ca = center_of(a), cb = center_of(b);
    double along = m.normal.x * (double(cb.x) - ca.x) + m.normal.y * (double(cb.y) - ca.y);
    I2D_CHECK(along >= -gap_tol);
    double p = deepest_penetration(m);
    I2D_CHECK(p >= -gap_tol);
    B separated = moved(b, m.normal.x * p, m.normal.y * p);
    I2D_CHECK(gap(a, separated) >= -gap_tol);
}

// Point order is not part of the contract: match each expected point to the nearest one.
void check_points(const i2d_manifold& m, const Expected& e) {
    for (int i = 0; i < e.count; ++i) {
        double best = std::numeric_limits<double>::infinity();
        int best_j = 0;
        for (int j = 0; j < m.point_count && j < 2; ++j) {
            double d = std::hypot(double(m.points[j].point.x) - e.points[i].x, double(m.points[j].point.y) - e.points[i].y);
            if (d < best) {
                best = d;
                best_j = j;
            }
        }
        I2D_CHECK_NEAR(m.points[best_j].point.x, e.points[i].x, tol);
        I2D_CHECK_NEAR(m.points[best_j].point.y, e.points[i].y, tol);
        I2D_CHECK_NEAR(m.points[best_j].penetration, e.penetration, tol);
    }
    if (m.point_count == 2) {
        I2D_CHECK(m.points[0].id != m.points[1].id);
    }
}

template <class A, class B>
void check_manifold(const char* what, A a, B b, const i2d_manifold& m, const Expected& e) {
    int before = i2d_check_failures;
    I2D_CHECK_STATUS(i2d_last_status(), I2D_OK);
    I2D_CHECK(m.point_count == e.count);
    if (e.count > 0 && m.point_count == e.count) {
        I2D_CHECK_NEAR(m.normal.x, e.normal.x, tol);
        I2D_CHECK_NEAR(m.normal.y, e.normal.y, tol);
        check_points(m, e);
        check_properties(a, b, m, tol);
    }
    report_case(before, what);
}

Expected none() { return Expected{v2(0, 0), 0, 0, {v2(0, 0), v2(0, 0)}}; }
Expected one(i2d_vec2 n, double pen, i2d_vec2 p) { return Expected{n, pen, 1, {p, v2(0, 0)}}; }
Expected two(i2d_vec2 n, double pen, i2d_vec2 p0, i2d_vec2 p1) { return Expected{n, pen, 2, {p0, p1}}; }
Expected flipped(Expected e) {
    e.normal = v2(-e.normal.x, -e.normal.y);
    return e;
}

// Circles in both argument orders: swapping A and B flips the normal and keeps the
// penetration and the contact point. The point is worked out here from the expected
// normal: midway between A's surface (a + n ra) and B's surface (b - n rb).
void check_circles(const char* what, i2d_circle a, i2d_circle b, i2d_vec2 n, double pen, int count) {
    Expected e = none();
    if (count == 1) {
        double ax = a.center.x + n.x * a.radius, ay = a.center.y + n.y * a.radius;
        double bx = b.center.x - n.x * b.radius, by = b.center.y - n.y * b.radius;
        e = one(n, pen, v2(0.5 * (ax + bx), 0.5 * (ay + by)));
    }
    check_manifold(what, a, b, i2d_collide_circles(a, b), e);
    check_manifold(what, b, a, i2d_collide_circles(b, a), flipped(e));
}

// Boxes in both orders: the swapped manifold has the opposite normal, same points.
void check_aabbs(const char* what, i2d_aabb a, i2d_aabb b, const Expected& e) {
    check_manifold(what, a, b, i2d_collide_aabbs(a, b), e);
    check_manifold(what, b, a, i2d_collide_aabbs(b, a), flipped(e));
}

// Box against circle (one order only: the function takes the box first). The expected
// point is worked out from the box's surface point pa and the normal: midway between pa
// and the circle's deepest point c - n r.
void check_aabb_circle(const char* what, i2d_aabb a, i2d_circle b, i2d_vec2 n, double pen, i2d_vec2 pa, int count) {
    Expected e = none();
    if (count == 1) {
        double bx = b.center.x - n.x * b.radius, by = b.center.y - n.y * b.radius;
        e = one(n, pen, v2(0.5 * (pa.x + bx), 0.5 * (pa.y + by)));
    }
    check_manifold(what, a, b, i2d_collide_aabb_circle(a, b), e);
}

void check_invalid(const char* what, const i2d_manifold& m) {
    int before = i2d_check_failures;
    I2D_CHECK(m.point_count == 0);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    report_case(before, what);
}

// Random shapes from a fixed seed, so that the randomized tests are reproducible: corners
// and centres in [-3, 3), sizes and radii in [0.05, 3).
using Rng = phys::SplitMix64;
float random_coord(Rng& rng) { return float(rng.uniform(-3, 3)); }
float random_size(Rng& rng) { return float(rng.uniform(0.05, 3)); }

i2d_aabb random_aabb(Rng& rng) {
    float x = random_coord(rng), y = random_coord(rng), w = random_size(rng), h = random_size(rng);
    return i2d_aabb{i2d_vec2{x, y}, i2d_vec2{x + w, y + h}};
}
i2d_circle random_circle(Rng& rng) {
    return i2d_circle{i2d_vec2{random_coord(rng), random_coord(rng)}, random_size(rng)};
}

// Reference penetration (double) of a touching pair: the depth of the minimum
// translation along the contact normal.
double reference_penetration(i2d_circle a, i2d_circle b) { return -gap(a, b); }
double reference_penetration(i2d_aabb a, i2d_aabb b) {
    double px = std::min(double(a.max.x) - b.min.x, double(b.max.x) - a.min.x);
    double py = std::min(double(a.max.y) - b.min.y, double(b.max.y) - a.min.y);
    return std::min(px, py);
}
double reference_penetration(i2d_aabb a, i2d_circle b) { return -gap(a, b); }

i2d_manifold collide(i2d_circle a, i2d_circle b) { return i2d_collide_circles(a, b); }
i2d_manifold collide(i2d_aabb a, i2d_aabb b) { return i2d_collide_aabbs(a, b); }
i2d_manifold collide(i2d_aabb a, i2d_circle b) { return i2d_collide_aabb_circle(a, b); }

// Runs many random pairs. Overlap must be reported iff the reference says the shapes
// share a point; pairs within `band` of touching are left out of that comparison only,
// since float rounding may legitimately decide them either way.
template <class A, class B, class MakeA, class MakeB>
void random_pairs(const char* what, uint64_t seed, MakeA make_a, MakeB make_b) {
    const int pairs = 20000;
    const double band = 1e-4;
    Rng rng{seed};
    int touching = 0, apart = 0, mismatches = 0;
    for (int i = 0; i < pairs && mismatches < 10; ++i) {
        A a = make_a(rng);
        B b = make_b(rng);
        int before = i2d_check_failures;
        i2d_manifold m = collide(a, b);
        double g = gap(a, b);
        I2D_CHECK(i2d_last_status() == I2D_OK);
        I2D_CHECK(m.point_count >= 0 && m.point_count <= 2);
        if (std::fabs(g) > band) {
            I2D_CHECK((m.point_count > 0) == (g < 0));
        }
        if (m.point_count > 0) {
            ++touching;
            I2D_CHECK_NEAR(deepest_penetration(m), reference_penetration(a, b), band);
            check_properties(a, b, m, band);
        } else {
            ++apart;
        }
        if (i2d_check_failures != before) {
            ++mismatches;
            fprintf(stderr, "    ... %s pair %d (seed %llu), reference gap %.9g, point_count %d\n", what, i,
                    (unsigned long long)seed, g, m.point_count);
        }
    }
    // The generator must exercise both outcomes, or the test proves nothing.
    I2D_CHECK(touching > pairs / 10);
    I2D_CHECK(apart > pairs / 10);
}

}  // namespace

// ---- Circles --------------------------------------------------------------------------

I2D_TEST(phys_collide_circles_overlap) {
    // Along +x: d = 1.5, ra + rb = 2: penetration 0.5.
    check_circles("circles overlap +x", circle(0, 0, 1), circle(1.5, 0, 1), v2(1, 0), 0.5, 1);
    // And on the other side of each axis.
    check_circles("circles overlap -x", circle(0, 0, 1), circle(-1.5, 0, 1), v2(-1, 0), 0.5, 1);
    check_circles("circles overlap +y", circle(0, 0, 1), circle(0, 1.25, 0.5), v2(0, 1), 0.25, 1);
    check_circles("circles overlap -y", circle(0, 0, 1), circle(0, -1.25, 0.5), v2(0, -1), 0.25, 1);
    // Diagonal, unequal radii (3-4-5 triangle): d = 5, ra + rb = 6, n = (0.6, 0.8).
    check_circles("circles overlap diagonal", circle(1, 2, 2), circle(4, 6, 4), v2(0.6, 0.8), 1, 1);
    check_circles("circles overlap diagonal 2", circle(1, 2, 2), circle(-2, -2, 4), v2(-0.6, -0.8), 1, 1);
    // ERRATA: penetration is ra + rb - d with the unsquared sum (the text squared it).
    // Here (ra + rb)^2 - d = 9 - 2 = 7 would be the garbled answer; right is 3 - 2 = 1.
    check_circles("circles unsquared sum", circle(0, 0, 1.5), circle(0, 2, 1.5), v2(0, 1), 1, 1);
    // One circle inside the other: d = 0.5, penetration 3 + 1 - 0.5 = 3.5.
    check_circles("circle inside circle", circle(0, 0, 3), circle(0.5, 0, 1), v2(1, 0), 3.5, 1);
}

I2D_TEST(phys_collide_circles_apart) {
    // ERRATA: the text had "r < distance" (overlap reported when apart) and (ax + bx)^2.
    check_circles("circles apart +x", circle(0, 0, 1), circle(2.5, 0, 1), v2(0, 0), 0, 0);
    check_circles("circles apart -y", circle(0, 0, 1), circle(0, -2.5, 1), v2(0, 0), 0, 0);
    // Diagonal: d = 5, ra + rb = 4.9.
    check_circles("circles apart diagonal", circle(0, 0, 2), circle(3, 4, 2.9), v2(0, 0), 0, 0);
    // Symmetric about the origin: (ax + bx)^2 + (ay + by)^2 would be 0 and report overlap.
    check_circles("circles apart symmetric", circle(-3, -4, 1), circle(3, 4, 1), v2(0, 0), 0, 0);
}

I2D_TEST(phys_collide_circles_touching) {
    // Distance exactly ra + rb: one contact with penetration 0.
    check_circles("circles touching +x", circle(0, 0, 1), circle(3, 0, 2), v2(1, 0), 0, 1);
    check_circles("circles touching -y", circle(0, 0, 1), circle(0, -2, 1), v2(0, -1), 0, 1);
    check_circles("circles touching diagonal", circle(0, 0, 2), circle(3, 4, 3), v2(0.6, 0.8), 0, 1);
}

I2D_TEST(phys_collide_circles_same_center) {
    // ERRATA: same centre gives normal (1, 0) and penetration ra + rb (the text said ra).
    // The normal is fixed, so it is (1, 0) in both argument orders; the point is midway
    // between A's surface c + n ra and B's surface c - n rb.
    i2d_circle a = circle(1, 1, 1), b = circle(1, 1, 2);
    check_manifold("same centre a,b", a, b, i2d_collide_circles(a, b), one(v2(1, 0), 3, v2(0.5 * (2 + -1), 1)));
    check_manifold("same centre b,a", b, a, i2d_collide_circles(b, a), one(v2(1, 0), 3, v2(0.5 * (3 + 0), 1)));
    // Identical circles.
    check_manifold("identical circles", a, a, i2d_collide_circles(a, a), one(v2(1, 0), 2, v2(1, 1)));
}

// ---- AABB against AABB -----------------------------------------------------------------

I2D_TEST(phys_collide_aabbs_x_axis) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    // B to the right: x overlap 0.25 < y overlap 1, so x; points on the contact edge at
    // x midway between A's right face (2) and B's left face (1.75), at the ends of the
    // y overlap [1, 2].
    check_aabbs("aabbs +x", a, aabb(1.75, 1, 3.75, 3), two(v2(1, 0), 0.25, v2(1.875, 1), v2(1.875, 2)));
    // B to the left: faces 0 (A) and 0.25 (B).
    check_aabbs("aabbs -x", a, aabb(-1.75, -1, 0.25, 1), two(v2(-1, 0), 0.25, v2(0.125, 0), v2(0.125, 1)));
    // ERRATA: the text resolved along x when x_overlap > y_overlap. Here x overlap is 1.5
    // and y overlap 1.75: least penetration is still x.
    check_aabbs("aabbs x when x < y", a, aabb(0.5, 0.25, 3.5, 4), two(v2(1, 0), 1.5, v2(1.25, 0.25), v2(1.25, 2)));
}

I2D_TEST(phys_collide_aabbs_y_axis) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    check_aabbs("aabbs +y", a, aabb(1, 1.75, 3, 3.75), two(v2(0, 1), 0.25, v2(1, 1.875), v2(2, 1.875)));
    check_aabbs("aabbs -y", a, aabb(-1, -1.75, 1, 0.25), two(v2(0, -1), 0.25, v2(0, 0.125), v2(1, 0.125)));
    // x overlap 1.75 > y overlap 1.5: y, even though the text's test would pick x.
    check_aabbs("aabbs y when y < x", a, aabb(0.25, 0.5, 4, 3.5), two(v2(0, 1), 1.5, v2(0.25, 1.25), v2(2, 1.25)));
}

I2D_TEST(phys_collide_aabbs_equal_overlap) {
    // Equal overlaps (0.5 and 0.5) resolve along x, sign from the centre difference.
    i2d_aabb a = aabb(0, 0, 2, 2);
    check_aabbs("equal overlap +x", a, aabb(1.5, 1.5, 3.5, 3.5), two(v2(1, 0), 0.5, v2(1.75, 1.5), v2(1.75, 2)));
    check_aabbs("equal overlap -x", a, aabb(-1.5, -1.5, 0.5, 0.5), two(v2(-1, 0), 0.5, v2(0.25, 0), v2(0.25, 0.5)));
    // Identical boxes: equal overlaps and coinciding centres: +x, penetration the width;
    // the points sit midway between A's right face (1) and B's left face (0).
    i2d_aabb u = aabb(0, 0, 1, 1);
    check_manifold("identical boxes", u, u, i2d_collide_aabbs(u, u), two(v2(1, 0), 1, v2(0.5, 0), v2(0.5, 1)));
}

I2D_TEST(phys_collide_aabbs_same_center) {
    // Centres coincide on the resolving axis: +axis. Here x depth 1.5 < y depth 2.5.
    // (ERRATA: the text's "else normal = (0, 0)" is wrong; a fixed unit axis is right.)
    i2d_aabb a = aabb(0, 0, 2, 2), b = aabb(0.5, -0.5, 1.5, 2.5);
    check_manifold("same centre x", a, b, i2d_collide_aabbs(a, b), two(v2(1, 0), 1.5, v2(1.25, 0), v2(1.25, 2)));
    check_manifold("same centre x swapped", b, a, i2d_collide_aabbs(b, a), two(v2(1, 0), 1.5, v2(0.75, 0), v2(0.75, 2)));
    // Same, resolving along y: x depth 2.5 > y depth 1.5.
    i2d_aabb c = aabb(-0.5, 0.5, 2.5, 1.5);
    check_manifold("same centre y", a, c, i2d_collide_aabbs(a, c), two(v2(0, 1), 1.5, v2(0, 1.25), v2(2, 1.25)));
}

I2D_TEST(phys_collide_aabbs_apart) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    check_aabbs("aabbs apart +x", a, aabb(2.5, 0, 3, 1), none());
    check_aabbs("aabbs apart -y", a, aabb(0, -3, 1, -0.5), none());
    check_aabbs("aabbs apart diagonal", a, aabb(2.25, 2.25, 3, 3), none());
    // Overlapping in x but apart in y, and the reverse.
    check_aabbs("aabbs apart in y only", a, aabb(0.5, 2.5, 1.5, 3), none());
    check_aabbs("aabbs apart in x only", a, aabb(-3, 0.5, -0.5, 1.5), none());
}

I2D_TEST(phys_collide_aabbs_touching) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    // Sharing an edge segment: penetration 0, two points at the segment's ends.
    check_aabbs("aabbs touch right edge", a, aabb(2, 0.5, 4, 1.5), two(v2(1, 0), 0, v2(2, 0.5), v2(2, 1.5)));
    check_aabbs("aabbs touch top edge", a, aabb(0.5, 2, 1.5, 3), two(v2(0, 1), 0, v2(0.5, 2), v2(1.5, 2)));
    check_aabbs("aabbs touch bottom edge", a, aabb(-1, -1, 1, 0), two(v2(0, -1), 0, v2(0, 0), v2(1, 0)));
    // Sharing one corner: both overlaps are 0, so x (tie rule), and the contact segment
    // has zero length: one point, at the corner.
    check_aabbs("aabbs touch corner", a, aabb(2, 2, 3, 3), one(v2(1, 0), 0, v2(2, 2)));
    check_aabbs("aabbs touch corner 2", a, aabb(-1, 2, 0, 3), one(v2(-1, 0), 0, v2(0, 2)));
}

I2D_TEST(phys_collide_aabbs_containment) {
    // B inside A. Resolving is the shortest way out: along -x B must move 3 - 0 = 3 to
    // clear A's left face, along -y 5 - 0 = 5 (the other directions are longer, and the
    // centre difference (-3, -0.5) points the short way). So -x with penetration 3
    // (= the text's a_extent + b_extent - |dx| = 5 + 1 - 3), not B's width 2. Points on
    // B's y range [4, 5], at x midway between A's face 0 and B's face 3.
    i2d_aabb a = aabb(0, 0, 10, 10), b = aabb(1, 4, 3, 5);
    check_aabbs("b inside a", a, b, two(v2(-1, 0), 3, v2(1.5, 4), v2(1.5, 5)));
    // Near A's top: y wins (10 - 8 = 2 up, versus 10 - 4.5 = 5.5 to the right).
    i2d_aabb c = aabb(4.5, 8, 6.5, 9.5);
    check_aabbs("c inside a near top", a, c, two(v2(0, 1), 2, v2(4.5, 9), v2(6.5, 9)));
    // Touching A's right face from inside.
    i2d_aabb d = aabb(8, 4, 10, 6);
    check_aabbs("d inside a at right face", a, d, two(v2(1, 0), 2, v2(9, 4), v2(9, 6)));
}

// ---- AABB against circle ------------------------------------------------------------------

I2D_TEST(phys_collide_aabb_circle_faces) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    // Centre outside, beside a face: normal is the face normal, penetration r - d.
    check_aabb_circle("circle right", a, circle(2.5, 1, 1), v2(1, 0), 0.5, v2(2, 1), 1);
    check_aabb_circle("circle left", a, circle(-0.5, 1, 1), v2(-1, 0), 0.5, v2(0, 1), 1);
    check_aabb_circle("circle above", a, circle(1, 2.5, 1), v2(0, 1), 0.5, v2(1, 2), 1);
    check_aabb_circle("circle below", a, circle(1.5, -0.75, 1), v2(0, -1), 0.25, v2(1.5, 0), 1);
}

I2D_TEST(phys_collide_aabb_circle_corners) {
    // Corner regions: normal from the corner toward the centre, normalised (ERRATA: the
    // text used the unnormalised n - closest); penetration r - d. With the 3-4-5 offset
    // (1.5, 2), d = 2.5, r = 3: penetration 0.5, normal (+-0.6, +-0.8).
    i2d_aabb a = aabb(0, 0, 2, 2);
    check_aabb_circle("corner top right", a, circle(3.5, 4, 3), v2(0.6, 0.8), 0.5, v2(2, 2), 1);
    check_aabb_circle("corner top left", a, circle(-1.5, 4, 3), v2(-0.6, 0.8), 0.5, v2(0, 2), 1);
    check_aabb_circle("corner bottom left", a, circle(-1.5, -2, 3), v2(-0.6, -0.8), 0.5, v2(0, 0), 1);
    check_aabb_circle("corner bottom right", a, circle(3.5, -2, 3), v2(0.6, -0.8), 0.5, v2(2, 0), 1);
}

I2D_TEST(phys_collide_aabb_circle_apart) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    check_aabb_circle("apart right", a, circle(3.5, 1, 1), v2(0, 0), 0, v2(0, 0), 0);
    check_aabb_circle("apart below", a, circle(1, -1.25, 1), v2(0, 0), 0, v2(0, 0), 0);
    // Corner region, d = 2.5 > r = 2.4, although the circle's bounding box overlaps A.
    check_aabb_circle("apart corner", a, circle(3.5, 4, 2.4), v2(0, 0), 0, v2(0, 0), 0);
    check_aabb_circle("apart corner 2", a, circle(-1.5, -2, 2.4), v2(0, 0), 0, v2(0, 0), 0);
}

I2D_TEST(phys_collide_aabb_circle_touching) {
    i2d_aabb a = aabb(0, 0, 2, 2);
    check_aabb_circle("touch right face", a, circle(3, 1, 1), v2(1, 0), 0, v2(2, 1), 1);
    check_aabb_circle("touch bottom face", a, circle(0.5, -1, 1), v2(0, -1), 0, v2(0.5, 0), 1);
    check_aabb_circle("touch corner", a, circle(3.5, 4, 2.5), v2(0.6, 0.8), 0, v2(2, 2), 1);
    check_aabb_circle("touch corner 2", a, circle(-3, 6, 5), v2(-0.6, 0.8), 0, v2(0, 2), 1);
}

I2D_TEST(phys_collide_aabb_circle_center_inside) {
    // ERRATA: with the centre inside, the normal is the outward normal of the nearest
    // face and the penetration r + (distance of the centre to that face).
    // Box 4 x 2; the box point is the centre's projection onto that face.
    i2d_aabb a = aabb(0, 0, 4, 2);
    check_aabb_circle("inside near +x", a, circle(3.5, 1, 0.25), v2(1, 0), 0.75, v2(4, 1), 1);
    check_aabb_circle("inside near -x", a, circle(0.25, 1.25, 0.5), v2(-1, 0), 0.75, v2(0, 1.25), 1);
    check_aabb_circle("inside near +y", a, circle(2, 1.75, 0.5), v2(0, 1), 0.75, v2(2, 2), 1);
    check_aabb_circle("inside near -y", a, circle(1.5, 0.25, 0.5), v2(0, -1), 0.75, v2(1.5, 0), 1);
    // A big circle whose centre is inside a small box: it still leaves by the near face.
    check_aabb_circle("inside big circle", a, circle(3.75, 1, 5), v2(1, 0), 5.25, v2(4, 1), 1);
    // Centre exactly on a face (d = 0: the text's normalisation would divide by zero):
    // the outward normal of that face, penetration r.
    check_aabb_circle("centre on right face", a, circle(4, 1, 0.5), v2(1, 0), 0.5, v2(4, 1), 1);
    check_aabb_circle("centre on bottom face", a, circle(1, 0, 0.5), v2(0, -1), 0.5, v2(1, 0), 1);
}

I2D_TEST(phys_collide_aabb_circle_inside_ties) {
    // Equal distances to several faces go to the first of +x, -x, +y, -y.
    i2d_aabb sq = aabb(0, 0, 4, 4);
    check_aabb_circle("tie all four", sq, circle(2, 2, 1), v2(1, 0), 3, v2(4, 2), 1);
    check_aabb_circle("tie +x -y", sq, circle(3, 1, 0.5), v2(1, 0), 1.5, v2(4, 1), 1);
    check_aabb_circle("tie +x +y", sq, circle(3, 3, 0.5), v2(1, 0), 1.5, v2(4, 3), 1);
    check_aabb_circle("tie -x +y", sq, circle(1, 3, 0.5), v2(-1, 0), 1.5, v2(0, 3), 1);
    check_aabb_circle("tie -x -y", sq, circle(1, 1, 0.5), v2(-1, 0), 1.5, v2(0, 1), 1);
    i2d_aabb wide = aabb(0, 0, 4, 2);
    check_aabb_circle("tie +y -y", wide, circle(2, 1, 0.5), v2(0, 1), 1.5, v2(2, 2), 1);
    check_aabb_circle("tie -x +y -y", wide, circle(1, 1, 0.5), v2(-1, 0), 1.5, v2(0, 1), 1);
    // Centre on a corner: +x and +y faces both at distance 0: +x, penetration r.
    check_aabb_circle("centre on corner", wide, circle(4, 2, 0.5), v2(1, 0), 0.5, v2(4, 2), 1);
}

// ---- Invalid input ----------------------------------------------------------------------

I2D_TEST(phys_collide_invalid_input) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    i2d_circle c = circle(0, 0, 1);
    i2d_aabb b = aabb(0, 0, 1, 1);

    check_invalid("circle a centre NaN", i2d_collide_circles(i2d_circle{v2(nan, 0), 1}, c));
    check_invalid("circle b centre NaN", i2d_collide_circles(c, i2d_circle{v2(0, nan), 1}));
    check_invalid("circle radius NaN", i2d_collide_circles(c, i2d_circle{v2(0, 0), nan}));
    check_invalid("circle centre inf", i2d_collide_circles(i2d_circle{v2(inf, 0), 1}, c));
    check_invalid("circle radius inf", i2d_collide_circles(c, i2d_circle{v2(0, 0), inf}));
    check_invalid("circle radius negative", i2d_collide_circles(c, circle(0.5, 0, -1)));
    check_invalid("circle a radius negative", i2d_collide_circles(circle(0.5, 0, -1), c));

    check_invalid("aabb a min.x NaN", i2d_collide_aabbs(i2d_aabb{v2(nan, 0), v2(1, 1)}, b));
    check_invalid("aabb b max.y NaN", i2d_collide_aabbs(b, i2d_aabb{v2(0, 0), v2(1, nan)}));
    check_invalid("aabb inf", i2d_collide_aabbs(b, i2d_aabb{v2(-inf, 0), v2(1, 1)}));
    check_invalid("aabb a min.x > max.x", i2d_collide_aabbs(aabb(1, 0, 0, 1), b));
    check_invalid("aabb b min.y > max.y", i2d_collide_aabbs(b, aabb(0, 1, 1, 0)));

    check_invalid("aabb-circle box NaN", i2d_collide_aabb_circle(i2d_aabb{v2(0, nan), v2(1, 1)}, c));
    check_invalid("aabb-circle box min > max", i2d_collide_aabb_circle(aabb(0, 0, -1, 1), c));
    check_invalid("aabb-circle centre NaN", i2d_collide_aabb_circle(b, i2d_circle{v2(nan, 0), 1}));
    check_invalid("aabb-circle radius NaN", i2d_collide_aabb_circle(b, i2d_circle{v2(0, 0), nan}));
    check_invalid("aabb-circle radius negative", i2d_collide_aabb_circle(b, circle(0.5, 0.5, -0.25)));

    // The next valid call records success again (every call sets the last status).
    i2d_manifold m = i2d_collide_circles(c, circle(1, 0, 1));
    I2D_CHECK(m.point_count == 1);
    I2D_CHECK_STATUS(i2d_last_status(), I2D_OK);
}

// ---- Randomized properties against the double-precision reference -------------------------

I2D_TEST(phys_collide_random_circles) {
    random_pairs<i2d_circle, i2d_circle>("circles", 12345, random_circle, random_circle);
}

I2D_TEST(phys_collide_random_aabbs) {
    random_pairs<i2d_aabb, i2d_aabb>("aabbs", 67890, random_aabb, random_aabb);
}

I2D_TEST(phys_collide_random_aabb_circle) {
    random_pairs<i2d_aabb, i2d_circle>("aabb-circle", 24680, random_aabb, random_circle);
}
