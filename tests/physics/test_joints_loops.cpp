// SPDX-License-Identifier: MIT
// Joint groups that close loops through the fixed world, solved exactly (joint_tree.hpp).
//
// A bridge hung at both ends carries a heavy box on its middle (issue 43's scene: 20 planks
// of 1 m x 0.125 m and 2.5 kg on revolute joints, an 80 kg box), taut as the or with
// slack, hung in a V. Hung twice, the planks
// and joints close a loop through the fixed world; the exact solve takes the second hold
// as a cut (joint_tree.hpp), so rigid joints hold under the load where soft ones give by
// load / (m_eff (2 pi f)^2) each: Box2D v3 opens 39.1 mm on this scene. The control is the
// same bridge with four of its joints doubled (a second joint on the same anchors, which a
// rigid bridge does not feel): five loops, more than the exact solve cuts, so the sweep
// solves them all as soft rows, and the gaps open again.
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

constexpr int plank_count = 20;
constexpr float plank_length = 1.0f;        // m, joint to joint
constexpr float plank_half_height = 0.0625f;
constexpr float plank_mass = 2.5f;          // kg
constexpr float box_half_size = 0.5f;       // m
constexpr float box_mass_kg = 80.0f;
constexpr float deck_height = 10.0f;        // m, where the planks hang from
constexpr double settle_seconds = 4.0;
constexpr double rigid_gap_bound = 0.001;   // m: the target for the widest gap
// The straight bridge is exactly as long as its span: rigid, it cannot sag without its
// joints giving (a sag s asks the span to shorten by about 4 s^2 / span). Near straight
// the sag is in the joints' null space, which rigid velocity rows do not see: without the
// loops' position projection the gaps opened 1.7 mm as it swung; with it, 0.28 mm.
// The slack bridge hangs in a V, its middle this far below its ends.
constexpr float slack_sag = 2.0f;           // m
// Redundant joints that make the control's loops: with the bridge's own, one more than the
// exact solve cuts (max_cut_joints, 4).
constexpr int control_doubled_joints = 4;

float density_for(float mass, float half_width, float half_height) {
    return mass / (4.0f * half_width * half_height);
}

// Builds the bridge from x = 0 with its first `doubled` inner joints doubled, straight or
// hung in a V that sags by `sag`, drops the box on its middle, and writes the widest joint
// gap over the run, m.
void widest_gap_under_the_box(float sag, int doubled, double* widest) {
    *widest = INFINITY;  // what a scene that failed to build reports
    Scene s;
    // Each half of the V runs straight from its end to the middle, 10 planks long.
    const float half_length = 0.5f * plank_count * plank_length;
    const float half_span = std::sqrt(half_length * half_length - sag * sag);
    const float angle = std::atan2(sag, half_span);  // of the left half, downwards
    const auto joint_point = [&](int i) {
        const float along = plank_length * float(i <= plank_count / 2 ? i : plank_count - i);
        const float x = i <= plank_count / 2 ? along * std::cos(angle) : 2.0f * half_span - along * std::cos(angle);
        return i2d_vec2{x, deck_height - along * std::sin(angle)};
    };
    const i2d_body_id left = s.anchor(joint_point(0));
    const i2d_body_id right = s.anchor(joint_point(plank_count));
    const Material plank = with_density(density_for(plank_mass, 0.5f * plank_length, plank_half_height));
    std::vector<i2d_joint_id> joints;
    const auto join = [&](i2d_body_id a, i2d_body_id b, i2d_vec2 at) {
        i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
        const i2d_joint_id joint = i2d_joint_create_revolute(s.world, &join_at(def, a, b, at));
        I2D_REQUIRE(!I2D_IS_NULL(joint));
        joints.push_back(joint);
    };
    i2d_body_id previous = left;
    for (int i = 0; i < plank_count; ++i) {
        const i2d_vec2 from = joint_point(i), to = joint_point(i + 1);
        const i2d_vec2 centre{0.5f * (from.x + to.x), 0.5f * (from.y + to.y)};
        const i2d_body_id body = s.turned_box(I2D_BODY_DYNAMIC, centre, std::atan2(to.y - from.y, to.x - from.x),
                                              0.5f * plank_length, plank_half_height, plank);
        I2D_REQUIRE(!I2D_IS_NULL(body));
        join(previous, body, from);
        if (i >= 1 && i <= doubled) {
            join(previous, body, from);
        }
        previous = body;
    }
    join(previous, right, joint_point(plank_count));
    const i2d_vec2 middle = joint_point(plank_count / 2);
    const Material heavy = with_density(density_for(box_mass_kg, box_half_size, box_half_size));
    I2D_REQUIRE(!I2D_IS_NULL(s.dynamic_box(
        i2d_vec2{middle.x, middle.y + plank_half_height + box_half_size + 0.01f}, box_half_size, box_half_size, heavy)));
    *widest = 0.0;
    for (int k = 0; k < steps_for(settle_seconds); ++k) {
        I2D_REQUIRE(s.step());
        for (const i2d_joint_id joint : joints) {
            *widest = std::max(*widest, joint_gap(joint));
        }
    }
}

}  // namespace

// Rigid joints: the box's 785 N, on a bridge with slack, opens no joint by a millimetre.
I2D_TEST(phys_joint_bridge_hung_at_both_ends_holds_a_heavy_box_within_a_millimetre) {
    double exact = 0.0, exact_with_doubles = 0.0, control = 0.0;
    widest_gap_under_the_box(slack_sag, 0, &exact);
    // Three doubled joints: four cuts, still exact; the doubles' rows depend on their twins'.
    widest_gap_under_the_box(slack_sag, control_doubled_joints - 1, &exact_with_doubles);
    widest_gap_under_the_box(slack_sag, control_doubled_joints, &control);
    fprintf(stderr, "    bridge in a V + 80 kg box: widest joint gap %.3f mm exact, %.3f mm exact with %d doubled "
            "joints, %.1f mm soft (control); bound %.0f mm\n",
            1000.0 * exact, 1000.0 * exact_with_doubles, control_doubled_joints - 1, 1000.0 * control,
            1000.0 * rigid_gap_bound);
    I2D_CHECK(exact < rigid_gap_bound);
    I2D_CHECK(exact_with_doubles < rigid_gap_bound);
    I2D_CHECK(control > rigid_gap_bound);
}

// The straight bridge, taut: it holds within a millimetre where soft joints (and
// Box2D v3, 39.1 mm) give by centimetres.
I2D_TEST(phys_joint_bridge_taut_holds_a_heavy_box_within_a_millimetre) {
    double exact = 0.0, control = 0.0;
    widest_gap_under_the_box(0.0f, 0, &exact);
    widest_gap_under_the_box(0.0f, control_doubled_joints, &control);
    fprintf(stderr, "    taut bridge + 80 kg box: widest joint gap %.3f mm exact, %.1f mm soft (control); bound %.0f "
            "mm; Box2D v3 39.1 mm\n", 1000.0 * exact, 1000.0 * control, 1000.0 * rigid_gap_bound);
    I2D_CHECK(exact < rigid_gap_bound);
    I2D_CHECK(control > rigid_gap_bound);
}

// A body hinged to the ground at its centre and, by a point 0.5 m to its side, to a bar 2 m
// away: the two hinges cannot both hold. The exact solve holds the first and of the second
// the part it can (its row along the line to the first hinge depends on the first's and
// takes nothing): the body turns its point towards the bar and comes to rest there,
// finite and never fast.
I2D_TEST(phys_joint_body_held_at_two_places_that_cannot_both_hold_comes_to_rest) {
    constexpr float apart = 2.0f;            // m between the first hinge and the bar
    constexpr float reach = 0.5f;            // m from the body's centre to its second anchor
    constexpr double speed_bound = 20.0;     // m/s: far beyond a 0.5 m swing under gravity
    constexpr double rest_speed = 0.05;      // m/s, the second anchor's, after the run
    constexpr double aim_tolerance = 0.01;   // rad
    Scene s;
    const i2d_vec2 at{0.0f, 5.0f};
    const i2d_body_id ground = s.anchor(at);
    const i2d_body_id bar = s.anchor(i2d_vec2{at.x + apart, at.y});
    // Its second anchor starts pointing down, a quarter turn from the bar.
    const i2d_body_id body = s.dynamic_box(at, 0.6f, 0.1f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    i2d_revolute_joint_def first = i2d_default_revolute_joint_def();
    I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_revolute(s.world, &join_at(first, ground, body, at))));
    i2d_revolute_joint_def second = i2d_default_revolute_joint_def();
    second.base.body_a = bar;
    second.base.body_b = body;
    second.base.local_anchor_b = i2d_vec2{0.0f, -reach};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_revolute(s.world, &second)));
    double fastest = 0.0;
    for (int k = 0; k < steps_for(settle_seconds); ++k) {
        I2D_REQUIRE(s.step());
        I2D_REQUIRE(is_finite(body));
        fastest = std::max(fastest, reach * std::fabs(double(i2d_body_get_angular_velocity(body))));
    }
    const double final_speed = reach * std::fabs(double(i2d_body_get_angular_velocity(body)));
    // Pointing at the bar: the local -y anchor along world +x, a quarter turn up.
    const double aim = wrap_angle(angle_of(body) - pi / 2.0);
    fprintf(stderr, "    held at two places: fastest %.2f m/s, final %.4f m/s, aimed %.4f rad off the bar, centre "
            "%.3f mm from the first hinge\n", fastest, final_speed, aim, 1000.0 * distance(position(body), at));
    I2D_CHECK(fastest < speed_bound);
    I2D_CHECK(final_speed < rest_speed);
    I2D_CHECK(std::fabs(aim) < aim_tolerance);
    I2D_CHECK(distance(position(body), at) < rigid_gap_bound);
}
