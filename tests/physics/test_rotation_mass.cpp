// SPDX-License-Identifier: MIT
// Mass, centre of mass and rotational inertia of rotating bodies against closed form:
// box, disc, capsule, offset box, triangle, rounded box, a body with two shapes, and the
// bodies that report no inertia. Then the shape creation refusals, which must leave the
// body's mass exactly as it was.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <limits>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// Relative tolerance for float mass properties computed by the engine.
constexpr double rel = 2e-5;

double rel_tol(double expected) { return rel * std::fabs(expected) + 1e-7; }

i2d_body_id make_body(Scene& scene, i2d_body_type type, i2d_vec2 position, float angle = 0.0f,
                      bool fixed_rotation = false) {
    i2d_body_def def = turned_body_def(type, position, angle);
    def.fixed_rotation = fixed_rotation;
    return i2d_body_create(scene.world, &def);
}

// Mass, inertia and local centre of mass, checked against closed-form values.
void check_mass(i2d_body_id body, double m, double inertia, double cx, double cy) {
    I2D_CHECK_NEAR(i2d_body_get_mass(body), m, rel_tol(m));
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(body), inertia, rel_tol(inertia));
    const i2d_vec2 c = i2d_body_get_local_center_of_mass(body);
    I2D_CHECK_NEAR(c.x, cx, 1e-5 * (1 + std::fabs(cx)));
    I2D_CHECK_NEAR(c.y, cy, 1e-5 * (1 + std::fabs(cy)));
}

// The closed form of the world centre of mass: position + R(angle) local.
void check_world_center(i2d_body_id body, double px, double py, double angle, double cx, double cy) {
    const Point expected = transform_point(px, py, angle, cx, cy);
    const i2d_vec2 w = i2d_body_get_world_center_of_mass(body);
    I2D_CHECK_NEAR(w.x, expected.x, 2e-5 * (1 + std::fabs(expected.x)));
    I2D_CHECK_NEAR(w.y, expected.y, 2e-5 * (1 + std::fabs(expected.y)));
}

// Everything a refused shape creation must leave untouched, bit for bit.
struct MassSnapshot {
    float mass, inertia;
    i2d_vec2 local_center, world_center;
    int32_t shape_count;

    static MassSnapshot of(i2d_body_id body) {
        return MassSnapshot{i2d_body_get_mass(body), i2d_body_get_rotational_inertia(body),
                            i2d_body_get_local_center_of_mass(body), i2d_body_get_world_center_of_mass(body),
                            i2d_body_get_shape_count(body)};
    }
    bool operator==(const MassSnapshot& o) const {
        return std::memcmp(&mass, &o.mass, sizeof mass) == 0 && std::memcmp(&inertia, &o.inertia, sizeof inertia) == 0 &&
               std::memcmp(&local_center, &o.local_center, sizeof local_center) == 0 &&
               std::memcmp(&world_center, &o.world_center, sizeof world_center) == 0 && shape_count == o.shape_count;
    }
};

// A refused creation: null id, I2D_ERR_INVALID_ARGUMENT, a message, the body unchanged.
void check_refused(i2d_shape_id shape, i2d_body_id body, const MassSnapshot& before, const char* what) {
    const int failures = i2d_check_failures;
    const i2d_status status = i2d_last_status();
    const char* message = i2d_last_error_message();
    const bool has_message = message != nullptr && message[0] != '\0';
    printf("    refused %-34s -> %s \"%s\"\n", what, i2d_status_string(status), has_message ? message : "");
    I2D_CHECK(I2D_IS_NULL(shape));
    I2D_CHECK(status == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(has_message);
    I2D_CHECK(MassSnapshot::of(body) == before);
    report_case(failures, what);
    if (!I2D_IS_NULL(shape)) {
        i2d_shape_destroy(shape);  // wrongly accepted: take it off so later cases start clean
    }
}

}  // namespace

I2D_TEST(phys_rotmass_box) {
    // A w x h box of mass m: I = m (w^2 + h^2) / 12 about its centre. Full sizes 3 x 0.5
    // at density 2: m = 3 kg, I = 3 (9 + 0.25) / 12 = 2.3125 kg m^2. The body's rotation
    // does not change the inertia; the centre of mass is the body origin.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{2, -1}, 0.7f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(2.0f));
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(body, &sd, 1.5f, 0.25f)));
    const double m = 2.0 * 3.0 * 0.5, inertia = m * (3.0 * 3.0 + 0.5 * 0.5) / 12.0;
    printf("    box 3 x 0.5, density 2: m %.6f (expected %.6f), I %.6f (expected %.6f)\n", i2d_body_get_mass(body), m,
           i2d_body_get_rotational_inertia(body), inertia);
    check_mass(body, m, inertia, 0, 0);
    check_world_center(body, 2, -1, 0.7, 0, 0);
}

I2D_TEST(phys_rotmass_disc) {
    // A disc: I = m r^2 / 2 about its centre, which is the centre of mass even when the
    // circle sits off the body origin. r = 0.75, density 2: m = 1.125 pi.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{-3, 4}, -0.4f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(2.0f));
    const i2d_circle circle{i2d_vec2{0.5f, -0.25f}, 0.75f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(body, &sd, &circle)));
    const double r = 0.75, m = 2.0 * pi * r * r, inertia = m * r * r / 2;
    printf("    disc r 0.75 at (0.5, -0.25), density 2: m %.6f (expected %.6f), I %.6f (expected %.6f)\n",
           i2d_body_get_mass(body), m, i2d_body_get_rotational_inertia(body), inertia);
    check_mass(body, m, inertia, 0.5, -0.25);
    check_world_center(body, -3, 4, -0.4, 0.5, -0.25);
}

I2D_TEST(phys_rotmass_capsule) {
    // A capsule of radius r whose centres are L apart is a 2r x L rectangle plus two half
    // discs. Rectangle: m_r = rho 2 r L, I_r = m_r (L^2 + 4 r^2) / 12. Each half disc: mass
    // m_h = rho pi r^2 / 2, inertia m_h r^2 / 2 about its flat side's centre; its centroid
    // lies d = 4 r / (3 pi) from the flat side, so about its centroid m_h (r^2/2 - d^2),
    // and the centroid is L/2 + d from the capsule centre (parallel axis theorem twice):
    // I = I_r + 2 m_h (r^2/2 - d^2 + (L/2 + d)^2). A slanted capsule, L = 1.5, r = 0.25.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{1, 1}, 1.1f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(3.0f));
    const i2d_vec2 c1{-0.3f, -0.4f}, c2{0.6f, 0.8f};
    const float radius = 0.25f;
    i2d_shape_id shape = i2d_shape_create_capsule(body, &sd, c1, c2, radius);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    const double rho = 3.0, r = radius;
    const double L = std::hypot(double(c2.x) - c1.x, double(c2.y) - c1.y);  // 1.5
    const double m_r = rho * 2 * r * L, m_h = rho * pi * r * r / 2;
    const double d = 4 * r / (3 * pi);
    const double inertia = m_r * (L * L + 4 * r * r) / 12 + 2 * m_h * (r * r / 2 - d * d + (L / 2 + d) * (L / 2 + d));
    const double m = m_r + 2 * m_h;
    const double cx = (double(c1.x) + c2.x) / 2, cy = (double(c1.y) + c2.y) / 2;
    printf("    capsule L %.3f r %.3f, density 3: m %.6f (expected %.6f), I %.6f (expected %.6f)\n", L, r,
           i2d_body_get_mass(body), m, i2d_body_get_rotational_inertia(body), inertia);
    check_mass(body, m, inertia, cx, cy);
    check_world_center(body, 1, 1, 1.1, cx, cy);

    // The getter returns the capsule as given.
    I2D_CHECK(i2d_shape_get_type(shape) == I2D_SHAPE_CAPSULE);
    const i2d_capsule cap = i2d_shape_get_capsule(shape);
    I2D_CHECK(cap.center1.x == c1.x && cap.center1.y == c1.y && cap.center2.x == c2.x && cap.center2.y == c2.y);
    I2D_CHECK(cap.radius == radius);
}

I2D_TEST(phys_rotmass_offset_box) {
    // A box of full size 2 x 0.5, density 2 (m = 2 kg), centred at (2, -1) in the body
    // frame and turned by 0.5 rad there. Its own inertia m (w^2 + h^2) / 12 does not
    // depend on its turn; being the only shape, its centre is the body's centre of mass,
    // so the inertia about the centre of mass is that (the parallel axis term is zero),
    // and the world centre of mass is the box centre placed by the body transform.
    Scene scene;
    const double body_angle = 0.3;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{1, 1}, float(body_angle));
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(2.0f));
    const double box_angle = 0.5;
    const i2d_rot q{float(std::cos(box_angle)), float(std::sin(box_angle))};
    i2d_shape_id shape = i2d_shape_create_offset_box(body, &sd, 1.0f, 0.25f, i2d_vec2{2, -1}, q);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    const double m = 2.0 * 2.0 * 0.5, inertia = m * (4.0 + 0.25) / 12.0;
    const i2d_vec2 wc = i2d_body_get_world_center_of_mass(body);
    printf("    offset box: m %.6f (expected %.6f), I %.6f (expected %.6f), world centre (%.5f, %.5f)\n",
           i2d_body_get_mass(body), m, i2d_body_get_rotational_inertia(body), inertia, wc.x, wc.y);
    check_mass(body, m, inertia, 2, -1);
    check_world_center(body, 1, 1, body_angle, 2, -1);

    // Its polygon: 4 corners centre + R(0.5) (+-1, +-0.25), counter-clockwise.
    I2D_CHECK(i2d_shape_get_type(shape) == I2D_SHAPE_POLYGON);
    const i2d_polygon poly = i2d_shape_get_polygon(shape);
    I2D_REQUIRE(poly.count == 4);
    const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (const auto& s : signs) {
        const Point corner = transform_point(2, -1, box_angle, s[0] * 1.0, s[1] * 0.25);
        bool found = false;
        for (int i = 0; i < poly.count; ++i) {
            found = found ||
                    (std::fabs(poly.vertices[i].x - corner.x) < 1e-5 && std::fabs(poly.vertices[i].y - corner.y) < 1e-5);
        }
        I2D_CHECK(found);
    }
    double area2 = 0;
    for (int i = 0; i < poly.count; ++i) {
        const i2d_vec2 a = poly.vertices[i], b = poly.vertices[(i + 1) % poly.count];
        area2 += double(a.x) * b.y - double(a.y) * b.x;
    }
    I2D_CHECK_NEAR(area2 / 2, 1.0, 1e-5);  // counter-clockwise: positive area 2 x 0.5
    I2D_CHECK_NEAR(poly.centroid.x, 2.0, 1e-5);
    I2D_CHECK_NEAR(poly.centroid.y, -1.0, 1e-5);
}

I2D_TEST(phys_rotmass_triangle) {
    // A triangle about its centroid: I = m (a^2 + b^2 + c^2) / 36 with side lengths a, b,
    // c. Vertices (0, 0), (3, 0), (0, 2), given clockwise and with an interior point the
    // hull drops: sides 3, 2, sqrt 13, area 3, centroid (1, 2/3). Density 0.5: m = 1.5,
    // I = 1.5 x 26 / 36.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, -2.0f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(0.5f));
    const i2d_vec2 points[4] = {{0, 0}, {0, 2}, {1, 0.5f}, {3, 0}};
    i2d_shape_id shape = i2d_shape_create_polygon(body, &sd, points, 4);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    const double m = 0.5 * 3.0, inertia = m * (9.0 + 4.0 + 13.0) / 36.0;
    printf("    triangle 3-2-sqrt13: m %.6f (expected %.6f), I %.6f (expected %.6f)\n", i2d_body_get_mass(body), m,
           i2d_body_get_rotational_inertia(body), inertia);
    check_mass(body, m, inertia, 1.0, 2.0 / 3.0);
    check_world_center(body, 0, 0, -2.0, 1.0, 2.0 / 3.0);

    const i2d_polygon poly = i2d_shape_get_polygon(shape);
    I2D_CHECK(poly.count == 3);
    I2D_CHECK(poly.radius == 0.0f);
    I2D_CHECK_NEAR(poly.centroid.x, 1.0, 1e-5);
    I2D_CHECK_NEAR(poly.centroid.y, 2.0 / 3.0, 1e-5);
    if (poly.count == 3) {
        const i2d_vec2 a = poly.vertices[0], b = poly.vertices[1], c = poly.vertices[2];
        const double area = 0.5 * ((double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x));
        I2D_CHECK_NEAR(area, 3.0, 1e-5);  // counter-clockwise after the hull
    }
}

I2D_TEST(phys_rotmass_rounded_box) {
    // A w x h box rounded by r (i2d_make_polygon with a radius, then polygon_from) is the
    // core rectangle, four edge strips r thick and four quarter discs at the corners.
    // Area w h + 2 r (w + h) + pi r^2. Second moments about the centre: core
    // w h (w^2 + h^2) / 12; a strip along the top w r ((w^2 + r^2) / 12 + (h/2 + r/2)^2),
    // along a side h r ((r^2 + h^2) / 12 + (w/2 + r/2)^2); a quarter disc with its apex at
    // corner p: pi r^4 / 8 about the apex, centroid 4r/(3 pi) out along both axes, so
    // pi r^4 / 8 + 2 A (4r/(3 pi)) (|px| + |py|) + A |p|^2 with A = pi r^2 / 4.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    const double w = 1.2, h = 0.6, r = 0.15, rho = 2.0;
    const i2d_vec2 pts[4] = {{float(-w / 2), float(-h / 2)}, {float(w / 2), float(-h / 2)}, {float(w / 2), float(h / 2)},
                             {float(-w / 2), float(h / 2)}};
    i2d_polygon poly;
    I2D_CHECK_STATUS(i2d_make_polygon(pts, 4, float(r), &poly), I2D_OK);
    i2d_shape_def sd = shape_def(with_density(float(rho)));
    i2d_shape_id shape = i2d_shape_create_polygon_from(body, &sd, &poly);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    const double area = w * h + 2 * r * (w + h) + pi * r * r;
    const double core = w * h * (w * w + h * h) / 12;
    const double strips = 2 * w * r * ((w * w + r * r) / 12 + (h / 2 + r / 2) * (h / 2 + r / 2)) +
                          2 * h * r * ((r * r + h * h) / 12 + (w / 2 + r / 2) * (w / 2 + r / 2));
    const double aq = pi * r * r / 4, dq = 4 * r / (3 * pi);
    const double quarter = pi * r * r * r * r / 8 + 2 * aq * dq * (w / 2 + h / 2) + aq * (w * w / 4 + h * h / 4);
    const double m = rho * area, inertia = rho * (core + strips + 4 * quarter);
    printf("    rounded box 1.2 x 0.6 r 0.15: m %.6f (expected %.6f), I %.6f (expected %.6f)\n", i2d_body_get_mass(body),
           m, i2d_body_get_rotational_inertia(body), inertia);
    check_mass(body, m, inertia, 0, 0);
    const i2d_polygon back = i2d_shape_get_polygon(shape);
    I2D_CHECK(back.count == 4);
    I2D_CHECK_NEAR(back.radius, r, 1e-7);
}

I2D_TEST(phys_rotmass_two_shapes) {
    // A 1 x 1 box (density 1, m1 = 1, I1 = 1/6) at the origin and a disc of radius 0.5 at
    // (2, 0) (density 2, m2 = pi/2, I2 = m2 r^2 / 2). Centre of mass
    // x = 2 m2 / (m1 + m2); inertia about it by the parallel axis theorem:
    // I = I1 + m1 x^2 + I2 + m2 (2 - x)^2. Destroying the disc gives back the box alone.
    Scene scene;
    const double body_angle = -0.8;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{5, 2}, float(body_angle));
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def box_def = shape_def(with_density(1.0f)), disc_def = shape_def(with_density(2.0f));
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(body, &box_def, 0.5f, 0.5f)));
    const i2d_circle circle{i2d_vec2{2, 0}, 0.5f};
    i2d_shape_id disc = i2d_shape_create_circle(body, &disc_def, &circle);
    I2D_REQUIRE(!I2D_IS_NULL(disc));
    const double m1 = 1.0, i1 = 1.0 / 6.0, m2 = 2.0 * pi * 0.25, i2 = m2 * 0.25 / 2;
    const double x = 2 * m2 / (m1 + m2);
    const double inertia = i1 + m1 * x * x + i2 + m2 * (2 - x) * (2 - x);
    printf("    box + disc: m %.6f (expected %.6f), centre x %.6f (expected %.6f), I %.6f (expected %.6f)\n",
           i2d_body_get_mass(body), m1 + m2, i2d_body_get_local_center_of_mass(body).x, x,
           i2d_body_get_rotational_inertia(body), inertia);
    check_mass(body, m1 + m2, inertia, x, 0);
    check_world_center(body, 5, 2, body_angle, x, 0);

    I2D_CHECK_STATUS(i2d_shape_destroy(disc), I2D_OK);
    check_mass(body, m1, i1, 0, 0);
    check_world_center(body, 5, 2, body_angle, 0, 0);
}

I2D_TEST(phys_rotmass_no_inertia_bodies) {
    // A fixed-rotation body keeps its mass but reports no inertia; static and kinematic
    // bodies report neither. A segment adds no mass: a box plus a segment weighs what the
    // box weighs, with the same centre and inertia.
    Scene scene;
    i2d_shape_def sd = shape_def(with_density(1.0f));
    i2d_body_id fixed = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, 0.0f, true);
    i2d_body_id still = make_body(scene, I2D_BODY_STATIC, i2d_vec2{5, 0});
    i2d_body_id kin = make_body(scene, I2D_BODY_KINEMATIC, i2d_vec2{10, 0}, 0.4f);
    i2d_body_id seg = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{15, 0}, 0.4f);
    I2D_REQUIRE(!I2D_IS_NULL(fixed) && !I2D_IS_NULL(still) && !I2D_IS_NULL(kin) && !I2D_IS_NULL(seg));
    for (i2d_body_id b : {fixed, still, kin, seg}) {
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(b, &sd, 1.0f, 0.5f)));
    }
    const double m = 2.0, inertia = m * (4.0 + 1.0) / 12.0;
    I2D_CHECK_NEAR(i2d_body_get_mass(fixed), m, rel_tol(m));
    I2D_CHECK(i2d_body_get_rotational_inertia(fixed) == 0.0f);
    I2D_CHECK(i2d_body_get_mass(still) == 0.0f && i2d_body_get_rotational_inertia(still) == 0.0f);
    I2D_CHECK(i2d_body_get_mass(kin) == 0.0f && i2d_body_get_rotational_inertia(kin) == 0.0f);

    const MassSnapshot before = MassSnapshot::of(seg);
    i2d_shape_id segment = i2d_shape_create_segment(seg, &sd, i2d_vec2{0, 0}, i2d_vec2{3, 1});
    I2D_REQUIRE(!I2D_IS_NULL(segment));
    const MassSnapshot after = MassSnapshot::of(seg);
    I2D_CHECK(after.shape_count == before.shape_count + 1);
    I2D_CHECK_NEAR(after.mass, m, rel_tol(m));
    I2D_CHECK_NEAR(after.inertia, inertia, rel_tol(inertia));
    I2D_CHECK_NEAR(after.local_center.x, 0.0, 1e-6);
    I2D_CHECK_NEAR(after.local_center.y, 0.0, 1e-6);
    I2D_CHECK(i2d_shape_get_type(segment) == I2D_SHAPE_SEGMENT);
    const i2d_segment sg = i2d_shape_get_segment(segment);
    I2D_CHECK(sg.point1.x == 0.0f && sg.point1.y == 0.0f && sg.point2.x == 3.0f && sg.point2.y == 1.0f);
    // Asking a segment for another kind gives zero and I2D_ERR_INVALID_ARGUMENT.
    const i2d_circle none = i2d_shape_get_circle(segment);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(none.radius == 0.0f);
    printf("    fixed-rotation I %.3g (m %.4f); static m %.3g I %.3g; kinematic m %.3g I %.3g; box+segment m %.6f I %.6f "
           "(expected %.6f, %.6f)\n",
           i2d_body_get_rotational_inertia(fixed), i2d_body_get_mass(fixed), i2d_body_get_mass(still),
           i2d_body_get_rotational_inertia(still), i2d_body_get_mass(kin), i2d_body_get_rotational_inertia(kin),
           after.mass, after.inertia, m, inertia);
}

I2D_TEST(phys_rotmass_shape_refusals) {
    // Degenerate shapes are refused with I2D_ERR_INVALID_ARGUMENT and a message, and the
    // body's mass, inertia, centre of mass and shape count stay exactly as they were.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{1, 2}, 0.3f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(1.0f));
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_offset_box(body, &sd, 0.5f, 0.25f, i2d_vec2{0.5f, 0}, i2d_make_rot(0))));
    const MassSnapshot before = MassSnapshot::of(body);
    I2D_CHECK_NEAR(before.mass, 0.5, rel_tol(0.5));
    I2D_CHECK_NEAR(before.inertia, 0.5 * (1.0 + 0.25) / 12, rel_tol(0.5 * 1.25 / 12));

    const float nan = std::numeric_limits<float>::quiet_NaN();
    const i2d_vec2 collinear[3] = {{0, 0}, {1, 0}, {2, 0}};
    check_refused(i2d_shape_create_polygon(body, &sd, collinear, 3), body, before, "polygon: collinear");
    const i2d_vec2 duplicate[3] = {{0, 0}, {1, 0}, {1, 0}};
    check_refused(i2d_shape_create_polygon(body, &sd, duplicate, 3), body, before, "polygon: duplicate points");
    const i2d_vec2 near_duplicate[4] = {{0, 0}, {0.001f, 0}, {1, 1}, {1.002f, 1.001f}};
    check_refused(i2d_shape_create_polygon(body, &sd, near_duplicate, 4), body, before,
                  "polygon: points closer than 0.005 m");
    // Equilateral, side 0.0065 m: points 0.0065 apart, heights 0.00563 (neither duplicate
    // nor collinear by the 0.005 m rules), but area 1.83e-5 m^2 < 0.005^2.
    const i2d_vec2 tiny[3] = {{0, 0}, {0.0065f, 0}, {0.00325f, 0.0056292f}};
    check_refused(i2d_shape_create_polygon(body, &sd, tiny, 3), body, before, "polygon: tiny area");
    const i2d_vec2 nine[9] = {{1, 0}, {0.77f, 0.64f}, {0.17f, 0.98f}, {-0.5f, 0.87f}, {-0.94f, 0.34f},
                              {-0.94f, -0.34f}, {-0.5f, -0.87f}, {0.17f, -0.98f}, {0.77f, -0.64f}};
    check_refused(i2d_shape_create_polygon(body, &sd, nine, 2), body, before, "polygon: count 2");
    check_refused(i2d_shape_create_polygon(body, &sd, nine, 9), body, before, "polygon: count 9");
    check_refused(i2d_shape_create_polygon(body, &sd, nullptr, 3), body, before, "polygon: NULL points");
    const i2d_vec2 with_nan[3] = {{0, 0}, {1, nan}, {0, 1}};
    check_refused(i2d_shape_create_polygon(body, &sd, with_nan, 3), body, before, "polygon: NaN point");

    check_refused(i2d_shape_create_capsule(body, &sd, i2d_vec2{1, 1}, i2d_vec2{1, 1}, 0.5f), body, before,
                  "capsule: coincident centres");
    check_refused(i2d_shape_create_capsule(body, &sd, i2d_vec2{0, 0}, i2d_vec2{0.004f, 0}, 0.5f), body, before,
                  "capsule: centres 0.004 m apart");
    check_refused(i2d_shape_create_capsule(body, &sd, i2d_vec2{0, 0}, i2d_vec2{1, 0}, 0.0f), body, before,
                  "capsule: radius 0");
    check_refused(i2d_shape_create_capsule(body, &sd, i2d_vec2{0, 0}, i2d_vec2{1, 0}, -0.5f), body, before,
                  "capsule: negative radius");
    check_refused(i2d_shape_create_capsule(body, &sd, i2d_vec2{0, 0}, i2d_vec2{1, 0}, 2e5f), body, before,
                  "capsule: radius 2e5");
    check_refused(i2d_shape_create_capsule(body, &sd, i2d_vec2{0, 0}, i2d_vec2{1, 0}, nan), body, before,
                  "capsule: NaN radius");

    check_refused(i2d_shape_create_segment(body, &sd, i2d_vec2{0, 0}, i2d_vec2{0.004f, 0}), body, before,
                  "segment: 0.004 m long");
    check_refused(i2d_shape_create_segment(body, &sd, i2d_vec2{0, 0}, i2d_vec2{0, 0}), body, before,
                  "segment: zero length");

    check_refused(i2d_shape_create_offset_box(body, &sd, 0.5f, 0.5f, i2d_vec2{0, 0}, i2d_rot{1.1f, 0.0f}), body,
                  before, "offset box: c^2 + s^2 = 1.21");
    check_refused(i2d_shape_create_offset_box(body, &sd, 0.5f, 0.5f, i2d_vec2{0, 0}, i2d_rot{0.0f, 0.0f}), body,
                  before, "offset box: zero rotation");
    check_refused(i2d_shape_create_offset_box(body, &sd, 0.5f, 0.5f, i2d_vec2{0, 0}, i2d_rot{0.6f, 0.6f}), body,
                  before, "offset box: c^2 + s^2 = 0.72");

    // After all that, a valid shape is still accepted and adds its mass.
    const i2d_vec2 tri[3] = {{0, 0}, {1, 0}, {0, 1}};
    I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_polygon(body, &sd, tri, 3)));
    I2D_CHECK_NEAR(i2d_body_get_mass(body), 1.0, rel_tol(1.0));
}

I2D_TEST(phys_rotmass_polygon_from_refusals) {
    // i2d_shape_create_polygon_from checks the polygon it is given ("convex,
    // counter-clockwise and consistent", impulse2d.h): a count of 0 (what i2d_make_box
    // returns for bad sizes), NULL, a box with its vertices in clockwise order (its normals
    // then belong to other edges) and a non-convex pentagon with correct outward edge
    // normals are refused like the other degenerate shapes.
    Scene scene;
    i2d_body_id body = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0});
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_shape_def sd = shape_def(with_density(1.0f));
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(body, &sd, 0.5f, 0.5f)));
    const MassSnapshot before = MassSnapshot::of(body);

    const i2d_polygon empty = i2d_make_box(-1.0f, 1.0f);
    I2D_CHECK(empty.count == 0);
    check_refused(i2d_shape_create_polygon_from(body, &sd, &empty), body, before, "polygon_from: count 0");
    check_refused(i2d_shape_create_polygon_from(body, &sd, nullptr), body, before, "polygon_from: NULL");

    i2d_polygon reversed = i2d_make_box(0.5f, 0.5f);
    std::reverse(reversed.vertices, reversed.vertices + reversed.count);
    check_refused(i2d_shape_create_polygon_from(body, &sd, &reversed), body, before,
                  "polygon_from: clockwise vertices");

    // (0,0) (2,0) (1,0.5) (2,2) (0,2): counter-clockwise, dented at (1, 0.5).
    i2d_polygon dented = i2d_make_box(1.0f, 1.0f);
    const i2d_vec2 v[5] = {{0, 0}, {2, 0}, {1, 0.5f}, {2, 2}, {0, 2}};
    dented.count = 5;
    for (int i = 0; i < 5; ++i) {
        const i2d_vec2 a = v[i], b = v[(i + 1) % 5];
        const double ex = double(b.x) - a.x, ey = double(b.y) - a.y, len = std::hypot(ex, ey);
        dented.vertices[i] = a;
        dented.normals[i] = i2d_vec2{float(ey / len), float(-ex / len)};
    }
    dented.centroid = i2d_vec2{1, 1};
    check_refused(i2d_shape_create_polygon_from(body, &sd, &dented), body, before, "polygon_from: not convex");
}
