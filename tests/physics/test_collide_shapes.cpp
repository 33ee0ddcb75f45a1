// SPDX-License-Identifier: MIT
// The public pure functions for rotated shapes: polygons from points, boxes, manifolds of
// every pair of kinds, mass and ray casts, with hand-worked values, and their refusals.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "check.h"
#include "physics_fixture.hpp"

using phys::deepest_penetration;
using phys::pi;

namespace {

const i2d_transform identity = {{0.0f, 0.0f}, {1.0f, 0.0f}};

i2d_transform at(float x, float y, double angle = 0.0) { return {{x, y}, phys::rot(angle)}; }

bool message_has(const char* text) { return std::strstr(i2d_last_error_message(), text) != nullptr; }

}  // namespace

I2D_TEST(physics_collide_make_polygon_and_boxes) {
    const i2d_vec2 pts[5] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0.5f}};  // an inner point
    i2d_polygon p;
    I2D_CHECK_STATUS(i2d_make_polygon(pts, 5, 0.0f, &p), I2D_OK);
    I2D_CHECK(p.count == 4);
    I2D_CHECK_NEAR(p.centroid.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(p.centroid.y, 0.5, 1e-6);

    const i2d_polygon box = i2d_make_box(1.0f, 0.5f);
    I2D_CHECK(i2d_last_status() == I2D_OK && box.count == 4);
    I2D_CHECK(box.vertices[2].x == 1.0f && box.vertices[2].y == 0.5f);
    const i2d_polygon turned = i2d_make_offset_box(1.0f, 0.5f, {2.0f, 0.0f}, {0.0f, 1.0f});
    I2D_CHECK(i2d_last_status() == I2D_OK && turned.count == 4);
    I2D_CHECK_NEAR(turned.vertices[2].x, 1.5, 1e-6);  // (1, 0.5) turned 90 degrees, moved by 2
    I2D_CHECK_NEAR(turned.vertices[2].y, 1.0, 1e-6);

    const i2d_mass_data md = i2d_compute_polygon_mass(&box, 2.0f);
    I2D_CHECK_NEAR(md.mass, 4.0, 1e-5);
    I2D_CHECK_NEAR(md.rotational_inertia, 4.0 * (4.0 + 1.0) / 12.0, 1e-5);
    const i2d_circle disc = {{1.0f, 1.0f}, 0.5f};
    I2D_CHECK_NEAR(i2d_compute_circle_mass(&disc, 1.0f).rotational_inertia, 0.5 * pi * 0.25 * 0.25, 1e-6);
    const i2d_capsule cap = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    I2D_CHECK_NEAR(i2d_compute_capsule_mass(&cap, 1.0f).mass, 2.0 + pi * 0.25, 1e-5);
}

I2D_TEST(physics_collide_make_polygon_refusals) {
    i2d_polygon p;
    std::memset(&p, 0x5a, sizeof p);
    const i2d_polygon before = p;
    const i2d_vec2 line[3] = {{0, 0}, {1, 1}, {2, 2}};
    I2D_CHECK_STATUS(i2d_make_polygon(line, 3, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("collinear"));
    const i2d_vec2 dup[3] = {{0, 0}, {0, 0}, {1, 0}};
    I2D_CHECK_STATUS(i2d_make_polygon(dup, 3, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("duplicate"));
    const i2d_vec2 tiny[3] = {{0.0f, 0.0f}, {0.006f, 0.0f}, {0.003f, 0.0051962f}};
    I2D_CHECK_STATUS(i2d_make_polygon(tiny, 3, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("area"));
    const i2d_vec2 ok[3] = {{0, 0}, {1, 0}, {0, 1}};
    I2D_CHECK_STATUS(i2d_make_polygon(ok, 2, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_make_polygon(ok, 9, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_make_polygon(nullptr, 3, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_make_polygon(ok, 3, 0.0f, nullptr), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_make_polygon(ok, 3, -0.1f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_make_polygon(ok, 3, std::nanf(""), &p), I2D_ERR_INVALID_ARGUMENT);
    const i2d_vec2 nan_pt[3] = {{0, 0}, {std::numeric_limits<float>::infinity(), 0}, {0, 1}};
    I2D_CHECK_STATUS(i2d_make_polygon(nan_pt, 3, 0.0f, &p), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(std::memcmp(&p, &before, sizeof p) == 0);  // refused calls leave out alone

    i2d_polygon bad = i2d_make_box(-1.0f, 1.0f);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && bad.count == 0);
    bad = i2d_make_box(1.0f, std::nanf(""));
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && bad.count == 0);
    bad = i2d_make_offset_box(1.0f, 1.0f, {0.0f, 0.0f}, {2.0f, 0.0f});
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && bad.count == 0);
}

I2D_TEST(physics_collide_every_pair_hand_worked) {
    const i2d_polygon box = i2d_make_box(1.0f, 1.0f);
    const i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    const i2d_capsule cap = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    const i2d_segment seg = {{-2.0f, 0.0f}, {2.0f, 0.0f}};

    // Boxes: B turned 90 degrees (still a unit box) resting 0.1 deep on A's top face.
    i2d_manifold m = i2d_collide_polygons(&box, identity, &box, at(0.5f, 1.9f, pi / 2));
    I2D_REQUIRE(m.point_count == 2);
    I2D_CHECK_NEAR(m.normal.y, 1.0, 1e-5);
    I2D_CHECK_NEAR(m.points[0].penetration, 0.1, 1e-5);
    I2D_CHECK_NEAR(m.points[1].penetration, 0.1, 1e-5);
    I2D_CHECK_NEAR(m.points[0].point.y, 0.95, 1e-5);
    // Within the speculative distance: points with negative penetration.
    m = i2d_collide_polygons(&box, identity, &box, at(0.0f, 2.01f));
    I2D_REQUIRE(m.point_count == 2);
    I2D_CHECK_NEAR(m.points[0].penetration, -0.01, 1e-5);
    I2D_CHECK(i2d_collide_polygons(&box, identity, &box, at(0.0f, 2.05f)).point_count == 0);

    m = i2d_collide_polygon_circle(&box, at(0.0f, 0.0f, 0.3f), &circle, at(0.0f, 0.0f));
    I2D_CHECK(m.point_count == 1);
    m = i2d_collide_polygon_circle(&box, identity, &circle, at(1.4f, 0.0f));
    I2D_REQUIRE(m.point_count == 1);
    I2D_CHECK_NEAR(m.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(m.points[0].penetration, 0.1, 1e-5);

    // Capsule lying on the box top, 0.05 deep: two points.
    m = i2d_collide_polygon_capsule(&box, identity, &cap, at(0.0f, 1.2f));
    I2D_REQUIRE(m.point_count == 2);
    I2D_CHECK_NEAR(deepest_penetration(m), 0.05, 1e-5);
    m = i2d_collide_capsule_circle(&cap, identity, &circle, at(0.0f, 0.7f));
    I2D_REQUIRE(m.point_count == 1);
    I2D_CHECK_NEAR(m.points[0].penetration, 0.05, 1e-5);
    I2D_CHECK_NEAR(m.points[0].point.y, 0.225, 1e-5);
    m = i2d_collide_capsules(&cap, identity, &cap, at(0.5f, 0.45f));
    I2D_REQUIRE(m.point_count == 2);
    I2D_CHECK_NEAR(deepest_penetration(m), 0.05, 1e-5);
    m = i2d_collide_segment_circle(&seg, identity, &circle, at(1.0f, -0.4f));
    I2D_REQUIRE(m.point_count == 1);
    I2D_CHECK_NEAR(m.normal.y, -1.0, 1e-6);
    I2D_CHECK_NEAR(m.points[0].penetration, 0.1, 1e-5);
    m = i2d_collide_segment_capsule(&seg, identity, &cap, at(0.0f, 0.2f, pi));
    I2D_REQUIRE(m.point_count == 2);
    I2D_CHECK_NEAR(deepest_penetration(m), 0.05, 1e-5);
    // A box dropped on a segment ground, turned 45 degrees: one corner 0.1 deep.
    m = i2d_collide_segment_polygon(&seg, identity, &box, at(0.0f, float(std::sqrt(2.0) - 0.1), pi / 4));
    I2D_REQUIRE(m.point_count >= 1);
    I2D_CHECK_NEAR(m.normal.y, 1.0, 1e-5);
    I2D_CHECK_NEAR(deepest_penetration(m), 0.1, 1e-4);
}

I2D_TEST(physics_collide_refusals) {
    const i2d_polygon box = i2d_make_box(1.0f, 1.0f);
    const i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    const i2d_capsule cap = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
    const i2d_segment seg = {{-2.0f, 0.0f}, {2.0f, 0.0f}};
    const i2d_transform not_unit = {{0.0f, 0.0f}, {1.0f, 0.1f}};
    const i2d_transform nan_xf = {{std::nanf(""), 0.0f}, {1.0f, 0.0f}};

    i2d_manifold m = i2d_collide_polygons(nullptr, identity, &box, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    m = i2d_collide_polygons(&box, not_unit, &box, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    I2D_CHECK(message_has("normalised"));
    m = i2d_collide_polygons(&box, identity, &box, nan_xf);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    i2d_polygon bad = box;
    bad.count = 9;
    m = i2d_collide_polygon_circle(&bad, identity, &circle, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    bad = box;
    bad.radius = -1.0f;
    m = i2d_collide_polygon_capsule(&bad, identity, &cap, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    bad = box;
    bad.vertices[1].x = std::nanf("");
    m = i2d_collide_segment_polygon(&seg, identity, &bad, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    const i2d_circle neg = {{0.0f, 0.0f}, -0.5f};
    m = i2d_collide_capsule_circle(&cap, identity, &neg, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    const i2d_capsule short_cap = {{0.0f, 0.0f}, {0.001f, 0.0f}, 0.25f};
    m = i2d_collide_capsules(&cap, identity, &short_cap, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    const i2d_segment point_seg = {{1.0f, 1.0f}, {1.0f, 1.0f}};
    m = i2d_collide_segment_circle(&point_seg, identity, &circle, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    m = i2d_collide_segment_capsule(&seg, identity, nullptr, identity);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && m.point_count == 0);
    // A good call after the refusals resets the status.
    m = i2d_collide_capsules(&cap, identity, &cap, at(0.0f, 0.4f));
    I2D_CHECK(i2d_last_status() == I2D_OK && m.point_count == 2);
}

I2D_TEST(physics_collide_ray_casts) {
    const i2d_polygon box = i2d_make_box(1.0f, 1.0f);
    i2d_cast_output r = i2d_ray_cast_polygon(&box, at(0.0f, 0.0f, pi / 4), {-3.0f, 0.0f}, {6.0f, 0.0f});
    I2D_REQUIRE(r.hit);
    I2D_CHECK_NEAR(r.fraction, (3.0 - std::sqrt(2.0)) / 6.0, 1e-6);
    I2D_CHECK_NEAR(r.point.x, -std::sqrt(2.0), 1e-5);
    const i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    r = i2d_ray_cast_circle(&circle, at(2.0f, 0.0f), {0.0f, 0.0f}, {4.0f, 0.0f});
    I2D_REQUIRE(r.hit);
    I2D_CHECK_NEAR(r.fraction, 1.5 / 4.0, 1e-6);
    const i2d_capsule cap = {{0.0f, -1.0f}, {0.0f, 1.0f}, 0.5f};
    r = i2d_ray_cast_capsule(&cap, identity, {3.0f, 0.5f}, {-3.0f, 0.0f});
    I2D_REQUIRE(r.hit);
    I2D_CHECK_NEAR(r.fraction, 2.5 / 3.0, 1e-6);
    I2D_CHECK_NEAR(r.normal.x, 1.0, 1e-6);
    const i2d_segment seg = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
    r = i2d_ray_cast_segment(&seg, at(0.0f, 1.0f), {0.5f, 3.0f}, {0.0f, -4.0f});
    I2D_REQUIRE(r.hit);
    I2D_CHECK_NEAR(r.fraction, 0.5, 1e-6);
    r = i2d_ray_cast_polygon(&box, identity, {std::nanf(""), 0.0f}, {1.0f, 0.0f});
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && !r.hit);
}
