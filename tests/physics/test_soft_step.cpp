// SPDX-License-Identifier: MIT
// The soft step against closed form: friction on an incline (holds below atan(mu),
// slides at g (sin - mu cos) above it), a disc rolling down an incline, tall stacks and a
// 20-row pyramid, Newton's cradle, an elastic ball that keeps its energy for 60 s,
// rolling resistance, conveyor belts (tangent speed), the friction and restitution
// mixing rules, speculative contacts against thin walls, the push-out speed limit, and
// bitwise determinism. Every expectation is computed here from the physics, never from
// the engine's earlier output.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// The inclines here: 20 m long.
constexpr double incline_half_length = 10.0;

}  // namespace

// ---- 1. Box on an incline -----------------------------------------------------------

I2D_TEST(phys_soft_incline_box_static_and_sliding) {
    // Box and incline both have friction mu = 0.5, mixed by the geometric mean to
    // sqrt(0.5 x 0.5) = 0.5; atan(0.5) = 26.57 degrees. A unit box set down at rest on the
    // incline (turned with it, just touching) holds below that angle: after 0.5 s to
    // settle it moves less than 1 mm in the next 2 s. Above it the box slides at
    // a = g (sin t - mu cos t), measured from its speed along the incline at 0.25 s and
    // 1.25 s, within 3 %. (tan t < 1 at every angle, so the box never tips.) Sleep is off so
    // that holding is the friction's work, not a sleeping body's.
    const double mu = 0.5;
    const double critical = std::atan(mu);
    const double holding[] = {degrees(10), degrees(20), degrees(25)};
    const double sliding[] = {degrees(30), degrees(35), degrees(40)};
    char what[96];
    for (double theta : holding) {
        const int before = i2d_check_failures;
        I2D_REQUIRE(theta < critical);
        Scene scene(Scene::no_sleep_def());
        const Slope in{theta, incline_half_length};
        I2D_REQUIRE(!I2D_IS_NULL(scene.slope(in, with_friction(float(mu)))));
        i2d_body_id box =
            scene.turned_box(I2D_BODY_DYNAMIC, in.at(3.0, 0.5), theta, 0.5f, 0.5f, with_friction(float(mu)));
        I2D_REQUIRE(!I2D_IS_NULL(box));
        I2D_REQUIRE(scene.step(steps_for(0.5)));
        const i2d_vec2 p0 = position(box);
        double drift = 0;
        for (int s = 0; s < steps_for(2.0); ++s) {
            I2D_REQUIRE(scene.step());
            drift = std::max(drift, distance(position(box), p0));
        }
        fprintf(stderr, "    incline %.0f deg (below %.2f deg): drift %.4f mm over 2 s from t = 0.5 s\n",
                theta * 180 / pi, critical * 180 / pi, drift * 1e3);
        I2D_CHECK(drift < 1e-3);
        snprintf(what, sizeof what, "box holding on %.0f deg incline", theta * 180 / pi);
        report_case(before, what);
    }
    for (double theta : sliding) {
        const int before = i2d_check_failures;
        I2D_REQUIRE(theta > critical);
        Scene scene(Scene::no_sleep_def());
        const Slope in{theta, incline_half_length};
        I2D_REQUIRE(!I2D_IS_NULL(scene.slope(in, with_friction(float(mu)))));
        i2d_body_id box =
            scene.turned_box(I2D_BODY_DYNAMIC, in.at(6.0, 0.5), theta, 0.5f, 0.5f, with_friction(float(mu)));
        I2D_REQUIRE(!I2D_IS_NULL(box));
        const int s1 = steps_for(0.25), s2 = steps_for(1.25);
        I2D_REQUIRE(scene.step(s1));
        const double v1 = -in.along(velocity(box));  // downhill speed
        I2D_REQUIRE(scene.step(s2 - s1));
        const double v2 = -in.along(velocity(box));
        const double a = (v2 - v1) / ((s2 - s1) * double(time_step));
        const double expected = g * (std::sin(theta) - mu * std::cos(theta));
        fprintf(stderr, "    incline %.0f deg (above %.2f deg): slides at %.4f m/s^2, expected %.4f (%+.2f %%)\n",
                theta * 180 / pi, critical * 180 / pi, a, expected, 100 * (a / expected - 1));
        I2D_CHECK_NEAR(a, expected, 0.03 * expected);
        // Still on the incline, not lifted off it or sunk into it.
        I2D_CHECK_NEAR(in.above(position(box)), 0.5, 0.01);
        snprintf(what, sizeof what, "box sliding on %.0f deg incline", theta * 180 / pi);
        report_case(before, what);
    }
}

// ---- 2. Disc rolling down an incline ----------------------------------------------------

I2D_TEST(phys_soft_disc_rolls_down_incline) {
    // A uniform disc (I = m r^2 / 2) rolling without slipping down an incline accelerates
    // at a = g sin t / (1 + I / (m r^2)) = 2/3 g sin t. Rolling needs friction
    // F = m a / 2 = m g sin t / 3 <= mu m g cos t, i.e. mu >= tan t / 3 (0.19 at 30
    // degrees); mu = 0.6 here. Measured from the speed along the incline at 0.25 s and
    // 1.25 s, within 2 %; the contact point does not slip: w r = -(v . t) within 2 %.
    const double r = 0.5, mu = 0.6;
    for (double theta : {degrees(15), degrees(30)}) {
        const int before = i2d_check_failures;
        Scene scene(Scene::no_sleep_def());
        const Slope in{theta, incline_half_length};
        I2D_REQUIRE(std::tan(theta) / 3 < mu);
        I2D_REQUIRE(!I2D_IS_NULL(scene.slope(in, with_friction(float(mu)))));
        i2d_body_id disc = scene.dynamic_circle(in.at(6.0, r), float(r), with_friction(float(mu)));
        I2D_REQUIRE(!I2D_IS_NULL(disc));
        const int s1 = steps_for(0.25), s2 = steps_for(1.25);
        I2D_REQUIRE(scene.step(s1));
        const double v1 = -in.along(velocity(disc));
        I2D_REQUIRE(scene.step(s2 - s1));
        const double v2 = -in.along(velocity(disc));
        const double w2 = i2d_body_get_angular_velocity(disc);
        const double a = (v2 - v1) / ((s2 - s1) * double(time_step));
        const double expected = 2.0 / 3.0 * g * std::sin(theta);
        fprintf(stderr,
                "    disc rolling down %.0f deg incline: a %.4f m/s^2, expected %.4f (%+.2f %%); at 1.25 s v %.4f m/s, "
                "w r %.4f m/s\n",
                theta * 180 / pi, a, expected, 100 * (a / expected - 1), v2, w2 * r);
        I2D_CHECK_NEAR(a, expected, 0.02 * expected);
        // Downhill is -t; rolling that way turns the disc counter-clockwise: w r = v2.
        I2D_CHECK_NEAR(w2 * r, v2, 0.02 * v2);
        char what[64];
        snprintf(what, sizeof what, "disc on %.0f deg incline", theta * 180 / pi);
        report_case(before, what);
    }
}

// ---- 3. Pyramid -------------------------------------------------------------------------

namespace {

struct PyramidResult {
    int count = 0;
    double top_drift = 0;   // largest distance of the top box from where it was built, m
    double any_drift = 0;   // the same for any box (sampled every 10 steps), m
    double asleep_at = -1;  // when the awake count first reached 0, s
    int awake_at_5 = -1, awake_counter_at_5 = -1, islands_at_5 = -1;
    double end_slide = 0;     // at the end: largest sideways distance of any box from where it was built, m
    double mean_slide = 0;    // the same averaged over the boxes, m
    double end_top_drop = 0;  // how far the top box ends below where it was built, m
    double end_top_slide = 0;  // how far sideways the top box ends from where it was built, m
    double checkpoint_mean_slide = 0;  // mean_slide at the checkpoint, m
};

double mean_sideways_slide(const std::vector<i2d_body_id>& boxes, const std::vector<i2d_vec2>& start) {
    double sum = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        sum += std::fabs(double(position(boxes[i]).x) - start[i].x);
    }
    return sum / double(boxes.size());
}

// `rows` rows of unit boxes, each row centred on the one below and touching its
// neighbours, on static ground, run for `seconds` (with the mean sideways slide also
// taken at `checkpoint` seconds).
bool run_pyramid(const i2d_world_def& def, PyramidResult* out, int rows = 20, double seconds = 10.0,
                 double checkpoint = 0.0) {
    Scene scene(def);
    if (I2D_IS_NULL(scene.ground(0.0f, 40.0f))) {
        return false;
    }
    const std::vector<i2d_body_id> boxes = scene.pyramid(0.0f, rows);
    if (boxes.empty()) {
        return false;
    }
    std::vector<i2d_vec2> start;  // where each box was built
    for (const i2d_body_id b : boxes) {
        start.push_back(position(b));
    }
    out->count = int(boxes.size());
    const i2d_body_id top = boxes.back();
    for (int s = 1; s <= steps_for(seconds); ++s) {
        if (!scene.step()) {
            return false;
        }
        out->top_drift = std::max(out->top_drift, distance(position(top), start.back()));
        if (s % 10 == 0) {
            for (int i = 0; i < out->count; ++i) {
                out->any_drift = std::max(out->any_drift, distance(position(boxes[i]), start[i]));
            }
        }
        const i2d_world_counters c = i2d_world_get_counters(scene.world);
        if (out->asleep_at < 0 && c.awake_body_count == 0) {
            out->asleep_at = s * double(time_step);
        }
        if (s == steps_for(checkpoint)) {
            out->checkpoint_mean_slide = mean_sideways_slide(boxes, start);
        }
        if (s == steps_for(5.0)) {
            out->awake_at_5 = count_awake(boxes);
            out->awake_counter_at_5 = c.awake_body_count;
            out->islands_at_5 = c.sleeping_island_count;
        }
    }
    for (int i = 0; i < out->count; ++i) {
        out->end_slide = std::max(out->end_slide, std::fabs(double(position(boxes[i]).x) - start[i].x));
    }
    out->mean_slide = mean_sideways_slide(boxes, start);
    out->end_top_drop = double(start.back().y) - position(top).y;
    out->end_top_slide = double(position(top).x) - start.back().x;
    return true;
}

}  // namespace

I2D_TEST(phys_soft_pyramid_20_rows_stands_and_sleeps) {
    // 20 rows of unit boxes (210 in all), each row centred on the one below and touching
    // its neighbours, on static ground, default world (sleep on). The pyramid stands for
    // 10 s: the top box moves less than 2 cm from where it was built. Every box is asleep
    // by 5 s (is_awake false for each and the counters' awake_body_count 0) and they
    // sleep as at least one island.
    PyramidResult r;
    I2D_REQUIRE(run_pyramid(i2d_default_world_def(), &r));
    I2D_REQUIRE(r.count == 210);
    fprintf(stderr,
            "    pyramid of 20 rows (%d boxes), 10 s: top drift %.3f cm, largest drift of any box %.3f cm; all asleep "
            "at %.3f s; at 5 s %d awake (counter %d), %d sleeping islands\n",
            r.count, r.top_drift * 100, r.any_drift * 100, r.asleep_at, r.awake_at_5, r.awake_counter_at_5,
            r.islands_at_5);
    I2D_CHECK(r.top_drift < 0.02);
    I2D_CHECK(r.awake_at_5 == 0);
    I2D_CHECK(r.awake_counter_at_5 == 0);
    I2D_CHECK(r.islands_at_5 >= 1);
    I2D_CHECK(r.asleep_at > 0 && r.asleep_at <= 5.0);
}

I2D_TEST(phys_soft_pyramid_20_rows_stands_without_sleep) {
    // The same pyramid with sleep off, so that the solver, not sleeping, holds it for
    // all of the 10 s: the top box still moves less than 2 cm, and nothing sleeps.
    PyramidResult r;
    I2D_REQUIRE(run_pyramid(Scene::no_sleep_def(), &r));
    I2D_REQUIRE(r.count == 210);
    fprintf(stderr, "    pyramid of 20 rows, sleep off, 10 s: top drift %.3f cm, largest drift of any box %.3f cm; %d awake at 5 s\n",
            r.top_drift * 100, r.any_drift * 100, r.awake_at_5);
    I2D_CHECK(r.top_drift < 0.02);
    I2D_CHECK(r.awake_at_5 == 210);
}

I2D_TEST(phys_long_soft_pyramid_70_rows_does_not_slide_apart) {
    // 70 rows (2485 boxes), sleep off, 5 s. The soft contacts sag under the load (the
    // top ends about 15 cm low, the sum of load / (mass omega^2) down the pile), but no
    // box may leave its column: at the end every box is within 10 cm of where it was
    // built sideways, and 4.5 cm on average. Solved in creation order instead of by
    // graph colour, boxes slid up to 11.1 cm (4.8 cm on average), and the benchmark's
    // 100-row pyramid slid apart.
    PyramidResult r;
    I2D_REQUIRE(run_pyramid(Scene::no_sleep_def(), &r, 70, 5.0));
    I2D_REQUIRE(r.count == 2485);
    fprintf(stderr,
            "    pyramid of 70 rows, sleep off, 5 s: largest sideways slide %.3f cm, mean %.3f cm; top ends %.3f cm "
            "low\n",
            r.end_slide * 100, r.mean_slide * 100, r.end_top_drop * 100);
    I2D_CHECK(r.end_slide < 0.10);
    I2D_CHECK(r.mean_slide < 0.045);
    I2D_CHECK(r.end_top_drop > 0.0 && r.end_top_drop < 0.25);
}

I2D_TEST(phys_long_soft_pyramid_70_rows_stops_creeping) {
    // 70 rows (2485 boxes), sleep off, default settings: once settled the pile must stop
    // moving sideways. The boxes' mean sideways distance from where they were built may
    // not grow from step 500 to step 2000 (within half a millimetre of rounding), and
    // stays under 2 cm; the top box stays within 1 cm of its column. Before manifolds
    // were recycled, friction pulled back each substep's slip and the step ended with a
    // second relax sweep, the mean grew from 3.1 to 3.5 cm over those steps and the top
    // box ended 2.3 cm aside (and in the benchmark's 100-row pyramid from 15 to 26 cm).
    PyramidResult r;
    I2D_REQUIRE(run_pyramid(Scene::no_sleep_def(), &r, 70, 2000 * double(time_step), 500 * double(time_step)));
    I2D_REQUIRE(r.count == 2485);
    fprintf(stderr,
            "    pyramid of 70 rows, sleep off: mean sideways slide %.3f cm at step 500, %.3f cm at step 2000; top "
            "box %.3f cm sideways, %.3f cm low\n",
            r.checkpoint_mean_slide * 100, r.mean_slide * 100, r.end_top_slide * 100, r.end_top_drop * 100);
    I2D_CHECK(r.mean_slide <= r.checkpoint_mean_slide + 0.0005);
    I2D_CHECK(r.mean_slide < 0.02);
    I2D_CHECK(std::fabs(r.end_top_slide) < 0.01);
}

// ---- 4. Stacks --------------------------------------------------------------------------

namespace {

struct StackResult {
    double top_drift = 0;  // largest distance of the top box from where it was built
    double x_drift = 0;    // largest |x| of any box (built at x = 0)
    double turn = 0;       // largest |angle| of any box
    double end_sink = 0;   // how far below where it was built the top box ends, m
    double end_speed = 0;  // fastest box at the end, m/s
};

// A stack of unit boxes of the given densities (bottom first), built touching on static
// ground at x = 0, run for `seconds` with sleep off.
bool run_stack(const std::vector<float>& densities, double seconds, StackResult* out) {
    Scene scene(Scene::no_sleep_def());
    if (I2D_IS_NULL(scene.ground(0.0f))) {
        return false;
    }
    std::vector<i2d_body_id> boxes;
    for (size_t i = 0; i < densities.size(); ++i) {
        const i2d_body_id b = scene.dynamic_box(i2d_vec2{0, float(0.5 + double(i))}, 0.5f, 0.5f,
                                                with_density(densities[i]));
        if (I2D_IS_NULL(b)) {
            return false;
        }
        boxes.push_back(b);
    }
    const i2d_vec2 top0 = position(boxes.back());
    for (int s = 0; s < steps_for(seconds); ++s) {
        if (!scene.step()) {
            return false;
        }
        out->top_drift = std::max(out->top_drift, distance(position(boxes.back()), top0));
        for (i2d_body_id b : boxes) {
            out->x_drift = std::max(out->x_drift, std::fabs(double(position(b).x)));
            out->turn = std::max(out->turn, std::fabs(angle_of(b)));
        }
    }
    out->end_sink = double(top0.y) - position(boxes.back()).y;
    for (i2d_body_id b : boxes) {
        out->end_speed = std::max(out->end_speed, speed(velocity(b)));
    }
    return true;
}

// How far the top of a stack of unit boxes settles below where it was built, from the
// contact compliance the world def documents: a contact under a load L (the weight of
// everything above it) settles at L / (m_eff w^2) of overlap, w = 2 pi hertz with the
// hertz capped at a quarter of the substep rate, and doubled against static bodies; m_eff
// is the contact's effective mass along its normal: the reduced mass m_a m_b / (m_a + m_b)
// between two boxes (a symmetric load does not turn them), the box's own mass on the
// ground. The top sinks by the sum over the contacts.
double compliance_sink(const std::vector<float>& densities) {
    const i2d_world_def def = i2d_default_world_def();
    const double hertz = std::min(double(def.contact_hertz), 0.25 * substeps / double(time_step));
    const double w = 2 * pi * hertz, w_static = 2 * w;
    double sink = 0;
    for (size_t k = 0; k < densities.size(); ++k) {
        double above = 0;  // unit boxes: mass = density
        for (size_t i = k; i < densities.size(); ++i) {
            above += densities[i];
        }
        const double load = above * g;
        if (k == 0) {
            sink += load / (densities[0] * w_static * w_static);
        } else {
            const double ma = densities[k - 1], mb = densities[k];
            sink += load / (ma * mb / (ma + mb) * w * w);
        }
    }
    return sink;
}

// absolute_drift: the "the top moves less than 2 cm" from where it was built;
// otherwise less than 2 cm beyond where the documented compliance puts it.
void check_stack(const char* name, const std::vector<float>& densities, bool absolute_drift) {
    const int before = i2d_check_failures;
    StackResult r;
    I2D_REQUIRE(run_stack(densities, 10.0, &r));
    const double expected_sink = compliance_sink(densities);
    fprintf(stderr,
            "    %s, 10 s: top drift %.3f cm (most), ends %.3f cm low (compliance closed form %.3f cm, %+.1f %%); "
            "largest |x| %.3g cm, largest turn %.3g rad, end speed %.2g m/s\n",
            name, r.top_drift * 100, r.end_sink * 100, expected_sink * 100, 100 * (r.end_sink / expected_sink - 1),
            r.x_drift * 100, r.turn, r.end_speed);
    // Stands: the top moves less than 2 cm; nothing leans or slides sideways (toppling
    // moves boxes by tens of cm and turns them by radians); it ends at rest, sunk by
    // what the contacts' documented compliance gives (within 10 % + 0.2 mm).
    I2D_CHECK(r.top_drift < 0.02 + (absolute_drift ? 0.0 : expected_sink));
    I2D_CHECK(r.x_drift < 0.01);
    I2D_CHECK(r.turn < 0.02);
    I2D_CHECK(r.end_speed < 1e-3);
    I2D_CHECK_NEAR(r.end_sink, expected_sink, 0.1 * expected_sink + 2e-4);
    report_case(before, name);
}

}  // namespace

I2D_TEST(phys_soft_stack_of_10_stands) {
    // Ten unit boxes stacked on the ground, sleep off: the stack stands for 10 s, its
    // top moving less than 2 cm (it sinks 0.65 cm by the contacts' compliance).
    check_stack("stack of 10", std::vector<float>(10, 1.0f), true);
}

I2D_TEST(phys_soft_stack_mass_ratio_stands) {
    // Mass ratio 1:10, sleep off: ten boxes of alternating density 1 and 10 (bottom 1);
    // and a box of density 10 on top of five of density 1. Both stand for 10 s: no lean,
    // at rest at the end, sunk by the documented compliance, and moving less than 2 cm
    // beyond that. (The contacts' compliance alone sinks the alternating stack, 55 kg, by
    // 2.19 cm at the default 60 Hz: more than the 2 cm the uniform stack is held to. The
    // stack with the heavy top sinks 0.81 cm.)
    std::vector<float> alternating;
    for (int i = 0; i < 10; ++i) {
        alternating.push_back(i % 2 == 0 ? 1.0f : 10.0f);
    }
    check_stack("stack of 10, densities 1 and 10 alternating", alternating, false);
    check_stack("heavy box (density 10) on five of density 1", std::vector<float>{1, 1, 1, 1, 1, 10}, false);
}

// ---- 5. Newton's cradle -------------------------------------------------------------------

namespace {

// Five balls of radius 0.5 in a row, `gap` apart (the first 0.5 m further back), the
// first moving at v; returns the x velocities after 2 s.
bool run_cradle(double v, double gap, double vx[5], float restitution = 1.0f) {
    const double r = 0.5;
    Scene scene(Scene::no_sleep_def(Scene::zero_gravity_def()));  // a slow ball put to sleep would lose its momentum
    i2d_body_id balls[5];
    for (int i = 0; i < 5; ++i) {
        const double x = i * (2 * r + gap) - (i == 0 ? 0.5 : 0.0);
        const i2d_vec2 vel{i == 0 ? float(v) : 0.0f, 0};
        balls[i] = scene.dynamic_circle(i2d_vec2{float(x), 0}, float(r), material(0.0f, restitution), vel);
        if (I2D_IS_NULL(balls[i])) {
            return false;
        }
    }
    if (!scene.step(steps_for(2.0))) {
        return false;
    }
    for (int i = 0; i < 5; ++i) {
        vx[i] = velocity(balls[i]).x;
    }
    return true;
}

}  // namespace

I2D_TEST(phys_soft_newtons_cradle) {
    // Five equal balls (radius 0.5) in a row, restitution 1, no friction, no gravity. The
    // first hits the others at v = 2 m/s. Each collision of equal masses with e = 1
    // swaps their velocities, so the last ball leaves at v (within 2 %) and the first
    // ends at rest (|v| < 2 % of v), as do the three in the middle.
    // The balls stand 5 cm apart: a gap small beside the balls but more than the half of
    // v dt a struck ball can cover in the step it is struck, so each collision is a
    // two-body one. (With exactly touching balls a rigid-body model has no unique answer:
    // simultaneous impulses share the momentum instead of passing it on. That case is
    // printed, not checked.)
    const double v = 2.0, gap = 0.05;
    double vx[5];
    I2D_REQUIRE(run_cradle(v, gap, vx));
    fprintf(stderr,
            "    Newton's cradle, v = %.1f m/s, gap %.0f cm: final speeds %.4f %.4f %.4f %.4f %.4f m/s (last %+.2f %%)\n",
            v, gap * 100, vx[0], vx[1], vx[2], vx[3], vx[4], 100 * (vx[4] / v - 1));
    I2D_CHECK_NEAR(vx[4], v, 0.02 * v);
    I2D_CHECK_NEAR(vx[0], 0.0, 0.02 * v);
    for (int i = 1; i < 4; ++i) {
        I2D_CHECK_NEAR(vx[i], 0.0, 0.02 * v);
    }
    double touching[5];
    I2D_REQUIRE(run_cradle(v, 0.0, touching));
    fprintf(stderr, "    (not checked) touching balls: final speeds %.4f %.4f %.4f %.4f %.4f m/s\n", touching[0],
            touching[1], touching[2], touching[3], touching[4]);
}

I2D_TEST(phys_soft_touching_balls_create_no_energy) {
    // Rows of five equal balls, touching or nearly so (gaps 0, 1 mm, 1 cm), struck at
    // 2 m/s as in the cradle, without sleep. Whatever a solver does with simultaneous
    // contacts, they only push pairs apart with equal and opposite impulses, and with
    // restitution e <= 1 no collision can add energy: momentum stays m v (within 0.1 %)
    // and the kinetic energy ends no higher than it started (within 1 %), for e = 1
    // and e = 0.5.
    const double v = 2.0;
    for (float e : {1.0f, 0.5f}) {
        for (double gap : {0.0, 0.001, 0.01}) {
            const int before = i2d_check_failures;
            double vx[5];
            I2D_REQUIRE(run_cradle(v, gap, vx, e));
            double p = 0, ke = 0;
            for (double u : vx) {
                p += u;
                ke += 0.5 * u * u;
            }
            const double ke0 = 0.5 * v * v;  // per unit mass: the balls are equal
            fprintf(stderr,
                    "    row of balls, e = %.1f, gap %.0f mm: speeds %.3f %.3f %.3f %.3f %.3f m/s; momentum %.4f of "
                    "%.1f; energy x %.3f\n",
                    double(e), gap * 1e3, vx[0], vx[1], vx[2], vx[3], vx[4], p, v, ke / ke0);
            I2D_CHECK_NEAR(p, v, 1e-3 * v);
            I2D_CHECK(ke <= 1.01 * ke0);
            char what[64];
            snprintf(what, sizeof what, "e = %.1f, gap %.0f mm", double(e), gap * 1e3);
            report_case(before, what);
        }
    }
}

// ---- 6. Elastic bouncing ball -----------------------------------------------------------

I2D_TEST(phys_soft_elastic_ball_keeps_energy) {
    // A ball (radius 0.25) dropped from 2 m (its bottom above the ground's top) onto the
    // ground, restitution 1 on both (the default minimum rule gives 1), no friction, sleep
    // off. Its energy per unit mass, v^2 / 2 + g (y - r), is g h = 20 J/kg at the start;
    // at every apex of the next 60 s it must be within 1 % of that. (At an apex the speed
    // is at most g dt, so sampling once per step costs < 0.1 %.)
    const double r = 0.25, h = 2.0;
    Scene scene(Scene::no_sleep_def());
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, material(0.0f, 1.0f))));
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, float(h + r)}, float(r), material(0.0f, 1.0f));
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    const double e0 = g * h;
    auto energy = [&]() {
        const i2d_vec2 v = velocity(ball);
        return 0.5 * (double(v.x) * v.x + double(v.y) * v.y) + g * (double(position(ball).y) - r);
    };
    int apexes = 0;
    double worst = 0, lo = INFINITY, hi = -INFINITY;
    double prev_vy = 0;
    for (int s = 1; s <= steps_for(60.0); ++s) {
        I2D_REQUIRE(scene.step());
        const double vy = velocity(ball).y;
        if (prev_vy > 0 && vy <= 0) {  // passed an apex during this step
            const double e = energy();
            ++apexes;
            lo = std::min(lo, e);
            hi = std::max(hi, e);
            worst = std::max(worst, std::fabs(e / e0 - 1));
        }
        prev_vy = vy;
    }
    // Period 2 sqrt(2 h / g) = 1.26 s: 47 apexes in 60 s.
    const int expected_apexes = int(60.0 / (2 * std::sqrt(2 * h / g)));
    fprintf(stderr,
            "    elastic ball, 60 s: %d apexes (expected %d); energy at the apexes %.4f .. %.4f J/kg of %.4f "
            "(worst %.3f %%)\n",
            apexes, expected_apexes, lo, hi, e0, 100 * worst);
    I2D_CHECK(apexes >= expected_apexes - 1);
    I2D_CHECK(worst < 0.01);
}

namespace {

// The soft step's shortfall on a ball bouncing off a plank that rests on the ground, as a
// share of the drop height: measured 0.18 (see the first test below).
constexpr double rebound_shortfall = 0.2;

struct Rebound {
    bool stepped = false;
    double apex = -INFINITY;   // the ball's lowest point at its first apex after bouncing, above `top`, m
    double plank_moved = 0.0;  // the plank's largest vertical move meanwhile, m
};

// Steps for at most 2 s until the ball (radius r) passes its first apex after bouncing.
Rebound follow_rebound(Scene& scene, i2d_body_id ball, double r, i2d_body_id plank, double top) {
    Rebound out;
    const double plank_y = position(plank).y;
    double prev_vy = 0;
    bool bounced = false;
    for (int s = 1; s <= steps_for(2.0) && out.apex == -INFINITY; ++s) {
        if (!scene.step()) {
            return out;
        }
        const double vy = velocity(ball).y;
        bounced = bounced || vy > 0;
        if (bounced && prev_vy > 0 && vy <= 0) {
            out.apex = position(ball).y - r - top;
        }
        prev_vy = vy;
        out.plank_moved = std::max(out.plank_moved, std::fabs(position(plank).y - plank_y));
    }
    out.stepped = true;
    return out;
}

}  // namespace

I2D_TEST(phys_soft_elastic_ball_on_a_resting_box_bounces_back_to_its_height) {
    // An elastic ball (radius 0.25, density 1) dropped from 1 m onto an elastic plank
    // (1 m x 0.2 m, density 1: about the ball's mass) that rests on an inelastic ground,
    // no friction, sleep off. The ground holds the plank, so in the rigid model the plank
    // takes none of the bounce: the ball comes back up to 1 m and the plank stays put.
    // That needs the restitution pass to hold the plank on the ground although that
    // contact does not bounce itself; without it the ball rose to 0.23 m. The soft step
    // falls short of the rigid answer here: the ball leaves at 91 % of its impact speed
    // (0.82 m; 92 % from 20 m, and not from the ground's stiffness or the number of
    // restitution iterations), an open fidelity gap that the bound below allows.
    const double r = 0.25, h = 1.0, plank_half_height = 0.1;
    Scene scene(Scene::no_sleep_def());
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, material(0.0f, 0.0f))));
    const i2d_body_id plank =
        scene.dynamic_box(i2d_vec2{0, float(plank_half_height)}, 0.5f, float(plank_half_height), material(0.0f, 1.0f));
    I2D_REQUIRE(!I2D_IS_NULL(plank));
    I2D_REQUIRE(scene.step(steps_for(0.5)));  // the plank settles before the drop
    const double top = 2 * plank_half_height;
    const i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, float(top + h + r)}, float(r), material(0.0f, 1.0f));
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    const Rebound rebound = follow_rebound(scene, ball, r, plank, top);
    I2D_REQUIRE(rebound.stepped);
    const double apex = rebound.apex, plank_moved = rebound.plank_moved;
    fprintf(stderr, "    ball back up to %.4f m of %.1f m; plank moved at most %.2f mm\n", apex, h,
            1e3 * plank_moved);
    I2D_CHECK(apex > (1 - rebound_shortfall) * h && apex < 1.02 * h);
    I2D_CHECK(plank_moved < 0.005);
}

I2D_TEST(phys_soft_ball_made_elastic_at_rest_bounces_off_a_resting_plank) {
    // The test above, with the materials changed while everything rests: a ball
    // (radius 0.25) lies on a plank (1 m x 0.2 m) on an inelastic ground, all inelastic
    // and settled; then the ball and the plank are made elastic, and the ball is given
    // 4.47 m/s downwards (the speed of a 1 m fall) while it touches the plank. Nothing
    // about the contacts' points changes, so this checks that changing a material alone
    // lets the restitution pass hold the plank on the ground: the ball rises to 0.89 m
    // of 1 m (0.31 m when the colouring kept its stale note that nothing was elastic),
    // and the plank stays put.
    const double r = 0.25, h = 1.0, plank_half_height = 0.1, top = 2 * plank_half_height;
    Scene scene(Scene::no_sleep_def());
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, material(0.0f, 0.0f))));
    const i2d_body_id plank =
        scene.dynamic_box(i2d_vec2{0, float(plank_half_height)}, 0.5f, float(plank_half_height), material(0.0f, 0.0f));
    const i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, float(top + r)}, float(r), material(0.0f, 0.0f));
    I2D_REQUIRE(!I2D_IS_NULL(plank) && !I2D_IS_NULL(ball));
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    for (const i2d_body_id body : {plank, ball}) {
        const i2d_shape_id shape = only_shape(body);
        I2D_REQUIRE(!I2D_IS_NULL(shape));
        I2D_REQUIRE(i2d_shape_set_restitution(shape, 1.0f) == I2D_OK);
    }
    I2D_REQUIRE(i2d_body_set_linear_velocity(ball, i2d_vec2{0, float(-std::sqrt(2 * g * h))}) == I2D_OK);
    const Rebound rebound = follow_rebound(scene, ball, r, plank, top);
    I2D_REQUIRE(rebound.stepped);
    const double apex = rebound.apex, plank_moved = rebound.plank_moved;
    fprintf(stderr, "    ball up to %.4f m of %.1f m; plank moved at most %.2f mm\n", apex, h, 1e3 * plank_moved);
    I2D_CHECK(apex > (1 - rebound_shortfall) * h && apex < 1.02 * h);
    I2D_CHECK(plank_moved < 0.005);
}

// ---- 7. Rolling resistance -----------------------------------------------------------------

namespace {

// A disc of radius r rolling on flat ground at v0 with matching spin -v0 / r; returns
// its speeds at t1 and t2.
bool roll_disc(float rolling_resistance, double v0, double t1, double t2, double* v1, double* v2, double* w2) {
    const double r = 0.5;
    Scene scene(Scene::no_sleep_def());
    if (I2D_IS_NULL(scene.ground(0.0f, 50.0f))) {
        return false;
    }
    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{-40, float(r)}, i2d_vec2{float(v0), 0});
    def.angular_velocity = float(-v0 / r);
    i2d_body_id disc = i2d_body_create(scene.world, &def);
    if (I2D_IS_NULL(disc)) {
        return false;
    }
    i2d_shape_def sd = shape_def(with_friction(0.6f));
    sd.rolling_resistance = rolling_resistance;
    i2d_circle c{i2d_vec2{0, 0}, float(r)};
    if (I2D_IS_NULL(i2d_shape_create_circle(disc, &sd, &c))) {
        fprintf(stderr, "    circle creation failed: %s\n", i2d_last_error_message());
        return false;
    }
    const int s1 = steps_for(t1), s2 = steps_for(t2);
    if (!scene.step(s1)) {
        return false;
    }
    *v1 = velocity(disc).x;
    if (!scene.step(s2 - s1)) {
        return false;
    }
    *v2 = velocity(disc).x;
    *w2 = i2d_body_get_angular_velocity(disc);
    return true;
}

}  // namespace

I2D_TEST(phys_soft_rolling_resistance) {
    // Rolling resistance c on a disc of radius r resists the roll with a torque of
    // c r N. With friction F at the contact keeping it rolling (v = -w r):
    //   m a = F,  I a / r = -(F r + c r m g)  =>  a = -c g / (1 + I / (m r^2)) = -c g / 1.5
    // for a solid disc; friction needs only mu >= c / 1.5 (mu = 0.6, c = 0.2). From
    // v0 = 4 m/s the deceleration, measured between 0.25 s and 1.75 s, is within 3 %
    // of c g / 1.5; it keeps rolling (w r = -v within 2 %). With c = 0 nothing slows it:
    // it loses less than 1 % of its speed in 2 s.
    const double c = 0.2, v0 = 4.0, r = 0.5;
    double v1, v2, w2;
    I2D_REQUIRE(roll_disc(float(c), v0, 0.25, 1.75, &v1, &v2, &w2));
    const double a = (v1 - v2) / 1.5;
    const double expected = c * g / 1.5;
    fprintf(stderr, "    rolling resistance %.2f: deceleration %.4f m/s^2, expected %.4f (%+.2f %%); w r %.4f vs v %.4f\n",
            c, a, expected, 100 * (a / expected - 1), w2 * r, v2);
    I2D_CHECK_NEAR(a, expected, 0.03 * expected);
    I2D_CHECK_NEAR(-w2 * r, v2, 0.02 * v2);

    double u1, u2, uw;
    I2D_REQUIRE(roll_disc(0.0f, v0, 0.25, 2.0, &u1, &u2, &uw));
    fprintf(stderr, "    no rolling resistance: speed %.5f m/s after 2 s from %.1f (loss %.3f %%)\n", u2, v0,
            100 * (1 - u2 / v0));
    I2D_CHECK(u2 > 0.99 * v0);
    I2D_CHECK(u2 < v0 * 1.001);
}

// ---- 8. Tangent speed: a conveyor belt ------------------------------------------------------

namespace {

// A unit box resting on a static belt of tangent speed s: returns its x velocity at
// 0.1 s, 0.3 s and 1.5 s. belt_first chooses which body is created first (so that
// the belt is shape A of the contact in one order and B in the other, whatever the
// engine's ordering is).
bool ride_belt(float belt_speed, bool belt_first, double* va, double* vb, double* vend, double* y_end) {
    Scene scene(Scene::no_sleep_def());
    i2d_body_id box{0}, belt{0};
    auto make_belt = [&]() {
        const i2d_body_def def = body_def(I2D_BODY_STATIC, i2d_vec2{0, -0.5f});
        i2d_body_id b = i2d_body_create(scene.world, &def);
        if (I2D_IS_NULL(b)) {
            return b;
        }
        i2d_shape_def sd = shape_def(with_friction(0.5f));
        sd.tangent_speed = belt_speed;
        if (I2D_IS_NULL(i2d_shape_create_box(b, &sd, 50.0f, 0.5f))) {
            fprintf(stderr, "    belt creation failed: %s\n", i2d_last_error_message());
            return I2D_NULL_BODY_ID;
        }
        return b;
    };
    if (belt_first) {
        belt = make_belt();
        box = scene.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f, with_friction(0.5f));
    } else {
        box = scene.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f, with_friction(0.5f));
        belt = make_belt();
    }
    if (I2D_IS_NULL(box) || I2D_IS_NULL(belt)) {
        return false;
    }
    const int sa = steps_for(0.1), sb = steps_for(0.3), se = steps_for(1.5);
    if (!scene.step(sa)) {
        return false;
    }
    *va = velocity(box).x;
    if (!scene.step(sb - sa)) {
        return false;
    }
    *vb = velocity(box).x;
    if (!scene.step(se - sb)) {
        return false;
    }
    *vend = velocity(box).x;
    *y_end = position(box).y;
    return true;
}

}  // namespace

I2D_TEST(phys_soft_conveyor_tangent_speed) {
    // A static ground box whose shape has tangent speed s (counter-clockwise positive
    // along its outline: its top face runs from right to left, so the surface moves at
    // -s along x there) carries a unit box set down at rest on it. Friction mu = 0.5
    // (both shapes) drags the box at mu g = 5 m/s^2 (measured between 0.1 s and 0.3 s,
    // within 3 %) until it reaches the belt speed at s / (mu g) = 0.4 s; then it moves
    // with the belt: velocity -s within 2 % at 1.5 s. Both signs of s, and both creation
    // orders.
    const double mu = 0.5, belt = 2.0;
    for (float s : {float(belt), float(-belt)}) {
        for (bool belt_first : {true, false}) {
            const int before = i2d_check_failures;
            double va, vb, vend, y;
            I2D_REQUIRE(ride_belt(s, belt_first, &va, &vb, &vend, &y));
            const double a = (vb - va) / ((steps_for(0.3) - steps_for(0.1)) * double(time_step));
            const double expected_a = -(s > 0 ? 1 : -1) * mu * g;
            fprintf(stderr,
                    "    conveyor s = %+.1f m/s (%s first): a %.4f m/s^2 (expected %.4f, %+.2f %%), v at 1.5 s %.4f "
                    "(expected %.4f, %+.2f %%)\n",
                    s, belt_first ? "belt" : "box", a, expected_a, 100 * (a / expected_a - 1), vend, -double(s),
                    100 * (vend / -double(s) - 1));
            I2D_CHECK_NEAR(a, expected_a, 0.03 * mu * g);
            I2D_CHECK_NEAR(vend, -double(s), 0.02 * belt);
            I2D_CHECK_NEAR(y, 0.5, 0.01);
            char what[64];
            snprintf(what, sizeof what, "tangent speed %+.1f, %s created first", s, belt_first ? "belt" : "box");
            report_case(before, what);
        }
    }
}

// ---- 9. Mixing rules ---------------------------------------------------------------------

I2D_TEST(phys_soft_friction_mixing_rules) {
    // A unit box (friction 0.8) slides at 5 m/s on ground of friction 0.2. The world's
    // friction_mixing decides the contact's mu: geometric mean 0.4, minimum 0.2, maximum
    // 0.8, average 0.5, multiply 0.16. The deceleration, measured from the speed at 0.1 s
    // and at 60 % of the stopping time v0 / (mu g), is mu g within 3 %.
    const float mu_box = 0.8f, mu_ground = 0.2f;
    const double v0 = 5.0;
    struct Case {
        i2d_mixing_rule rule;
        const char* name;
        double mu;
    };
    const Case cases[] = {
        {I2D_MIX_GEOMETRIC_MEAN, "geometric mean", std::sqrt(0.8 * 0.2)},
        {I2D_MIX_MINIMUM, "minimum", 0.2},
        {I2D_MIX_MAXIMUM, "maximum", 0.8},
        {I2D_MIX_AVERAGE, "average", 0.5},
        {I2D_MIX_MULTIPLY, "multiply", 0.8 * 0.2},
    };
    I2D_CHECK(i2d_default_world_def().friction_mixing == I2D_MIX_GEOMETRIC_MEAN);
    for (const Case& c : cases) {
        const int before = i2d_check_failures;
        i2d_world_def def = Scene::no_sleep_def();
        def.friction_mixing = c.rule;
        Scene scene(def);
        I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, with_friction(mu_ground))));
        i2d_body_id box =
            scene.dynamic_box(i2d_vec2{-40, 0.5f}, 0.5f, 0.5f, with_friction(mu_box), i2d_vec2{float(v0), 0});
        I2D_REQUIRE(!I2D_IS_NULL(box));
        const double stop = v0 / (c.mu * g);
        const int s1 = steps_for(0.1), s2 = steps_for(0.6 * stop);
        I2D_REQUIRE(scene.step(s1));
        const double v1 = velocity(box).x;
        I2D_REQUIRE(scene.step(s2 - s1));
        const double v2 = velocity(box).x;
        const double a = (v1 - v2) / ((s2 - s1) * double(time_step));
        fprintf(stderr, "    friction mixing %s: deceleration %.4f m/s^2, expected %.4f (%+.2f %%)\n", c.name, a,
                c.mu * g, 100 * (a / (c.mu * g) - 1));
        I2D_CHECK_NEAR(a, c.mu * g, 0.03 * c.mu * g);
        report_case(before, c.name);
    }
}

namespace {

// Drops a ball (radius 0.25, no friction) from bottom height h onto the ground and
// returns the highest its bottom rises after the first bounce within `seconds`.
double bounce_apex(const i2d_world_def& def, float e_ball, float e_ground, double h, double seconds) {
    const double r = 0.25;
    Scene scene(def);
    i2d_body_id ground = scene.ground(0.0f, 50.0f, material(0.0f, e_ground));
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, float(h + r)}, float(r), material(0.0f, e_ball));
    if (I2D_IS_NULL(ground) || I2D_IS_NULL(ball)) {
        ++i2d_check_failures;
        return NAN;
    }
    bool bounced = false;
    double apex = 0;
    for (int s = 0; s < steps_for(seconds); ++s) {
        if (!scene.step()) {
            ++i2d_check_failures;
            return NAN;
        }
        const double vy = velocity(ball).y, y = double(position(ball).y) - r;
        if (!bounced && vy > 0 && y < 0.5 * h) {
            bounced = true;
        }
        if (bounced) {
            apex = std::max(apex, y);
        }
    }
    return apex;
}

}  // namespace

I2D_TEST(phys_soft_restitution_mixing_rules) {
    // A ball dropped from h = 2 m leaves the ground at e times its impact speed and
    // rises to e^2 h, e being the world's restitution_mixing of the ball's and the
    // ground's restitution. Apex within 5 % of e^2 h (2.5 % in e) for: maximum of
    // (0.8, 0) = 0.8, average of (1, 0.6) = 0.8, multiply (0.9, 0.9) = 0.81, geometric
    // mean of (1, 0.64) = 0.8, and the default minimum of (0.8, 1) = 0.8. The same pair
    // (0.8, 0) under the default minimum does not bounce (apex < 1 % of h).
    const double h = 2.0;
    struct Case {
        i2d_mixing_rule rule;
        const char* name;
        float ball, ground;
        double e;
    };
    const Case cases[] = {
        {I2D_MIX_MAXIMUM, "maximum", 0.8f, 0.0f, 0.8},
        {I2D_MIX_AVERAGE, "average", 1.0f, 0.6f, 0.8},
        {I2D_MIX_MULTIPLY, "multiply", 0.9f, 0.9f, 0.81},
        {I2D_MIX_GEOMETRIC_MEAN, "geometric mean", 1.0f, 0.64f, 0.8},
        {I2D_MIX_MINIMUM, "minimum", 0.8f, 1.0f, 0.8},
    };
    I2D_CHECK(i2d_default_world_def().restitution_mixing == I2D_MIX_MINIMUM);
    for (const Case& c : cases) {
        const int before = i2d_check_failures;
        i2d_world_def def = Scene::no_sleep_def();
        def.restitution_mixing = c.rule;
        const double apex = bounce_apex(def, c.ball, c.ground, h, 2.5);
        const double expected = c.e * c.e * h;
        fprintf(stderr, "    restitution mixing %s of (%.2f, %.2f): apex %.4f m, expected %.4f (%+.2f %%)\n", c.name,
                c.ball, c.ground, apex, expected, 100 * (apex / expected - 1));
        I2D_CHECK_NEAR(apex, expected, 0.05 * expected);
        report_case(before, c.name);
    }
    const double dead = bounce_apex(Scene::no_sleep_def(), 0.8f, 0.0f, h, 2.5);
    fprintf(stderr, "    restitution (0.8, 0) under the default minimum: apex %.4f m\n", dead);
    I2D_CHECK(dead < 0.01 * h);
}

// ---- 10. Speculative contacts --------------------------------------------------------------

I2D_TEST(phys_soft_speculative_no_tunnelling) {
    // A ball (radius 0.25, restitution 0) flies at 30 m/s and at 100 m/s (0.5 m and
    // 1.7 m per step, 2 to 7 diameters) without gravity at a thin static wall at x = 0:
    // a two-sided segment, and a box 2 cm thick. Its centre never reaches the wall's
    // plane: it stays on the near side (x < 0) at every step and ends against the wall,
    // its surface no more than the slop + 1 mm into it, stopped. Each case is flown from
    // ten starting points a tenth of a step's travel apart, so that every phase of the
    // last step before the wall is tried.
    const double r = 0.25;
    const double slop = i2d_default_world_def().contact_slop;
    for (double v : {30.0, 100.0}) {
        for (bool segment : {true, false}) {
            const int before = i2d_check_failures;
            double worst_x = -INFINITY, worst_end = -INFINITY, nearest_end = INFINITY, worst_speed = 0;
            int through = 0;
            for (int k = 0; k < 10; ++k) {
                Scene scene(Scene::zero_gravity_def());
                const i2d_body_def wall_def = body_def(I2D_BODY_STATIC, i2d_vec2{0, 0});
                i2d_body_id wall = i2d_body_create(scene.world, &wall_def);
                I2D_REQUIRE(!I2D_IS_NULL(wall));
                i2d_shape_def sd = shape_def(with_friction(0.6f));
                const i2d_shape_id shape =
                    segment ? i2d_shape_create_segment(wall, &sd, i2d_vec2{0, -3}, i2d_vec2{0, 3})
                            : i2d_shape_create_offset_box(wall, &sd, 0.01f, 3.0f, i2d_vec2{0.01f, 0}, i2d_make_rot(0.0f));
                I2D_REQUIRE(!I2D_IS_NULL(shape));
                // The near face is x = 0 for both.
                const double x0 = -6.0 - 0.1 * k * v * double(time_step);
                const i2d_vec2 start{float(x0), 0.1f};
                i2d_body_id ball = scene.dynamic_circle(start, float(r), with_friction(0.6f), i2d_vec2{float(v), 0});
                I2D_REQUIRE(!I2D_IS_NULL(ball));
                double max_x = -INFINITY;
                for (int s = 0; s < steps_for(1.0); ++s) {
                    I2D_REQUIRE(scene.step());
                    max_x = std::max(max_x, double(position(ball).x));
                }
                const double x_end = position(ball).x;
                through += max_x >= 0.0 ? 1 : 0;
                worst_x = std::max(worst_x, max_x);
                worst_end = std::max(worst_end, x_end);
                nearest_end = std::min(nearest_end, x_end);
                worst_speed = std::max(worst_speed, speed(velocity(ball)));
            }
            fprintf(stderr,
                    "    ball at %.0f m/s into a %s, 10 phases: %d passed through; furthest centre x %.4f m; ends at "
                    "%.4f .. %.4f m (touching at %.2f); speed after 1 s <= %.3g m/s\n",
                    v, segment ? "segment" : "2 cm box", through, worst_x, nearest_end, worst_end, -r, worst_speed);
            I2D_CHECK(through == 0);
            I2D_CHECK(worst_x < 0.0);
            I2D_CHECK(nearest_end >= -r - 0.05);       // it got there and stopped against it
            I2D_CHECK(worst_end + r <= slop + 1e-3);   // not embedded, not through
            I2D_CHECK(worst_speed < 0.05 * v);         // restitution 0: it stopped
            char what[64];
            snprintf(what, sizeof what, "%.0f m/s into a %s", v, segment ? "segment" : "2 cm box");
            report_case(before, what);
        }
    }
}

// ---- 11. Push-out speed --------------------------------------------------------------------

namespace {

struct PushOut {
    double max_rel_speed = 0;  // largest separation speed, from positions, m/s
    double max_body_speed = 0; // largest speed a body reports after a step, m/s
    double end_overlap = 0;    // overlap after 2 s, m
    double end_rel_speed = 0;  // separation speed over the last step, m/s
};

// Two unit boxes created overlapping by 0.5 m along x, no gravity.
bool push_apart(const i2d_world_def& def, PushOut* out) {
    Scene scene(def);
    i2d_body_id a = scene.dynamic_box(i2d_vec2{-0.25f, 0}, 0.5f, 0.5f);
    i2d_body_id b = scene.dynamic_box(i2d_vec2{0.25f, 0}, 0.5f, 0.5f);
    if (I2D_IS_NULL(a) || I2D_IS_NULL(b)) {
        return false;
    }
    double d = double(position(b).x) - position(a).x;
    for (int s = 0; s < steps_for(2.0); ++s) {
        if (!scene.step()) {
            return false;
        }
        const double d1 = double(position(b).x) - position(a).x;
        out->max_rel_speed = std::max(out->max_rel_speed, (d1 - d) / double(time_step));
        out->max_body_speed = std::max({out->max_body_speed, speed(velocity(a)), speed(velocity(b))});
        d = d1;
    }
    out->end_overlap = 1.0 - d;
    out->end_rel_speed = double(velocity(b).x) - velocity(a).x;
    return true;
}

}  // namespace

I2D_TEST(phys_soft_push_out_speed_limit) {
    // Two unit boxes created overlapping by 0.5 m (no gravity) are pushed apart at no
    // more than contact_push_max_speed: their separation grows by at most that times
    // the step (+ 2 %), and no body reports more than that speed. After 2 s they are
    // apart, overlapping no more than the slop + 1 mm, and the push has not left them
    // flying apart: the relax pass takes the push-out velocity back, so what remains of
    // their separation speed is under 5 % of the limit (a pushed pair that kept 0.3 m/s
    // drifts 0.6 m apart in 2 s). Default 3 m/s, then 1 m/s. And a
    // box created half into the ground (gravity on) rises no faster than the limit and
    // ends resting within the slop + 1 mm.
    const double slop = i2d_default_world_def().contact_slop;
    for (float limit : {0.0f, 1.0f}) {
        const int before = i2d_check_failures;
        i2d_world_def def = Scene::no_sleep_def(Scene::zero_gravity_def());
        if (limit > 0) {
            def.contact_push_max_speed = limit;
        }
        const double max_speed = def.contact_push_max_speed;
        PushOut p;
        I2D_REQUIRE(push_apart(def, &p));
        fprintf(stderr,
                "    overlap 0.5 m, push limit %.1f m/s: separation speed <= %.4f m/s, body speed <= %.4f m/s, "
                "overlap after 2 s %.4f m (slop %.3f), still separating at %.4f m/s\n",
                max_speed, p.max_rel_speed, p.max_body_speed, p.end_overlap, slop, p.end_rel_speed);
        I2D_CHECK(p.max_rel_speed <= 1.02 * max_speed);
        I2D_CHECK(p.max_body_speed <= 1.02 * max_speed);
        I2D_CHECK(p.end_overlap <= slop + 1e-3);
        I2D_CHECK(std::fabs(p.end_rel_speed) < 0.05 * max_speed);  // pushed apart, not flung apart
        report_case(before, limit > 0 ? "limit 1 m/s" : "default limit");
    }
    {
        const int before = i2d_check_failures;
        const i2d_world_def def = Scene::no_sleep_def();
        const double max_speed = def.contact_push_max_speed;
        Scene scene(def);
        I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
        i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f);
        I2D_REQUIRE(!I2D_IS_NULL(box));
        double y = 0, max_rise = 0;
        for (int s = 0; s < steps_for(2.0); ++s) {
            I2D_REQUIRE(scene.step());
            const double y1 = position(box).y;
            max_rise = std::max(max_rise, (y1 - y) / double(time_step));
            y = y1;
        }
        fprintf(stderr, "    box half in the ground: rises at <= %.4f m/s (limit %.1f), sinks %.4f m after 2 s\n",
                max_rise, max_speed, 0.5 - y);
        I2D_CHECK(max_rise <= 1.02 * max_speed);
        I2D_CHECK(0.5 - y <= slop + 1e-3);
        I2D_CHECK(0.5 - y >= -1e-3);
        report_case(before, "box half in the ground");
    }
}

// ---- 13. Determinism -------------------------------------------------------------------------

namespace {

// A small pyramid of turned boxes with circles dropped on it: everything the solver does
// (contacts of every kind, friction, restitution, rotation) happens in 300 steps.
void build_busy_scene(Scene& scene, std::vector<i2d_body_id>& bodies) {
    if (I2D_IS_NULL(scene.ground(0.0f, 30.0f))) {
        return;
    }
    for (int row = 0; row < 8; ++row) {
        for (int k = 0; k < 8 - row; ++k) {
            i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{float(k * 1.05 - 0.525 * (7 - row)), float(0.52 + row * 1.02)});
            def.rotation = i2d_make_rot(0.02f * float((k + row) % 5 - 2));
            bodies.push_back(scene.box(def, 0.5f, 0.5f, material(0.6f, 0.1f)));
        }
    }
    for (int i = 0; i < 6; ++i) {
        bodies.push_back(scene.dynamic_circle(i2d_vec2{float(-3 + 1.1 * i), float(11 + 0.7 * i)}, 0.3f + 0.05f * i,
                                              material(0.4f, 0.5f, 2.0f), i2d_vec2{float(0.5 * (i - 3)), 0}));
    }
}

}  // namespace

I2D_TEST(phys_soft_determinism_two_worlds) {
    // The same scene built in two worlds and stepped 300 times, alternately (so that no
    // state shared between worlds can hide), ends bitwise equal: positions, rotations,
    // linear and angular velocities of every body.
    Scene a, b;
    std::vector<i2d_body_id> ba, bb;
    build_busy_scene(a, ba);
    build_busy_scene(b, bb);
    I2D_REQUIRE(ba.size() == 42 && bb.size() == 42);
    for (size_t i = 0; i < ba.size(); ++i) {
        I2D_REQUIRE(!I2D_IS_NULL(ba[i]) && !I2D_IS_NULL(bb[i]));
    }
    for (int s = 0; s < 300; ++s) {
        I2D_REQUIRE(a.step());
        I2D_REQUIRE(b.step());
    }
    int differ = 0;
    for (size_t i = 0; i < ba.size(); ++i) {
        differ += BodyState::of(ba[i]).same_bits(BodyState::of(bb[i])) ? 0 : 1;
    }
    // The scene did something: the last circle (built at y = 14.5) fell onto the pyramid.
    const double ball_drop = 14.5 - position(ba.back()).y;
    fprintf(stderr, "    determinism, 2 worlds x 300 steps, %zu bodies: %d differ bitwise; last ball fell %.2f m\n",
            ba.size(), differ, ball_drop);
    I2D_CHECK(differ == 0);
    I2D_CHECK(ball_drop > 5.0);
}
