// SPDX-License-Identifier: MIT
// Weld joints against closed form: a rigid weld holds a body still under gravity, and a
// welded cantilever keeps its shape.
#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

constexpr int cantilever_boxes = 10;
constexpr float box_half_length = 0.25f, box_half_height = 0.1f;
const i2d_vec2 cantilever_wall{0.0f, 10.0f};

// The cantilever's boxes, from the wall out, each welded to the one before at their
// shared end (the first to a static body at the wall).
std::vector<i2d_body_id> build_cantilever(Scene& s, std::vector<i2d_joint_id>* welds = nullptr) {
    i2d_body_id previous = s.anchor(cantilever_wall);
    std::vector<i2d_body_id> boxes;
    for (int i = 0; i < cantilever_boxes; ++i) {
        const float left = cantilever_wall.x + 2.0f * box_half_length * float(i);
        const i2d_body_id box = s.dynamic_box(i2d_vec2{left + box_half_length, cantilever_wall.y}, box_half_length,
                                              box_half_height);
        i2d_weld_joint_def def = i2d_default_weld_joint_def();
        const i2d_joint_id weld =
            I2D_IS_NULL(box) ? I2D_NULL_JOINT_ID
                             : i2d_joint_create_weld(s.world, &join_at(def, previous, box, i2d_vec2{left, cantilever_wall.y}));
        if (I2D_IS_NULL(weld)) {
            return {};
        }
        if (welds != nullptr) {
            welds->push_back(weld);
        }
        boxes.push_back(box);
        previous = box;
    }
    return boxes;
}

}  // namespace

// A 1 m bar welded by one end to a static body, sticking out sideways: gravity pulls and
// twists it, and the (rigid) weld keeps both its ends within 1 mm of where they started.
I2D_TEST(phys_joint_weld_to_static_holds_within_1mm_under_gravity) {
    constexpr double tolerance = 0.001;  // m
    Scene s;
    const i2d_vec2 wall{0.0f, 5.0f};
    const i2d_body_id ground = s.anchor(wall);
    const i2d_body_id bar = s.dynamic_box(i2d_vec2{wall.x + 0.5f, wall.y}, 0.5f, 0.1f);
    i2d_weld_joint_def def = i2d_default_weld_joint_def();
    const i2d_joint_id joint = i2d_joint_create_weld(s.world, &join_at(def, ground, bar, wall));
    I2D_REQUIRE(!I2D_IS_NULL(bar) && !I2D_IS_NULL(joint));
    const i2d_vec2 far_end_local{0.5f, 0.0f};
    const i2d_vec2 far_start = i2d_body_get_world_point(bar, far_end_local);
    const i2d_vec2 centre_start = position(bar);
    double worst = 0.0;
    for (int k = 0; k < steps_for(3.0); ++k) {
        I2D_REQUIRE(s.step());
        const i2d_vec2 far = i2d_body_get_world_point(bar, far_end_local), c = position(bar);
        worst = std::max({worst, distance(far, far_start), distance(c, centre_start)});
    }
    fprintf(stderr, "    worst displacement of the bar's centre or far end: %.4f mm (allowed 1 mm); angle %.2e rad; "
            "reaction (%.4f, %.4f) N, %.4f N m (weight %.4f N, its torque %.4f N m)\n",
            1000.0 * worst, angle_of(bar), double(i2d_joint_get_reaction_force(joint).x),
            double(i2d_joint_get_reaction_force(joint).y), double(i2d_joint_get_reaction_torque(joint)),
            double(i2d_body_get_mass(bar)) * s.gravity(), double(i2d_body_get_mass(bar)) * s.gravity() * 0.5);
    I2D_CHECK(worst < tolerance);
}

// Ten 0.5 m boxes welded end to end out of a wall: the cantilever holds its shape. Its
// tip drops less than 2 % of its 5 m (10 cm: a bend of about a degree), no box turns more
// than 2 degrees, and it is still: the tip moves less than 1 mm between 2 s and 5 s. It is
// a tree held by one weld to the wall, solved exactly (joint_tree.hpp); soft welds at the
// substep's rate bent it by 2.6 m (the angle rows' stiffness scales with these slender
// boxes' small inertia).
I2D_TEST(phys_joint_weld_cantilever_of_10_boxes_holds_its_shape) {
    constexpr double length = 2.0 * box_half_length * cantilever_boxes;
    constexpr double max_drop = 0.02 * length;         // m
    constexpr double max_turn = degrees(2.0);          // rad
    constexpr double max_creep = 0.001;                // m
    Scene s;
    const std::vector<i2d_body_id> boxes = build_cantilever(s);
    I2D_REQUIRE(boxes.size() == std::size_t(cantilever_boxes));
    const i2d_vec2 tip_local{box_half_length, 0.0f};
    I2D_REQUIRE(s.step(steps_for(2.0)));
    const i2d_vec2 tip_at_2s = i2d_body_get_world_point(boxes.back(), tip_local);
    I2D_REQUIRE(s.step(steps_for(3.0)));
    const i2d_vec2 tip = i2d_body_get_world_point(boxes.back(), tip_local);
    double turn = 0.0;
    bool finite = true;
    for (const i2d_body_id b : boxes) {
        turn = std::max(turn, std::fabs(angle_of(b)));
        finite = finite && is_finite(b);
    }
    const double drop = double(cantilever_wall.y) - double(tip.y);
    const double creep = distance(tip, tip_at_2s);
    fprintf(stderr, "    tip dropped %.3f mm (allowed %.0f cm), largest box angle %.4f deg, tip moved %.4f mm "
            "between 2 s and 5 s\n",
            1000.0 * drop, 100.0 * max_drop, turn * 180.0 / pi, 1000.0 * creep);
    I2D_CHECK(finite);
    I2D_CHECK(drop < max_drop);
    I2D_CHECK(turn < max_turn);
    I2D_CHECK(creep < max_creep);
}

// The boxes stay joined end to end (each weld's anchors within 1 cm of each other at every
// step) and every number finite for 5 s.
I2D_TEST(phys_joint_weld_cantilever_of_10_boxes_stays_joined) {
    constexpr double max_gap = 0.01;  // m
    const i2d_vec2 left_end{-box_half_length, 0.0f}, right_end{box_half_length, 0.0f};
    Scene s;
    const std::vector<i2d_body_id> boxes = build_cantilever(s);
    I2D_REQUIRE(boxes.size() == std::size_t(cantilever_boxes));
    double widest = 0.0;
    bool finite = true;
    for (int step = 0; step < steps_for(5.0); ++step) {
        I2D_REQUIRE(s.step());
        for (std::size_t i = 1; i < boxes.size(); ++i) {
            const i2d_vec2 a = i2d_body_get_world_point(boxes[i - 1], right_end);
            const i2d_vec2 b = i2d_body_get_world_point(boxes[i], left_end);
            widest = std::max(widest, distance(a, b));
            finite = finite && is_finite(boxes[i]);
        }
    }
    fprintf(stderr, "    widest gap between welded ends over 5 s: %.3f mm (allowed %.0f mm)\n", 1000.0 * widest,
            1000.0 * max_gap);
    I2D_CHECK(finite);
    I2D_CHECK(widest < max_gap);
}

// The welds' settings decide at every step how they are held: made springs (2 Hz) by
// their setters, they leave the tree pass and the cantilever sags as soft welds let it
// (more than 10 cm); made rigid again, they rejoin it and pull the cantilever back up
// (its tip within 1 cm of the wall's height).
I2D_TEST(phys_joint_weld_cantilever_follows_its_welds_settings) {
    constexpr double rigid_drop = 0.001, soft_drop = 0.1, recovered_drop = 0.01;  // m
    constexpr float spring_hertz = 2.0f;
    Scene s;
    std::vector<i2d_joint_id> welds;
    const std::vector<i2d_body_id> boxes = build_cantilever(s, &welds);
    I2D_REQUIRE(boxes.size() == std::size_t(cantilever_boxes));
    const auto tip_drop = [&] {
        return double(cantilever_wall.y) - double(i2d_body_get_world_point(boxes.back(), {box_half_length, 0.0f}).y);
    };
    I2D_REQUIRE(s.step(steps_for(1.0)));
    const double rigid = tip_drop();
    for (const i2d_joint_id weld : welds) {
        I2D_CHECK(i2d_weld_joint_set_angular_hertz(weld, spring_hertz) == I2D_OK);
    }
    I2D_REQUIRE(s.step(steps_for(2.0)));
    const double soft = tip_drop();
    for (const i2d_joint_id weld : welds) {
        I2D_CHECK(i2d_weld_joint_set_angular_hertz(weld, 0.0f) == I2D_OK);
    }
    I2D_REQUIRE(s.step(steps_for(3.0)));
    const double recovered = tip_drop();
    fprintf(stderr, "    tip drop: rigid %.4f mm, after 2 s as %.0f Hz springs %.1f cm, rigid again after 3 s %.4f mm\n",
            1000.0 * rigid, double(spring_hertz), 100.0 * soft, 1000.0 * recovered);
    I2D_CHECK(std::fabs(rigid) < rigid_drop);
    I2D_CHECK(soft > soft_drop);
    I2D_CHECK(std::fabs(recovered) < recovered_drop);
}
