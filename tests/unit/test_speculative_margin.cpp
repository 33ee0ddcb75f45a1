// SPDX-License-Identifier: MIT
// The speculative margin of the manifold functions: shapes of every pair of kinds at a
// known gap get points exactly when the margin covers the gap, with the true depth, the
// gap's axis as normal and points on the facing features; a larger margin only adds
// points that are farther than the default one (the normal, the reference face and every
// default point stay bit for bit), and the default argument is the old behaviour.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>

#include "brute_geometry.hpp"
#include "check.h"
#include "collision/manifold.hpp"
#include "world_fixture.hpp"

using namespace i2d;
using unit::box_geometry;
using unit::capsule_geometry;
using unit::circle_geometry;
using unit::segment_geometry;

namespace {

constexpr float gap = 0.3f;

// Each test kind is symmetric about its body's x axis and faces the other shape with a
// flat side (or a circle's pole) `reach` from its origin along +-y. Its facing feature
// spans `half_width` either side of the origin along x (0 for a circle's single point).
struct Kind {
    const char* name;
    Geometry geometry;
    float reach, half_width;
};

constexpr int32_t kind_count = 5;

Kind test_kind(int32_t i) {
    switch (i) {
        case 0: return {"circle", circle_geometry({0.0f, 0.0f}, 0.5f), 0.5f, 0.0f};
        case 1: return {"capsule", capsule_geometry({-0.6f, 0.0f}, {0.6f, 0.0f}, 0.25f), 0.25f, 0.6f};
        case 2: return {"segment", segment_geometry({-0.8f, 0.0f}, {0.8f, 0.0f}), 0.0f, 0.8f};
        case 3: return {"box", box_geometry(0.5f, 0.4f), 0.4f, 0.5f};
        default: return {"rounded box", box_geometry(0.4f, 0.3f, 0.1f), 0.4f, 0.4f};
    }
}

// A above the frame's origin, B `gap` beyond it along the frame's +y (or -y when `below`),
// shifted by `shift` across so that the facing features overlap over an unequal stretch.
struct Placement {
    Transform xa, xb;
    Vec2 axis, across;  // unit, world
};

Placement place(const Kind& a, const Kind& b, Rot frame, bool below, float shift) {
    const Vec2 origin{0.7f, -1.3f};
    const float side = below ? -1.0f : 1.0f;
    Placement p;
    p.axis = rotate(frame, Vec2{0.0f, side});
    p.across = rotate(frame, Vec2{1.0f, 0.0f});
    p.xa = Transform{origin, frame};
    p.xb = Transform{origin + rotate(frame, Vec2{shift, side * (a.reach + gap + b.reach)}), frame};
    return p;
}

bool both_segments(const Kind& a, const Kind& b) {
    return a.geometry.type == ShapeType::segment && b.geometry.type == ShapeType::segment;
}

// Checks one manifold of the placed pair at margin 0.5: points at -gap, the normal along
// the axis, each point midway across the gap and on both facing features, and two points
// at the ends of the features' common stretch when that stretch has a length.
void check_speculative_points(const Manifold& m, const Kind& a, const Kind& b, const Placement& p, float shift) {
    const float lo = std::fmax(-a.half_width, shift - b.half_width);
    const float hi = std::fmin(a.half_width, shift + b.half_width);
    const int32_t expected = hi > lo ? 2 : 1;
    I2D_CHECK(m.point_count == expected);
    if (m.point_count != expected) {
        std::fprintf(stderr, "  %s-%s: %d points, expected %d\n", a.name, b.name, int(m.point_count), int(expected));
        return;
    }
    I2D_CHECK_NEAR(m.normal.x, p.axis.x, 1e-5);
    I2D_CHECK_NEAR(m.normal.y, p.axis.y, 1e-5);
    float seen_lo = 1e30f, seen_hi = -1e30f;
    for (int32_t i = 0; i < m.point_count; ++i) {
        const ManifoldPoint& mp = m.points[i];
        I2D_CHECK_NEAR(mp.penetration, -gap, 1e-5);
        const Vec2 d = mp.point - p.xa.p;
        I2D_CHECK_NEAR(dot(d, p.axis), a.reach + 0.5f * gap, 1e-5);
        seen_lo = std::fmin(seen_lo, dot(d, p.across));
        seen_hi = std::fmax(seen_hi, dot(d, p.across));
    }
    I2D_CHECK_NEAR(seen_lo, lo, 1e-5);
    I2D_CHECK_NEAR(seen_hi, hi, 1e-5);
}

bool same_point(const ManifoldPoint& x, const ManifoldPoint& y) {
    return std::memcmp(&x, &y, sizeof(ManifoldPoint)) == 0;
}

bool has_point(const Manifold& m, const ManifoldPoint& x) {
    for (int32_t i = 0; i < m.point_count; ++i) {
        if (same_point(m.points[i], x)) {
            return true;
        }
    }
    return false;
}

}  // namespace

// Every ordered pair of kinds (so both argument orders of each primary pair go through
// the table), B above and below A, in the world frame and in a turned one.
I2D_TEST(unit_speculative_margin_every_pair_at_gap) {
    const Rot frames[2] = {Rot{}, make_rot(0.7f)};
    int32_t checked = 0;
    for (int32_t ia = 0; ia < kind_count; ++ia) {
        for (int32_t ib = 0; ib < kind_count; ++ib) {
            const Kind a = test_kind(ia), b = test_kind(ib);
            // Two circles must stay centre over centre for the normal to be the axis.
            const float shift = ia == 0 && ib == 0 ? 0.0f : 0.1f;
            for (const Rot& frame : frames) {
                for (const bool below : {false, true}) {
                    const Placement p = place(a, b, frame, below, shift);
                    const Geometry& ga = a.geometry;
                    const Geometry& gb = b.geometry;
                    I2D_CHECK(collide_shapes(ga, p.xa, gb, p.xb).point_count == 0);
                    I2D_CHECK(collide_shapes(ga, p.xa, gb, p.xb, 0.25f).point_count == 0);
                    const Manifold m = collide_shapes(ga, p.xa, gb, p.xb, 0.5f);
                    const Manifold r = collide_shapes(gb, p.xb, ga, p.xa, 0.5f);
                    if (both_segments(a, b)) {
                        I2D_CHECK(m.point_count == 0 && r.point_count == 0);
                        continue;
                    }
                    check_speculative_points(m, a, b, p, shift);
                    // The reversed call mirrors it: seen from B, A lies along -axis, -shift across.
                    const Placement q{p.xb, p.xa, -p.axis, p.across};
                    check_speculative_points(r, b, a, q, -shift);
                    ++checked;
                }
            }
        }
    }
    I2D_CHECK(checked == (kind_count * kind_count - 1) * 4);
}

// The margin is reached exactly at the gap: just above it gives points, just below none.
I2D_TEST(unit_speculative_margin_edge_is_the_gap) {
    for (int32_t ia = 0; ia < kind_count; ++ia) {
        for (int32_t ib = 0; ib < kind_count; ++ib) {
            const Kind a = test_kind(ia), b = test_kind(ib);
            if (both_segments(a, b)) {
                continue;
            }
            const Placement p = place(a, b, make_rot(-0.4f), false, 0.0f);
            I2D_CHECK(collide_shapes(a.geometry, p.xa, b.geometry, p.xb, gap + 1e-3f).point_count >= 1);
            I2D_CHECK(collide_shapes(a.geometry, p.xa, b.geometry, p.xb, gap - 1e-3f).point_count == 0);
        }
    }
}

// Corners and end caps at the gap, where the closest features are two vertices (or a
// vertex and a circle) and the normal runs between them, not along a face normal: the
// polygon clipper's vertex-vertex contact, the polygon-circle vertex region and capsule
// ends. B's closest core point sits on the ray from A's along n, beyond both surfaces.
I2D_TEST(unit_speculative_margin_corners_at_gap) {
    struct Case {
        Geometry a;
        Vec2 core_a;  // A's closest core point, A's frame
        float radius_a;
        Geometry b;
        Vec2 core_b;  // B's, B's frame
        float radius_b;
    };
    const Geometry box = box_geometry(0.5f, 0.4f), rounded = box_geometry(0.4f, 0.3f, 0.1f);
    const Geometry capsule = capsule_geometry({-0.6f, 0.0f}, {0.6f, 0.0f}, 0.25f);
    const Geometry segment = segment_geometry({-0.8f, 0.0f}, {0.8f, 0.0f});
    const Geometry circle = circle_geometry({0.0f, 0.0f}, 0.5f);
    const Vec2 box_corner{0.5f, 0.4f}, box_low{-0.5f, -0.4f};
    const Case cases[] = {
        {box, box_corner, 0.0f, box, box_low, 0.0f},
        {rounded, {0.4f, 0.3f}, 0.1f, box, box_low, 0.0f},
        {box, box_corner, 0.0f, circle, {}, 0.5f},
        {circle, {}, 0.5f, box, box_low, 0.0f},
        {capsule, {0.6f, 0.0f}, 0.25f, capsule, {-0.6f, 0.0f}, 0.25f},
        {capsule, {0.6f, 0.0f}, 0.25f, box, box_low, 0.0f},
        {capsule, {0.6f, 0.0f}, 0.25f, circle, {}, 0.5f},
        {segment, {0.8f, 0.0f}, 0.0f, circle, {}, 0.5f},
        {segment, {0.8f, 0.0f}, 0.0f, box, box_low, 0.0f},
        {rounded, {0.4f, 0.3f}, 0.1f, capsule, {-0.6f, 0.0f}, 0.25f},
        {box, box_corner, 0.0f, segment, {-0.8f, 0.0f}, 0.0f},
    };
    const Vec2 n{0.6f, 0.8f};
    for (const Rot& frame : {Rot{}, make_rot(0.7f)}) {
        for (const Case& c : cases) {
            const Vec2 origin{-0.4f, 2.1f};
            const Transform xa{origin, frame};
            const Vec2 offset = c.core_a + (c.radius_a + gap + c.radius_b) * n - c.core_b;
            const Transform xb{origin + rotate(frame, offset), frame};
            I2D_CHECK(collide_shapes(c.a, xa, c.b, xb).point_count == 0);
            I2D_CHECK(collide_shapes(c.a, xa, c.b, xb, 0.25f).point_count == 0);
            I2D_CHECK(collide_shapes(c.b, xb, c.a, xa, 0.25f).point_count == 0);
            const Manifold m = collide_shapes(c.a, xa, c.b, xb, 0.5f);
            const Manifold r = collide_shapes(c.b, xb, c.a, xa, 0.5f);
            I2D_REQUIRE(m.point_count == 1 && r.point_count == 1);
            const Vec2 normal = rotate(frame, n);
            const Vec2 mid = origin + rotate(frame, c.core_a + (c.radius_a + 0.5f * gap) * n);
            I2D_CHECK_NEAR(m.normal.x, normal.x, 1e-5);
            I2D_CHECK_NEAR(m.normal.y, normal.y, 1e-5);
            I2D_CHECK_NEAR(m.points[0].penetration, -gap, 1e-5);
            I2D_CHECK_NEAR(m.points[0].point.x, mid.x, 1e-5);
            I2D_CHECK_NEAR(m.points[0].point.y, mid.y, 1e-5);
            I2D_CHECK_NEAR(r.normal.x, -normal.x, 1e-5);
            I2D_CHECK_NEAR(r.normal.y, -normal.y, 1e-5);
            I2D_CHECK_NEAR(r.points[0].penetration, -gap, 1e-5);
        }
    }
}

// The case the margin exists for: a ball at 30 m/s moves 0.5 m in a 60 Hz step, so a
// one-collide-per-step solver asks for a margin of that size and must see the thin wall
// 0.45 m away; here through the typed functions, which the table tests above go through.
I2D_TEST(unit_speculative_margin_fast_ball_sees_thin_wall) {
    const Segment wall{{0.0f, -2.0f}, {0.0f, 2.0f}};
    const Circle ball{{0.0f, 0.0f}, 0.1f};
    const Transform xball{{-0.55f, 0.3f}, Rot{}};
    const float margin = 30.0f / 60.0f;
    I2D_CHECK(collide_segment_circle(wall, Transform{}, ball, xball).point_count == 0);
    const Manifold m = collide_segment_circle(wall, Transform{}, ball, xball, margin);
    I2D_REQUIRE(m.point_count == 1);
    I2D_CHECK_NEAR(m.normal.x, -1.0, 1e-6);
    I2D_CHECK_NEAR(m.points[0].penetration, -0.45, 1e-5);
    I2D_CHECK_NEAR(m.points[0].point.x, -0.225, 1e-5);
    I2D_CHECK_NEAR(m.points[0].point.y, 0.3, 1e-5);
    // A thin box wall and a box bullet: two points across the bullet's face.
    const Polygon plate = make_box(0.01f, 2.0f), bullet = make_box(0.1f, 0.1f);
    const Transform xbullet{{0.56f, 0.3f}, Rot{}};
    I2D_CHECK(collide_polygons(plate, Transform{}, bullet, xbullet).point_count == 0);
    const Manifold q = collide_polygons(plate, Transform{}, bullet, xbullet, margin);
    I2D_REQUIRE(q.point_count == 2);
    I2D_CHECK_NEAR(q.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(q.points[0].penetration, -0.45, 1e-5);
    I2D_CHECK_NEAR(q.points[1].penetration, -0.45, 1e-5);
}

// A box tilted on one corner into the ground: the default margin keeps only the corner,
// a larger one also keeps the far end of the incident edge, at its true height and midway
// to the ground. This is why a larger margin may change a touching manifold: it adds
// points, and never moves or drops the ones the default margin reports.
I2D_TEST(unit_speculative_margin_tilted_box_far_corner) {
    const Geometry ground = box_geometry(5.0f, 0.5f);
    const Geometry box = box_geometry(0.5f, 0.5f);
    const Transform xg{{0.0f, -0.5f}, Rot{}};
    const Rot tilt = make_rot(0.3f);
    // Lowest corner (-0.5, -0.5) turned by 0.3 rad, put 1 cm into the ground.
    const Vec2 low = rotate(tilt, Vec2{-0.5f, -0.5f});
    const Vec2 high = rotate(tilt, Vec2{0.5f, -0.5f});
    const Transform xb{Vec2{0.2f, -0.01f} - low, tilt};
    const Manifold near = collide_shapes(ground, xg, box, xb);
    const Manifold both = collide_shapes(ground, xg, box, xb, 1.0f);
    I2D_REQUIRE(near.point_count == 1);
    I2D_REQUIRE(both.point_count == 2);
    I2D_CHECK_NEAR(near.points[0].penetration, 0.01, 1e-5);
    I2D_CHECK(near.normal == both.normal);
    I2D_CHECK(has_point(both, near.points[0]));
    const ManifoldPoint& far = same_point(both.points[0], near.points[0]) ? both.points[1] : both.points[0];
    const float height = high.y - low.y - 0.01f;  // of the far corner above the ground
    I2D_CHECK_NEAR(far.penetration, -height, 1e-5);
    I2D_CHECK_NEAR(far.point.x, 0.2f + high.x - low.x, 1e-5);
    I2D_CHECK_NEAR(far.point.y, 0.5f * height, 1e-5);
    // With a margin just short of the far corner's height it is dropped again.
    const Manifold short_of = collide_shapes(ground, xg, box, xb, height - 1e-3f);
    I2D_CHECK(std::memcmp(&near, &short_of, sizeof(Manifold)) == 0);
}

// Touching and overlapping shapes of every pair of kinds, at random poses: the default
// argument is speculative_distance, and margin 1 gives the same normal and the same points
// bit for bit, plus only points farther than the default margin (the far ends of tilted
// incident edges), between the surfaces. Without such extra points the manifolds are
// identical byte for byte.
I2D_TEST(unit_speculative_margin_keeps_overlapping_manifolds) {
    TestRng rng(515);
    int32_t compared = 0, identical = 0, extra = 0;
    double worst_off_midline = 0.0;
    for (int32_t ka = 0; ka < brute::random_kind_count; ++ka) {
        for (int32_t kb = 0; kb < brute::random_kind_count; ++kb) {
            for (int32_t trial = 0; trial < 3000; ++trial) {
                const Geometry a = brute::random_geometry(rng, static_cast<ShapeType>(ka));
                const Geometry b = brute::random_geometry(rng, static_cast<ShapeType>(kb));
                const Transform xa = brute::random_transform(rng, 1.2f), xb = brute::random_transform(rng, 1.2f);
                const brute::Core ca = brute::core_of(a, xa), cb = brute::core_of(b, xb);
                if (brute::core_gap(ca.pts, cb.pts) - ca.radius - cb.radius > 0.0) {
                    continue;
                }
                const Manifold d = collide_shapes(a, xa, b, xb);
                const Manifold s = collide_shapes(a, xa, b, xb, speculative_distance);
                const Manifold l = collide_shapes(a, xa, b, xb, 1.0f);
                I2D_CHECK(std::memcmp(&d, &s, sizeof(Manifold)) == 0);
                if (d.point_count == 0) {
                    I2D_CHECK(l.point_count == 0);  // two segments
                    continue;
                }
                ++compared;
                I2D_REQUIRE(l.point_count >= d.point_count);
                I2D_CHECK(l.normal == d.normal);
                for (int32_t i = 0; i < d.point_count; ++i) {
                    I2D_CHECK(has_point(l, d.points[i]));
                }
                if (l.point_count == d.point_count) {
                    identical += std::memcmp(&d, &l, sizeof(Manifold)) == 0 ? 1 : 0;
                    I2D_CHECK(std::memcmp(&d, &l, sizeof(Manifold)) == 0);
                    continue;
                }
                for (int32_t i = 0; i < l.point_count; ++i) {
                    const ManifoldPoint& mp = l.points[i];
                    if (has_point(d, mp)) {
                        continue;
                    }
                    ++extra;
                    I2D_CHECK(mp.penetration < -speculative_distance && mp.penetration >= -1.0f);
                    const double half = 0.5 * std::fabs(mp.penetration);
                    const double da = brute::signed_distance(ca, brute::p(mp.point));
                    const double db = brute::signed_distance(cb, brute::p(mp.point));
                    worst_off_midline = std::fmax(worst_off_midline, std::fmax(da, db) - half);
                    I2D_CHECK(da <= half + 1e-4 && db <= half + 1e-4);
                }
            }
        }
    }
    std::printf("speculative margin 1 on touching shapes: %d of %d manifolds identical, %d extra points, "
                "worst off the midline %.3g\n",
                int(identical), int(compared), int(extra), worst_off_midline);
    I2D_CHECK(compared > 10000);
    I2D_CHECK(identical > 0 && extra > 0);
}
