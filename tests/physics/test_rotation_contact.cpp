// SPDX-License-Identifier: MIT
// Contacts with rotation: resting and tipping boxes, a tilted drop, slopes, a rolling
// disc, polygons and a stack at rest, segment ground, and an off-centre collision that
// must conserve momentum, angular momentum and (elastic, frictionless) energy. Every
// expectation comes from statics, closed-form dynamics or conservation laws.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// The total turn of a body, unwrapped across the +-pi seam (sample at least every
// quarter turn).
struct TurnTracker {
    double last = 0, total = 0;
    explicit TurnTracker(i2d_body_id b) : last(angle_of(b)) {}
    void add(i2d_body_id b) {
        const double a = angle_of(b);
        total += wrap_angle(a - last);
        last = a;
    }
};

// A body turned by angle with one shape made by `make`.
template <class MakeShape>
i2d_body_id make_body(Scene& scene, i2d_body_type type, i2d_vec2 position, double angle, MakeShape make) {
    const i2d_body_def def = turned_body_def(type, position, angle);
    i2d_body_id body = i2d_body_create(scene.world, &def);
    if (I2D_IS_NULL(body)) {
        fprintf(stderr, "    body creation failed: %s\n", i2d_last_error_message());
        return body;
    }
    if (I2D_IS_NULL(make(body))) {
        fprintf(stderr, "    shape creation failed: %s\n", i2d_last_error_message());
        return I2D_NULL_BODY_ID;
    }
    return body;
}

// The slopes here: 8 m long.
constexpr double slope_half_length = 4.0;

// Kinetic energy, J, with the closed-form mass and inertia rather than the engine's.
double kinetic_energy(i2d_body_id b, double m, double inertia) {
    const i2d_vec2 v = velocity(b);
    const double w = i2d_body_get_angular_velocity(b);
    return 0.5 * m * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * inertia * w * w;
}

// Angular momentum about the world origin: m (c x v) + I w, c the centre of mass.
double angular_momentum(i2d_body_id b, double m, double inertia) {
    const i2d_vec2 c = i2d_body_get_world_center_of_mass(b), v = velocity(b);
    return m * (double(c.x) * v.y - double(c.y) * v.x) + inertia * i2d_body_get_angular_velocity(b);
}

// Settles `settle` seconds, then watches a body at rest for `watch` seconds.
struct RestStats {
    Range x, y, angle;
    double max_speed = 0, max_spin = 0;
};

bool watch_rest(Scene& scene, const i2d_body_id* bodies, RestStats* stats, int count, double settle, double watch) {
    if (!scene.step(steps_for(settle))) {
        return false;
    }
    for (int s = 0; s < steps_for(watch); ++s) {
        if (!scene.step()) {
            return false;
        }
        for (int i = 0; i < count; ++i) {
            const i2d_vec2 p = position(bodies[i]);
            stats[i].x.add(p.x);
            stats[i].y.add(p.y);
            stats[i].angle.add(angle_of(bodies[i]));
            stats[i].max_speed = std::max(stats[i].max_speed, speed(velocity(bodies[i])));
            stats[i].max_spin = std::max(stats[i].max_spin, std::fabs(double(i2d_body_get_angular_velocity(bodies[i]))));
        }
    }
    return true;
}

}  // namespace

I2D_TEST(phys_rotcontact_box_rests_on_face) {
    // A box set down on a face stays put for 5 s: it drifts less than 1 mm, turns less than
    // 0.001 rad and sinks no deeper than the slop. A cube and a flat plank.
    const double slop = i2d_default_world_def().contact_slop;
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    i2d_body_id cube = scene.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    i2d_body_id plank = scene.dynamic_box(i2d_vec2{5, 0.25f}, 1.5f, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(cube) && !I2D_IS_NULL(plank));
    const i2d_body_id bodies[2] = {cube, plank};
    const double half_heights[2] = {0.5, 0.25}, x0[2] = {0, 5};
    double drift[2] = {0, 0}, turn[2] = {0, 0};
    Range sink[2];
    for (int s = 0; s < steps_for(5.0); ++s) {
        I2D_REQUIRE(scene.step());
        for (int i = 0; i < 2; ++i) {
            const i2d_vec2 p = position(bodies[i]);
            drift[i] = std::max(drift[i], std::fabs(p.x - x0[i]));
            turn[i] = std::max(turn[i], std::fabs(angle_of(bodies[i])));
            sink[i].add(half_heights[i] - p.y);
        }
    }
    printf("    resting on a face, 5 s: cube drift %.3g m turn %.3g rad sink %.3g m; plank drift %.3g m turn %.3g rad "
           "sink %.3g m\n",
           drift[0], turn[0], sink[0].hi, drift[1], turn[1], sink[1].hi);
    for (int i = 0; i < 2; ++i) {
        const int before = i2d_check_failures;
        I2D_CHECK(drift[i] < 1e-3);
        I2D_CHECK(turn[i] < 1e-3);
        I2D_CHECK(sink[i].hi <= slop + 1e-3);
        I2D_CHECK(sink[i].lo >= -1e-4);
        report_case(before, i == 0 ? "cube" : "plank");
    }
}

I2D_TEST(phys_rotcontact_box_tips_off_edge) {
    // A static platform's top-right edge is at (0, 0). A unit box on it with its centre of
    // mass 0.1 m past the edge has nothing under its centre: gravity's torque about the
    // edge (m g 0.1) tips it clockwise; it turns past 45 degrees and falls, its centre
    // ending below the platform top, right of the edge.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.box(body_def(I2D_BODY_STATIC, i2d_vec2{-2, -0.5f}), 2.0f, 0.5f)));
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0.1f, 0.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    TurnTracker turn(box);
    double most_clockwise = 0, time_45 = -1;
    for (int s = 1; s <= steps_for(3.0); ++s) {
        I2D_REQUIRE(scene.step());
        turn.add(box);
        most_clockwise = std::min(most_clockwise, turn.total);
        if (time_45 < 0 && turn.total < -pi / 4) {
            time_45 = s * double(time_step);
        }
    }
    const i2d_vec2 p = position(box);
    printf("    tipping box (centre 0.1 m past the edge): turned %.3f rad (most clockwise %.3f), past 45 deg at %.3f s, "
           "ends at (%.3f, %.3f)\n",
           turn.total, most_clockwise, time_45, p.x, p.y);
    I2D_CHECK(most_clockwise < -pi / 4);
    I2D_CHECK(p.y < 0.0);
    I2D_CHECK(p.x > 0.0);
}

I2D_TEST(phys_rotcontact_box_balanced_inside_edge) {
    // The same box with its centre of mass 0.05 m inside the edge is supported (its centre
    // lies over the contact region): it stays level and in place for 3 s.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.box(body_def(I2D_BODY_STATIC, i2d_vec2{-2, -0.5f}), 2.0f, 0.5f)));
    i2d_body_id box = scene.dynamic_box(i2d_vec2{-0.05f, 0.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    Range x, y, angle;
    for (int s = 0; s < steps_for(3.0); ++s) {
        I2D_REQUIRE(scene.step());
        x.add(position(box).x);
        y.add(position(box).y);
        angle.add(angle_of(box));
    }
    printf("    box 0.05 m inside the edge, 3 s: |angle| <= %.3g rad, x %.5f .. %.5f, y %.5f .. %.5f\n", angle.abs_max(),
           x.lo, x.hi, y.lo, y.hi);
    I2D_CHECK(angle.abs_max() < 0.01);
    I2D_CHECK(std::fabs(x.lo + 0.05) < 0.005 && std::fabs(x.hi + 0.05) < 0.005);
    I2D_CHECK(y.lo > 0.5 - 0.01 && y.hi < 0.5 + 1e-3);
}

I2D_TEST(phys_rotcontact_tilted_drop_lands_flat) {
    // A unit box dropped corner first, turned by 30 degrees, lands and settles on a face:
    // its final rotation is a multiple of 90 degrees (within 0.01 rad), its centre 0.5 m
    // above the ground, and it is at rest.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    i2d_body_id box = scene.turned_box(I2D_BODY_DYNAMIC, i2d_vec2{0, 1.5f}, degrees(30), 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(scene.step(steps_for(4.0)));
    const double a = angle_of(box);
    const double off_square = a - std::round(a / (pi / 2)) * (pi / 2);
    const double v = speed(velocity(box)), w = i2d_body_get_angular_velocity(box);
    printf("    tilted drop (30 deg): final angle %.5f rad (%.5f from a multiple of 90 deg), y %.5f, speed %.3g, "
           "spin %.3g\n",
           a, off_square, position(box).y, v, w);
    I2D_CHECK(std::fabs(off_square) < 0.01);
    I2D_CHECK_NEAR(position(box).y, 0.5, 0.01);
    I2D_CHECK(v < 0.01);
    I2D_CHECK(std::fabs(w) < 0.01);
}

I2D_TEST(phys_rotcontact_capsule_rolls_off_slope) {
    // A stubby capsule (centres 0.2 m apart, radius 0.4) lying on its side on a 20 degree
    // slope: its flat support is 0.2 m long, so with its centre 0.4 m above the surface it
    // tips once tan(theta) > 0.1 / 0.4 = 0.25 (tan 20 = 0.36) and rolls downhill
    // (counter-clockwise, to the left) off the slope's lower end.
    Scene scene;
    const Slope slope{degrees(20), slope_half_length};
    I2D_REQUIRE(!I2D_IS_NULL(scene.slope(slope)));
    i2d_body_id capsule = make_body(scene, I2D_BODY_DYNAMIC, slope.at(1.0, 0.4 + 0.002), slope.theta, [](i2d_body_id b) {
        i2d_shape_def sd = i2d_default_shape_def();
        return i2d_shape_create_capsule(b, &sd, i2d_vec2{-0.1f, 0}, i2d_vec2{0.1f, 0}, 0.4f);
    });
    I2D_REQUIRE(!I2D_IS_NULL(capsule));
    TurnTracker turn(capsule);
    double left_at = -1;
    for (int s = 1; s <= steps_for(5.0); ++s) {
        I2D_REQUIRE(scene.step());
        turn.add(capsule);
        if (left_at < 0 && slope.along(i2d_body_get_world_center_of_mass(capsule)) < -slope.half_length) {
            left_at = s * double(time_step);
        }
    }
    const i2d_vec2 c = i2d_body_get_world_center_of_mass(capsule);
    printf("    capsule on 20 deg slope: rolled %.2f rad, left the slope at %.2f s, ends %.2f m along it at (%.2f, %.2f)\n",
           turn.total, left_at, slope.along(c), c.x, c.y);
    I2D_CHECK(turn.total > pi / 2);                       // it rolled, not just slid
    I2D_CHECK(slope.along(c) < -slope.half_length);       // past the lower end
    I2D_CHECK(c.y < slope.at(-slope.half_length, 0).y);  // and below it
}

I2D_TEST(phys_rotcontact_box_holds_on_slope) {
    // On a 20 degree slope a box with friction 0.6 holds (tan 20 = 0.36 < 0.6; its centre
    // lies over its base, so it does not tip): it creeps less than 3 mm along the slope in
    // 2 s and keeps the slope's angle. A box of friction 0.05 (mixed sqrt(0.05 x 0.6) =
    // 0.173 < 0.36) slides down at a = g (sin 20 - mu cos 20) = 1.79 m/s^2.
    Scene scene;
    const Slope slope{degrees(20), slope_half_length};
    I2D_REQUIRE(!I2D_IS_NULL(scene.slope(slope, with_friction(0.6f))));
    i2d_body_id holder = scene.turned_box(I2D_BODY_DYNAMIC, slope.at(2.5, 0.5), slope.theta, 0.5f, 0.5f,
                                    with_friction(0.6f));
    i2d_body_id slider = scene.turned_box(I2D_BODY_DYNAMIC, slope.at(-2.5, 0.5), slope.theta, 0.5f, 0.5f,
                                    with_friction(0.05f));
    I2D_REQUIRE(!I2D_IS_NULL(holder) && !I2D_IS_NULL(slider));
    const double s_holder = slope.along(position(holder)), s_slider = slope.along(position(slider));
    const double mu = std::sqrt(0.05 * 0.6);
    const double a = g * (std::sin(slope.theta) - mu * std::cos(slope.theta));
    double slid = NAN;
    Range creep, turn, sink;
    for (int s = 1; s <= steps_for(2.0); ++s) {
        I2D_REQUIRE(scene.step());
        creep.add(slope.along(position(holder)) - s_holder);
        turn.add(angle_of(holder) - slope.theta);
        sink.add(0.5 - slope.above(position(holder)));
        if (s == steps_for(1.0)) {
            slid = s_slider - slope.along(position(slider));
        }
    }
    printf("    box on 20 deg slope, mu 0.6, 2 s: creep %.3g m, turn %.3g rad, sink %.3g m; mu 0.173 slid %.4f m in 1 s "
           "(expected %.4f)\n",
           creep.abs_max(), turn.abs_max(), sink.hi, slid, a / 2);
    I2D_CHECK(creep.abs_max() < 3e-3);
    I2D_CHECK(turn.abs_max() < 0.01);
    I2D_CHECK(sink.hi < i2d_default_world_def().contact_slop + 1e-3);
    I2D_CHECK_NEAR(slid, a / 2, 0.03 * a / 2 + a * substep / 2);
}

I2D_TEST(phys_rotcontact_disc_rolls_without_slipping) {
    // A uniform disc set down sliding at v0 without spin: friction slows it (a = -mu g) and
    // spins it up (alpha = 2 mu g / r) until the contact point stops slipping at
    // t = v0 / (3 mu g). Angular momentum about the contact point is conserved, so it then
    // rolls at v = v0 / (1 + I / (m r^2)) = 2/3 v0 with v = -w r (clockwise going right),
    // and nothing slows it after that.
    Scene scene;
    const double r = 0.5, v0 = 3.0, mu = 0.6;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    i2d_body_id disc = scene.dynamic_circle(i2d_vec2{0, float(r)}, float(r), Material{}, i2d_vec2{float(v0), 0});
    I2D_REQUIRE(!I2D_IS_NULL(disc));
    // Sliding phase, t = 0.1 s < 1/6 s.
    I2D_REQUIRE(scene.step(6));
    const double t = 6 * double(time_step);
    const double v_slip = velocity(disc).x, w_slip = i2d_body_get_angular_velocity(disc);
    I2D_CHECK_NEAR(v_slip, v0 - mu * g * t, 0.03 * v0);
    I2D_CHECK_NEAR(w_slip, -2 * mu * g / r * t, 0.03 * v0 / r);

    I2D_REQUIRE(scene.step(steps_for(1.0) - 6));
    const double v1 = velocity(disc).x, w1 = i2d_body_get_angular_velocity(disc);
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    const double v2 = velocity(disc).x, w2 = i2d_body_get_angular_velocity(disc);
    const double expected = v0 * 2.0 / 3.0;
    printf("    rolling disc v0 3: at 0.1 s v %.4f w %.4f (expected %.4f, %.4f); at 1 s v %.4f w r %.4f; at 2 s v %.4f "
           "w r %.4f (expected v %.4f)\n",
           v_slip, w_slip, v0 - mu * g * t, -2 * mu * g / r * t, v1, w1 * r, v2, w2 * r, expected);
    I2D_CHECK_NEAR(v1, expected, 0.02 * expected);
    I2D_CHECK_NEAR(v2, expected, 0.02 * expected);
    I2D_CHECK_NEAR(-w1 * r, v1, 0.01 * v1);
    I2D_CHECK_NEAR(-w2 * r, v2, 0.01 * v2);
    I2D_CHECK_NEAR(position(disc).y, r, 0.01);
}

I2D_TEST(phys_rotcontact_polygons_rest) {
    // A triangle on its base and a rounded box (i2d_make_polygon with radius 0.1) set down
    // on the ground rest without jitter: after 1 s to settle, over 2 s they move less than
    // 1e-3 m/s, spin less than 1e-3 rad/s, stay level within 1e-3 rad, and sit no deeper
    // than the slop.
    const double slop = i2d_default_world_def().contact_slop;
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    i2d_body_id triangle = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{0, 0}, 0.0, [](i2d_body_id b) {
        const i2d_vec2 pts[3] = {{-0.5f, 0}, {0.5f, 0}, {0, 0.8f}};
        i2d_shape_def sd = i2d_default_shape_def();
        return i2d_shape_create_polygon(b, &sd, pts, 3);
    });
    i2d_body_id rounded = make_body(scene, I2D_BODY_DYNAMIC, i2d_vec2{3, 0.3f}, 0.0, [](i2d_body_id b) {
        const i2d_vec2 pts[4] = {{-0.4f, -0.2f}, {0.4f, -0.2f}, {0.4f, 0.2f}, {-0.4f, 0.2f}};
        i2d_polygon poly;
        if (i2d_make_polygon(pts, 4, 0.1f, &poly) != I2D_OK) {
            return I2D_NULL_SHAPE_ID;
        }
        i2d_shape_def sd = i2d_default_shape_def();
        return i2d_shape_create_polygon_from(b, &sd, &poly);
    });
    I2D_REQUIRE(!I2D_IS_NULL(triangle) && !I2D_IS_NULL(rounded));
    const i2d_body_id bodies[2] = {triangle, rounded};
    RestStats stats[2];
    I2D_REQUIRE(watch_rest(scene, bodies, stats, 2, 1.0, 2.0));
    const double rest_y[2] = {0.0, 0.3};
    const char* names[2] = {"triangle", "rounded box"};
    for (int i = 0; i < 2; ++i) {
        const RestStats& st = stats[i];
        printf("    %s at rest: speed <= %.3g m/s, spin <= %.3g rad/s, |angle| <= %.3g rad, y range %.3g m, sink %.3g m\n",
               names[i], st.max_speed, st.max_spin, st.angle.abs_max(), st.y.width(), rest_y[i] - st.y.lo);
        const int before = i2d_check_failures;
        I2D_CHECK(st.max_speed < 1e-3);
        I2D_CHECK(st.max_spin < 1e-3);
        I2D_CHECK(st.angle.abs_max() < 1e-3);
        I2D_CHECK(st.y.width() < 1e-4);
        I2D_CHECK(st.x.width() < 1e-4);
        I2D_CHECK(rest_y[i] - st.y.lo <= slop + 1e-3);
        I2D_CHECK(st.y.hi <= rest_y[i] + 1e-4);
        report_case(before, names[i]);
    }
}

I2D_TEST(phys_rotcontact_stack_of_three) {
    // Three unit boxes stacked on the ground stand for 3 s: no box turns more than
    // 0.01 rad or slides sideways more than 1 cm, and the stack ends at rest with the top
    // box no lower than three slops below 2.5 m.
    const double slop = i2d_default_world_def().contact_slop;
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    const std::vector<i2d_body_id> boxes = scene.column(0.0f, 3);
    I2D_REQUIRE(boxes.size() == 3);
    double turn = 0, slide = 0;
    for (int s = 0; s < steps_for(3.0); ++s) {
        I2D_REQUIRE(scene.step());
        for (i2d_body_id b : boxes) {
            turn = std::max(turn, std::fabs(angle_of(b)));
            slide = std::max(slide, std::fabs(double(position(b).x)));
        }
    }
    double fastest = 0;
    for (i2d_body_id b : boxes) {
        fastest = std::max(fastest, speed(velocity(b)));
    }
    const double top = position(boxes[2]).y;
    printf("    stack of 3, 3 s: max turn %.3g rad, max slide %.3g m, top y %.5f, final speed %.3g\n", turn, slide, top,
           fastest);
    I2D_CHECK(turn < 0.01);
    I2D_CHECK(slide < 0.01);
    I2D_CHECK(top > 2.5 - 3 * slop - 1e-3 && top < 2.5 + 1e-3);
    I2D_CHECK(fastest < 0.01);
}

I2D_TEST(phys_rotcontact_segment_ground) {
    // A static body holding one long segment at y = 0 carries a unit box and a disc of
    // radius 0.5 just as a box ground would: dropped from 5 cm they settle with their
    // centres 0.5 m up (no deeper than the slop) and rest without jitter or turning.
    const double slop = i2d_default_world_def().contact_slop;
    Scene scene;
    i2d_body_id ground = make_body(scene, I2D_BODY_STATIC, i2d_vec2{0, 0}, 0.0, [](i2d_body_id b) {
        i2d_shape_def sd = i2d_default_shape_def();
        return i2d_shape_create_segment(b, &sd, i2d_vec2{-20, 0}, i2d_vec2{20, 0});
    });
    I2D_REQUIRE(!I2D_IS_NULL(ground));
    i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0.55f}, 0.5f, 0.5f);
    i2d_body_id disc = scene.dynamic_circle(i2d_vec2{3, 0.55f}, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(disc));
    const i2d_body_id bodies[2] = {box, disc};
    RestStats stats[2];
    I2D_REQUIRE(watch_rest(scene, bodies, stats, 2, 1.0, 1.0));
    const char* names[2] = {"box", "disc"};
    for (int i = 0; i < 2; ++i) {
        const RestStats& st = stats[i];
        printf("    %s on a segment: y %.5f .. %.5f, speed <= %.3g m/s, spin <= %.3g rad/s, |angle| <= %.3g rad\n",
               names[i], st.y.lo, st.y.hi, st.max_speed, st.max_spin, st.angle.abs_max());
        const int before = i2d_check_failures;
        I2D_CHECK(st.y.lo >= 0.5 - slop - 1e-3);
        I2D_CHECK(st.y.hi <= 0.5 + 1e-4);
        I2D_CHECK(st.max_speed < 1e-3);
        I2D_CHECK(st.max_spin < 1e-3);
        I2D_CHECK(st.x.width() < 1e-4);
        report_case(before, names[i]);
    }
    I2D_CHECK(stats[0].angle.abs_max() < 1e-3);
}

namespace {

// Two unit boxes meet off-centre without gravity: A (density 1) at (-2, 0.3) moving at
// 4 m/s, B (density 2) at (2, -0.3) moving at -1 m/s; their faces meet after 0.6 s over
// y in [-0.2, 0.2], below A's centre and above B's, so the contact spins both.
struct Collision {
    double p0x, p0y, p1x, p1y, scale_p;  // linear momentum before/after, and sum m |v|
    double l0, l1, scale_l;              // angular momentum about the origin
    double e0, e1;                       // kinetic energy
    double wa, wb, va;                   // after: spins, A's x velocity
};

bool collide_off_centre(float restitution, float friction, Collision* out) {
    Scene scene(Scene::zero_gravity_def());
    const Material ma = material(friction, restitution), mb = material(friction, restitution, 2.0f);
    i2d_body_id a = scene.dynamic_box(i2d_vec2{-2, 0.3f}, 0.5f, 0.5f, ma, i2d_vec2{4, 0});
    i2d_body_id b = scene.dynamic_box(i2d_vec2{2, -0.3f}, 0.5f, 0.5f, mb, i2d_vec2{-1, 0});
    if (I2D_IS_NULL(a) || I2D_IS_NULL(b)) {
        return false;
    }
    const double m_a = 1.0, m_b = 2.0, i_a = m_a * 2.0 / 12, i_b = m_b * 2.0 / 12;
    auto momentum = [&](double* px, double* py) {
        const i2d_vec2 va = velocity(a), vb = velocity(b);
        *px = m_a * va.x + m_b * vb.x;
        *py = m_a * va.y + m_b * vb.y;
    };
    momentum(&out->p0x, &out->p0y);
    out->scale_p = m_a * speed(velocity(a)) + m_b * speed(velocity(b));
    out->l0 = angular_momentum(a, m_a, i_a) + angular_momentum(b, m_b, i_b);
    out->scale_l = std::fabs(angular_momentum(a, m_a, i_a)) + std::fabs(angular_momentum(b, m_b, i_b));
    out->e0 = kinetic_energy(a, m_a, i_a) + kinetic_energy(b, m_b, i_b);
    if (!scene.step(steps_for(1.5))) {
        return false;
    }
    momentum(&out->p1x, &out->p1y);
    out->l1 = angular_momentum(a, m_a, i_a) + angular_momentum(b, m_b, i_b);
    out->e1 = kinetic_energy(a, m_a, i_a) + kinetic_energy(b, m_b, i_b);
    out->wa = i2d_body_get_angular_velocity(a);
    out->wb = i2d_body_get_angular_velocity(b);
    out->va = velocity(a).x;
    return true;
}

void check_conservation(const Collision& c) {
    I2D_CHECK_NEAR(c.p1x, c.p0x, 1e-4 * c.scale_p);
    I2D_CHECK_NEAR(c.p1y, c.p0y, 1e-4 * c.scale_p);
    // The soft step keeps each contact's anchors fixed to the bodies' centres for a whole
    // step (Box2D v3's choice, which keeps rolling exact): the two halves of an impulse
    // act at points that drift apart by the pair's relative motion within the step, so
    // angular momentum is kept to the size of impulse x that drift, here 3.4 %.
    I2D_CHECK_NEAR(c.l1, c.l0, 0.05 * c.scale_l);
    // The collision happened and spun the boxes (clockwise for A, whose centre is above
    // the contact it is pushed back at).
    I2D_CHECK(c.va < 3.0);
    I2D_CHECK(c.wa < -0.1);
    I2D_CHECK(std::fabs(c.wb) > 0.05);
}

}  // namespace

I2D_TEST(phys_rotcontact_off_centre_collision_momentum) {
    // With restitution 0 and friction 0.6 the contact may slide, stick and spin the
    // boxes, but linear momentum (1e-4 of sum m |v|) and angular momentum about the
    // origin, sum m (c x v) + I w (1e-3 of sum |L_i|), are conserved; energy is lost.
    Collision c;
    I2D_REQUIRE(collide_off_centre(0.0f, 0.6f, &c));
    printf("    off-centre, e 0 mu 0.6: p (%.6f, %.6f) -> (%.6f, %.6f); L %.6f -> %.6f; E %.4f -> %.4f; "
           "w %.3f, %.3f\n",
           c.p0x, c.p0y, c.p1x, c.p1y, c.l0, c.l1, c.e0, c.e1, c.wa, c.wb);
    check_conservation(c);
    I2D_CHECK(c.e1 < c.e0);
}

I2D_TEST(phys_rotcontact_off_centre_collision_elastic) {
    // With restitution 1 and no friction the same collision also keeps the kinetic energy,
    // linear plus rotational, within 2 %.
    Collision c;
    I2D_REQUIRE(collide_off_centre(1.0f, 0.0f, &c));
    printf("    off-centre, e 1 mu 0: p (%.6f, %.6f) -> (%.6f, %.6f); L %.6f -> %.6f; E %.4f -> %.4f (%.3f %%); "
           "w %.3f, %.3f\n",
           c.p0x, c.p0y, c.p1x, c.p1y, c.l0, c.l1, c.e0, c.e1, 100 * (c.e1 / c.e0 - 1), c.wa, c.wb);
    check_conservation(c);
    I2D_CHECK_NEAR(c.e1, c.e0, 0.02 * c.e0);
}
