// SPDX-License-Identifier: MIT
// A chain of 20 links on revolute joints hanging from a static body: how much it stretches
// under its own weight and under a weight 100 times a link's, and that it never blows up.
// A rigid chain does not stretch at all; soft joints stretch by load / (m_eff w^2) each
// (printed beside the measurement), so the figure measures how stiff the solver keeps a
// long chain of joints. (The joints issue quotes Box2D v3 at 2.9 cm and 39 cm; this scene
// rebuilt on Box2D v3 617d32a measured 2.88 cm and 29.8 cm.) Released level with its
// weight, the chain neither gains energy nor comes apart as it whips.
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

constexpr int link_count = 20;
constexpr float link_length = 0.5f;        // m, joint to joint
constexpr float link_half_width = 0.05f;   // m
constexpr float link_mass = 1.0f;          // kg
constexpr float weight_half_size = 0.5f;   // m: a 1 m box
constexpr float weight_mass = 100.0f;      // kg
constexpr double chain_length = link_count * double(link_length);
const i2d_vec2 top{0.0f, 20.0f};

// Density that gives a box of these half sizes the mass.
float density_for(float mass, float half_width, float half_height) {
    return mass / (4.0f * half_width * half_height);
}

struct Chain {
    std::vector<i2d_body_id> bodies;  // the links, top first, then the weight if any
    i2d_body_id last_link = I2D_NULL_BODY_ID;
    bool ok = false;
};

// Links hang straight down from `top` (or lie level to its right, when `level`), at
// rest, each joined to the one before at their shared end; the weight (when asked) hangs
// from the last link's far end.
Chain make_chain(Scene& s, bool with_weight, bool level = false) {
    Chain c;
    const i2d_body_id ceiling = s.anchor(top);
    i2d_body_id above = ceiling;
    const Material link = with_density(density_for(link_mass, link_half_width, 0.5f * link_length));
    // Along the chain from the top: where a point at distance d lies, and a box's half sizes.
    const auto along = [&](float d) { return level ? i2d_vec2{top.x + d, top.y} : i2d_vec2{top.x, top.y - d}; };
    const float half_x = level ? 0.5f * link_length : link_half_width;
    const float half_y = level ? link_half_width : 0.5f * link_length;
    for (int i = 0; i < link_count; ++i) {
        const float joint_at = link_length * float(i);
        const i2d_body_id body = s.dynamic_box(along(joint_at + 0.5f * link_length), half_x, half_y, link);
        if (I2D_IS_NULL(body)) {
            return c;
        }
        i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
        if (I2D_IS_NULL(i2d_joint_create_revolute(s.world, &join_at(def, above, body, along(joint_at))))) {
            fprintf(stderr, "    joint %d: %s\n", i, i2d_last_error_message());
            return c;
        }
        c.bodies.push_back(body);
        above = body;
    }
    c.last_link = above;
    if (with_weight) {
        const float end = float(chain_length);
        const Material heavy = with_density(density_for(weight_mass, weight_half_size, weight_half_size));
        const i2d_body_id weight =
            s.dynamic_box(along(end + weight_half_size), weight_half_size, weight_half_size, heavy);
        i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
        if (I2D_IS_NULL(weight) ||
            I2D_IS_NULL(i2d_joint_create_revolute(s.world, &join_at(def, above, weight, along(end))))) {
            return c;
        }
        c.bodies.push_back(weight);
    }
    c.ok = true;
    return c;
}

// How much longer the chain is than its links laid end to end: the distance from the
// ceiling's pivot to the last link's far end, minus 20 link lengths.
double stretch(const Chain& c, bool level = false) {
    const i2d_vec2 end = i2d_body_get_world_point(
        c.last_link, level ? i2d_vec2{0.5f * link_length, 0.0f} : i2d_vec2{0.0f, -0.5f * link_length});
    return distance(end, top) - chain_length;
}

// What a soft-joint solver gives, for the report beside the measurement: each rigid joint
// acts as a spring of the world's joint_hertz (60 Hz by default, and at most a quarter of
// the substep rate) on its effective mass, so joint j stretches by its load over
// m_eff (2 pi f)^2; the anchors lie on the line of the links' centres, so
// m_eff = 1 / (1/m_above + 1/m_below) (the ceiling's 1/m is 0). Summed over the 20 joints
// above the chain's lower end.
double soft_model_stretch(bool with_weight, double g) {
    const double f = std::min(double(i2d_default_world_def().joint_hertz), 1.0 / (4.0 * substep));
    const double omega2 = (2.0 * pi * f) * (2.0 * pi * f);
    double total = 0.0;
    for (int j = 0; j < link_count; ++j) {
        const double below = (link_count - j) * double(link_mass) + (with_weight ? double(weight_mass) : 0.0);
        const double inv_mass = (j == 0 ? 0.0 : 1.0 / link_mass) + 1.0 / link_mass;
        total += below * g * inv_mass / omega2;
    }
    return total;
}

struct HangResult {
    double stretch = 0.0;         // m, at the end
    double soft_model = 0.0;      // m, soft_model_stretch for the scene
    double fastest = 0.0;         // m/s, the fastest any body moved at any step
    double widest = 0.0;          // m, the farthest any body strayed sideways
    double final_speed = 0.0;     // m/s, the fastest body at the end
    bool finite = true;
};

HangResult hang(bool with_weight, double seconds) {
    HangResult r;
    Scene s;
    const Chain c = make_chain(s, with_weight);
    if (!c.ok) {
        ++i2d_check_failures;
        fprintf(stderr, "    chain creation failed: %s\n", i2d_last_error_message());
        return r;
    }
    for (int k = 0; k < steps_for(seconds); ++k) {
        if (!s.step()) {
            ++i2d_check_failures;
            return r;
        }
        for (const i2d_body_id b : c.bodies) {
            r.finite = r.finite && is_finite(b);
            r.fastest = std::max(r.fastest, speed(velocity(b)));
            r.widest = std::max(r.widest, std::fabs(double(position(b).x - top.x)));
        }
    }
    for (const i2d_body_id b : c.bodies) {
        r.final_speed = std::max(r.final_speed, speed(velocity(b)));
    }
    r.stretch = stretch(c);
    r.soft_model = soft_model_stretch(with_weight, s.gravity());
    return r;
}

// "No explosion": every number finite, nothing ever faster than falling a metre (the scene
// starts at rest and can only drop by the chain's stretch, centimetres), nothing strayed
// sideways from a chain that starts straight, and, given time, everything at rest.
void check_no_explosion(const HangResult& r, bool given_time) {
    constexpr double speed_bound = 4.5;      // m/s: sqrt(2 g 1 m)
    constexpr double sideways_bound = 0.01;  // m
    constexpr double rest_speed = 0.01;      // m/s
    I2D_CHECK(r.finite);
    I2D_CHECK(r.fastest < speed_bound);
    I2D_CHECK(r.widest < sideways_bound);
    I2D_CHECK(!given_time || r.final_speed < rest_speed);
}

// A hanging chain is a tree held by one joint to a static body: its joints are solved
// exactly (joint_tree.hpp), and it stretches only by what a substep's motion leaves
// before the next pass takes it back. The joints issue asks for less than 1 cm and 5 cm;
// the engine holds both chains within a millimetre.
constexpr double light_chain_bound = 0.01;   // m: the joints issue's bound without the weight
constexpr double heavy_chain_bound = 0.05;   // m: and with it
constexpr double exact_chain_bound = 0.001;  // m: what exact joints keep either chain within

void check_heavy_chain(double seconds) {
    const HangResult r = hang(true, seconds);
    fprintf(stderr, "    20 x 1 kg links + 100 kg, %.0f s: stretch %.4f mm (the issue's bound %.0f cm; soft joints at "
            "their stiffness: %.2f cm); fastest %.3f m/s, widest %.2e m, final speed %.2e m/s\n",
            seconds, 1000.0 * r.stretch, 100.0 * heavy_chain_bound, 100.0 * r.soft_model, r.fastest, r.widest,
            r.final_speed);
    I2D_CHECK(r.stretch < heavy_chain_bound);
    I2D_CHECK(std::fabs(r.stretch) < exact_chain_bound);
    check_no_explosion(r, seconds >= 60.0);
}

}  // namespace

// Under its own weight a 10 m chain of 20 links stretches less than the 1 cm, and
// less than a millimetre (soft joints at the default 60 Hz, as Box2D v3's, stretch it
// 2.8 cm), and holds still.
I2D_TEST(phys_joint_chain_of_20_links_stretches_under_1cm) {
    const HangResult r = hang(false, 3.0);
    fprintf(stderr, "    20 x 1 kg links: stretch %.4f mm (the issue's bound %.0f cm; soft joints at their stiffness: "
            "%.3f cm); fastest %.3f m/s, final speed %.2e m/s\n",
            1000.0 * r.stretch, 100.0 * light_chain_bound, 100.0 * r.soft_model, r.fastest, r.final_speed);
    I2D_CHECK(r.stretch < light_chain_bound);
    I2D_CHECK(std::fabs(r.stretch) < exact_chain_bound);
    check_no_explosion(r, true);
}

// With 100 kg hanging from 1 kg links (a mass ratio of 100): under the 5 cm and
// under a millimetre (soft joints: 30 cm), and no explosion.
I2D_TEST(phys_joint_chain_with_100kg_weight_stretches_under_5cm) { check_heavy_chain(3.0); }

// The same held for a minute: a solver that slowly pumps energy in shows it here.
I2D_TEST(phys_joint_chain_long_with_100kg_weight_holds_a_minute) { check_heavy_chain(60.0); }

// Released level with its 100 kg weight, the chain falls and swings for 10 s, whipping its
// light links: exact joints neither pump energy in (never 1 % above the start's, a tenth
// of that measured) nor come apart (every joint's anchors within 5 cm at every step: the
// whip turns links so fast within a substep that their ends drift 3 cm before the next
// pass pulls them back; soft joints drifted 5.5 cm and stretched the chain by a metre).
I2D_TEST(phys_joint_chain_with_100kg_weight_released_level_keeps_its_energy) {
    constexpr double energy_margin = 0.01;  // share of the start's energy
    constexpr double max_gap = 0.05;        // m between a joint's two anchors
    Scene s;
    const Chain c = make_chain(s, true, true);
    I2D_REQUIRE(c.ok);
    const double g = s.gravity();
    const auto energy = [&] {
        double e = 0.0;
        for (const i2d_body_id b : c.bodies) {
            e += kinetic_energy(b) + double(i2d_body_get_mass(b)) * g * double(position(b).y);
        }
        return e;
    };
    // The far end of each body along the chain, and the near end of the next.
    const i2d_vec2 link_far{0.5f * link_length, 0.0f}, link_near{-0.5f * link_length, 0.0f};
    const i2d_vec2 weight_near{-weight_half_size, 0.0f};
    const double e0 = energy();
    double highest = e0, widest = 0.0, fastest = 0.0;
    bool finite = true;
    for (int k = 0; k < steps_for(10.0); ++k) {
        I2D_REQUIRE(s.step());
        highest = std::max(highest, energy());
        for (std::size_t i = 0; i + 1 < c.bodies.size(); ++i) {
            const i2d_vec2 a = i2d_body_get_world_point(c.bodies[i], link_far);
            const i2d_vec2 near_end = i + 2 == c.bodies.size() ? weight_near : link_near;
            const i2d_vec2 b = i2d_body_get_world_point(c.bodies[i + 1], near_end);
            widest = std::max(widest, distance(a, b));
        }
        for (const i2d_body_id b : c.bodies) {
            finite = finite && is_finite(b);
            fastest = std::max(fastest, speed(velocity(b)));
        }
    }
    fprintf(stderr, "    energy at most %+.3f %% of the start's (allowed %+.0f %%); widest joint %.1f mm (allowed %.0f "
            "mm); fastest %.1f m/s\n",
            100.0 * (highest - e0) / std::fabs(e0), 100.0 * energy_margin, 1000.0 * widest, 1000.0 * max_gap, fastest);
    I2D_CHECK(finite);
    I2D_CHECK(highest - e0 <= energy_margin * std::fabs(e0));
    I2D_CHECK(widest < max_gap);
}
