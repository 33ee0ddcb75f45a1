// SPDX-License-Identifier: MIT
// Impacts passed from body to body within one step (impact_chain.hpp, issue 43), against
// the closed forms of sequential rigid impacts: each impact of a chain alone, the earliest
// closing gap first. Each figure is also run with the chains off (the substeps solve the
// whole row at once) as a control that must miss it; and what takes no chain (a lone
// bounce, a resting elastic stack) must step to the same bits either way.
#include <cmath>
#include <vector>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

constexpr float ball_radius = 0.5f;

// Balls of radius 0.5 in a row along x without gravity or friction, `gap` apart, the
// first starting 0.5 m further back and moving at v; each ball's density in `densities`.
struct Row {
    std::vector<float> densities;
    double gap = 0.0, v = 0.0;
    float restitution = 1.0f;
};

// The balls' x velocities after 2 s (sleep off: a slow ball put to sleep would lose its
// momentum), with the chains on or off, and the approach speeds of the hit events the
// balls (which ask for them) reported; false if the scene failed.
bool run_row(const Row& row, bool chains, std::vector<double>& vx, std::vector<double>* hit_speeds = nullptr) {
    i2d_world_def def = Scene::no_sleep_def(Scene::zero_gravity_def());
    def.enable_impact_chains = chains;
    Scene scene(def);
    std::vector<i2d_body_id> balls;
    for (std::size_t i = 0; i < row.densities.size(); ++i) {
        const double x = double(i) * (2.0 * ball_radius + row.gap) - (i == 0 ? 0.5 : 0.0);
        const i2d_vec2 v{i == 0 ? float(row.v) : 0.0f, 0.0f};
        const Material m = material(0.0f, row.restitution, row.densities[i]);
        balls.push_back(scene.dynamic_circle(i2d_vec2{float(x), 0.0f}, ball_radius, m, v));
        if (I2D_IS_NULL(balls.back()) || i2d_shape_enable_hit_events(only_shape(balls.back()), true) != I2D_OK) {
            return false;
        }
    }
    for (int s = 0; s < steps_for(2.0); ++s) {
        if (!scene.step()) {
            return false;
        }
        const i2d_contact_events e = i2d_world_get_contact_events(scene.world);
        for (int k = 0; k < e.hit_count && hit_speeds != nullptr; ++k) {
            hit_speeds->push_back(e.hit_events[k].approach_speed);
        }
    }
    vx.clear();
    for (const i2d_body_id b : balls) {
        vx.push_back(velocity(b).x);
    }
    return true;
}

// Whether the last ball leaves at v within 2 % and the others keep under 0.1 m/s in
// total (the target).
bool cradle_passes_on(const std::vector<double>& vx, double v) {
    double others = 0.0;
    for (std::size_t i = 0; i + 1 < vx.size(); ++i) {
        others += std::fabs(vx[i]);
    }
    return std::fabs(vx.back() - v) <= 0.02 * v && others < 0.1;
}

void print_speeds(const char* what, const std::vector<double>& vx) {
    fprintf(stderr, "    %s:", what);
    for (const double u : vx) {
        fprintf(stderr, " %.4f", u);
    }
    fprintf(stderr, " m/s\n");
}

}  // namespace

I2D_TEST(phys_chain_newtons_cradle_sends_the_last_ball_off_at_the_strikes_speed) {
    // Five equal balls, restitution 1: each impact of equal masses swaps the pair's
    // velocities, so the last ball leaves at v and the rest stand still. With 2 cm gaps at
    // 3 m/s a struck ball reaches the next within the step it was struck. Each impact is
    // a hit event at v.
    struct Case {
        double gap, v;
        bool control_fails;  // the substeps alone miss it (at 5 cm, 2 m/s they do not)
    };
    for (const Case c : {Case{0.02, 3.0, true}, Case{0.05, 2.0, false}, Case{0.0, 3.0, true}}) {
        const Row row{{1, 1, 1, 1, 1}, c.gap, c.v, 1.0f};
        std::vector<double> vx, control, hits;
        I2D_REQUIRE(run_row(row, true, vx, &hits));
        I2D_REQUIRE(run_row(row, false, control));
        char what[96];
        snprintf(what, sizeof what, "cradle, %.0f cm gaps at %.0f m/s, chains", c.gap * 100, c.v);
        print_speeds(what, vx);
        snprintf(what, sizeof what, "cradle, %.0f cm gaps at %.0f m/s, control", c.gap * 100, c.v);
        print_speeds(what, control);
        I2D_CHECK(cradle_passes_on(vx, c.v));
        I2D_CHECK(cradle_passes_on(control, c.v) == !c.control_fails);
        // Each of the four impacts is a hit event at the strike's speed.
        I2D_CHECK(hits.size() == 4);
        for (const double h : hits) {
            I2D_CHECK_NEAR(h, c.v, 0.02 * c.v);
        }
    }
}

I2D_TEST(phys_chain_of_masses_one_two_four_ends_at_the_sequential_impacts_speeds) {
    // Masses 1, 2, 4 (densities, equal radii), restitution 1, 2 mm gaps, the first at v:
    // 1 hits 2, which leaves at 2/3 v while 1 goes back at -v/3; 2 hits 4, which leaves at
    // 4/9 v while 2 goes back at -2/9 v, slower than 1: no third impact. Momentum v and
    // energy v^2/2 (per unit of the first mass) are kept.
    const double v = 3.0;
    const Row row{{1, 2, 4}, 0.002, v, 1.0f};
    std::vector<double> vx, control;
    I2D_REQUIRE(run_row(row, true, vx));
    I2D_REQUIRE(run_row(row, false, control));
    print_speeds("masses 1, 2, 4, chains", vx);
    print_speeds("masses 1, 2, 4, control", control);
    const double expected[3] = {-v / 3.0, -2.0 * v / 9.0, 4.0 * v / 9.0};
    bool control_matches = true;
    for (int i = 0; i < 3; ++i) {
        I2D_CHECK_NEAR(vx[std::size_t(i)], expected[i], 0.02 * v);
        control_matches = control_matches && std::fabs(control[std::size_t(i)] - expected[i]) <= 0.02 * v;
    }
    I2D_CHECK(!control_matches);
}

I2D_TEST(phys_chain_leaves_a_lone_bounce_and_a_resting_elastic_stack_as_the_substeps_step_them) {
    // Restitution 0.8 throughout: a ball dropped on the floor bounces alone (no neighbour
    // to pass it on to), and a stack of five boxes rests (nothing approaches). Neither is a
    // chain, so the world's state hash after 3 s is the same bits with chains on and off.
    uint64_t hashes[2] = {};
    for (int chains = 0; chains < 2; ++chains) {
        i2d_world_def def = i2d_default_world_def();
        def.enable_impact_chains = chains == 1;
        Scene scene(def);
        const Material elastic = with_restitution(0.8f);
        I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, elastic)));
        I2D_REQUIRE(!I2D_IS_NULL(scene.dynamic_circle(i2d_vec2{-5.0f, 3.0f}, 0.25f, elastic)));
        for (int k = 0; k < 5; ++k) {
            I2D_REQUIRE(!I2D_IS_NULL(scene.dynamic_box(i2d_vec2{5.0f, 0.5f + float(k)}, 0.5f, 0.5f, elastic)));
        }
        I2D_REQUIRE(scene.step(steps_for(3.0)));
        hashes[chains] = i2d_world_get_state_hash(scene.world);
    }
    fprintf(stderr, "    state hash after 3 s: chains off %016llx, on %016llx\n", (unsigned long long)hashes[0],
            (unsigned long long)hashes[1]);
    I2D_CHECK(hashes[0] == hashes[1]);
}

namespace {

// What a ball of restitution 0.8 dropped 2 m onto a resting stack of five boxes of the
// same restitution did over 2 s (sleep off).
struct StackDrop {
    double worst_excess = -1e9;  // J: kinetic energy over the potential energy released
    double fastest = 0.0;        // m/s: any body's
    double impact_speed = 0.0;   // m/s: the ball's at the stack, sqrt(2 g h)
    double ball_drop_energy = 0.0;
    uint64_t hash = 0;
};

bool drop_on_elastic_stack(bool chains, StackDrop& out) {
    i2d_world_def def = Scene::no_sleep_def();
    def.enable_impact_chains = chains;
    Scene scene(def);
    const Material elastic = with_restitution(0.8f);
    if (I2D_IS_NULL(scene.ground(0.0f, 50.0f, elastic))) {
        return false;
    }
    std::vector<i2d_body_id> bodies;
    for (int k = 0; k < 5; ++k) {
        bodies.push_back(scene.dynamic_box(i2d_vec2{0.0f, 0.5f + float(k)}, 0.5f, 0.5f, elastic));
    }
    const double drop = 2.0, g = 10.0;
    bodies.push_back(scene.dynamic_circle(i2d_vec2{0.0f, 5.25f + float(drop)}, 0.25f, elastic));
    for (const i2d_body_id b : bodies) {
        if (I2D_IS_NULL(b)) {
            return false;
        }
    }
    const auto potential = [&]() {
        double e = 0.0;
        for (const i2d_body_id b : bodies) {
            e += i2d_body_get_mass(b) * g * position(b).y;
        }
        return e;
    };
    out.impact_speed = std::sqrt(2.0 * g * drop);
    out.ball_drop_energy = i2d_body_get_mass(bodies.back()) * g * drop;
    const double start = potential();
    for (int s = 0; s < steps_for(2.0); ++s) {
        if (!scene.step()) {
            return false;
        }
        double kinetic = 0.0;
        for (const i2d_body_id b : bodies) {
            kinetic += kinetic_energy(b);
            out.fastest = std::max(out.fastest, speed(velocity(b)));
        }
        out.worst_excess = std::max(out.worst_excess, kinetic - (start - potential()));
    }
    out.hash = i2d_world_get_state_hash(scene.world);
    return true;
}

}  // namespace

I2D_TEST(phys_chain_down_an_elastic_stack_gains_no_energy_and_outruns_no_impact) {
    // The ball's impact on the top box starts a chain down to the floor (the run differs
    // from the one without chains). Whatever the order, impacts push pairs apart with
    // equal and opposite impulses and none with e <= 1 adds energy: the bodies' kinetic
    // energy never exceeds the potential energy released by then (each step, with 1 % of
    // the ball's drop as slack), and nothing moves faster than the ball's impact speed.
    StackDrop chains, control;
    I2D_REQUIRE(drop_on_elastic_stack(true, chains));
    I2D_REQUIRE(drop_on_elastic_stack(false, control));
    fprintf(stderr,
            "    ball onto an elastic stack: most energy over the released %.4f J (%.4f without chains), fastest "
            "%.3f m/s (%.3f; impact %.3f)\n",
            chains.worst_excess, control.worst_excess, chains.fastest, control.fastest, chains.impact_speed);
    I2D_CHECK(chains.hash != control.hash);
    I2D_CHECK(chains.worst_excess <= 0.01 * chains.ball_drop_energy);
    I2D_CHECK(chains.fastest <= 1.01 * chains.impact_speed);
}

namespace {

// A rack of `rows` rows of touching balls (r 0.5, restitution 1, no friction or gravity),
// its apex towards a cue ball 2 m away moving at 4 m/s along the rack's axis; the balls'
// velocities after 2 s, the rack's row by row (top to bottom), the cue ball's last.
bool break_rack(int rows, bool chains, std::vector<i2d_vec2>& v) {
    i2d_world_def def = Scene::no_sleep_def(Scene::zero_gravity_def());
    def.enable_impact_chains = chains;
    Scene scene(def);
    const float d = 2.0f * ball_radius;
    const Material m = material(0.0f, 1.0f);
    std::vector<i2d_body_id> balls;
    for (int row = 0; row < rows; ++row) {
        for (int k = 0; k <= row; ++k) {
            const i2d_vec2 at{float(row) * d * 0.8660254f, (0.5f * float(row) - float(k)) * d};
            balls.push_back(scene.dynamic_circle(at, ball_radius, m));
        }
    }
    balls.push_back(scene.dynamic_circle(i2d_vec2{-3.0f, 0.0f}, ball_radius, m, i2d_vec2{4.0f, 0.0f}));
    for (const i2d_body_id b : balls) {
        if (I2D_IS_NULL(b)) {
            return false;
        }
    }
    if (!scene.step(steps_for(2.0))) {
        return false;
    }
    v.clear();
    for (const i2d_body_id b : balls) {
        v.push_back(velocity(b));
    }
    return true;
}

}  // namespace

I2D_TEST(phys_chain_rack_struck_on_its_axis_breaks_as_mirror_images) {
    // Two balls meeting the apex at once take it together: taken one after the other, the
    // apex would leave to one side. Two rows: the cue ball gives the apex its 4 m/s; the
    // apex meets both balls behind it at 30 degrees, each along its normal n = (cos 30,
    // +-sin 30) with impulse P: e = 1 on each, 2.5 P = 2 (4 cos 30), so each leaves at P n =
    // (2.4, +-0.8 sqrt 3). Three rows: every ball and its mirror image across the axis end
    // with the same x speed and opposite y speeds, and momentum stays (4, 0). Without
    // chains (the control) the substeps' sweeps miss the two-row answer.
    std::vector<i2d_vec2> two, control, three;
    I2D_REQUIRE(break_rack(2, true, two));
    I2D_REQUIRE(break_rack(2, false, control));
    I2D_REQUIRE(break_rack(3, true, three));
    const double vx = 2.4, vy = 0.8 * std::sqrt(3.0);
    fprintf(stderr, "    rack of 2 rows: (%.4f, %.4f) and (%.4f, %.4f) m/s, closed form (%.4f, +-%.4f); control (%.4f, %.4f)\n",
            two[1].x, two[1].y, two[2].x, two[2].y, vx, vy, control[1].x, control[1].y);
    for (int k = 1; k <= 2; ++k) {
        I2D_CHECK_NEAR(two[std::size_t(k)].x, vx, 0.01 * vx);
        I2D_CHECK_NEAR(std::fabs(two[std::size_t(k)].y), vy, 0.01 * vy);
    }
    I2D_CHECK(!(std::fabs(control[1].x - vx) <= 0.01 * vx));
    double asymmetry = 0.0, px = 0.0, py = 0.0;
    for (int row = 0; row < 3; ++row) {
        const int first = row * (row + 1) / 2;  // the row's first ball
        for (int k = 0; k <= row; ++k) {
            const i2d_vec2 a = three[std::size_t(first + k)], b = three[std::size_t(first + row - k)];
            asymmetry = std::max({asymmetry, std::fabs(double(a.x) - b.x), std::fabs(double(a.y) + b.y)});
        }
    }
    for (const i2d_vec2 u : three) {
        px += u.x;
        py += u.y;
    }
    fprintf(stderr, "    rack of 3 rows: largest difference from its mirror image %.2e m/s; momentum (%.4f, %.4f)\n",
            asymmetry, px, py);
    I2D_CHECK(asymmetry < 1e-4);
    I2D_CHECK_NEAR(px, 4.0, 1e-3);
    I2D_CHECK_NEAR(py, 0.0, 1e-3);
}

I2D_TEST(phys_chain_leaves_a_lone_impact_of_the_same_moment_to_the_substeps) {
    // A row of five touching balls, the first moving at 3 m/s into the rest, and far from
    // it two touching balls meeting head-on at 2 m/s each (masses 1 and 3, restitution
    // 0.8, where the substeps' answer differs from a rigid impact's in its last bits):
    // both impacts happen at the
    // step's start, the same moment. Only the row is a chain; the pair, which shares no
    // body with it, is left to the substeps and ends with the same bits as without chains.
    i2d_vec2 pair[2][2];
    double last_ball = 0.0;
    for (int chains = 0; chains < 2; ++chains) {
        i2d_world_def def = Scene::no_sleep_def(Scene::zero_gravity_def());
        def.enable_impact_chains = chains == 1;
        Scene scene(def);
        const Material m = material(0.0f, 1.0f);
        std::vector<i2d_body_id> row;
        for (int i = 0; i < 5; ++i) {
            const i2d_vec2 v{i == 0 ? 3.0f : 0.0f, 0.0f};
            row.push_back(scene.dynamic_circle(i2d_vec2{float(i) * 2.0f * ball_radius, 0.0f}, ball_radius, m, v));
        }
        const i2d_body_id left = scene.dynamic_circle(i2d_vec2{-0.5f, 10.0f}, ball_radius, m, i2d_vec2{2.0f, 0.0f});
        const i2d_body_id right = scene.dynamic_circle(i2d_vec2{0.5f, 10.0f}, ball_radius, material(0.0f, 0.8f, 3.0f),
                                                       i2d_vec2{-2.0f, 0.0f});
        I2D_REQUIRE(!I2D_IS_NULL(left) && !I2D_IS_NULL(right) && !I2D_IS_NULL(row.back()));
        I2D_REQUIRE(scene.step(steps_for(1.0)));
        pair[chains][0] = velocity(left);
        pair[chains][1] = velocity(right);
        last_ball = velocity(row.back()).x;
    }
    fprintf(stderr, "    pair with chains (%.6f, %.6f), without (%.6f, %.6f) m/s; the row's last ball %.4f m/s\n",
            pair[1][0].x, pair[1][1].x, pair[0][0].x, pair[0][1].x, last_ball);
    I2D_CHECK(same_bits(pair[0][0], pair[1][0]) && same_bits(pair[0][1], pair[1][1]));
    I2D_CHECK_NEAR(last_ball, 3.0, 0.02 * 3.0);
}
