// SPDX-License-Identifier: MIT
// Non-finite quarantine: a body whose state a step finds non-finite is frozen where the
// step found it (made static, its contacts ended, its joints' impulses cleared) and
// reported, and every body it did not touch goes on exactly as before. No public call
// can make a state non-finite (that is the point of the API's checks), so these tests
// poison a body's velocity inside the core, standing in for an overflow nobody foresaw.
#include <cmath>
#include <limits>

#include "check.h"
#include "world_fixture.hpp"

using namespace i2d;

using unit::add_body;
using unit::add_box_body;
using unit::is_finite_body;
using unit::step;
using unit::substeps;
using unit::time_step;

namespace {

constexpr float half_size = 0.5f;        // boxes, m
constexpr float ground_top = 0.5f;       // m
constexpr float resting_y = ground_top + half_size;
constexpr double rest_tolerance = 0.01;  // m: a resting box's centre against its closed form
constexpr double drop_tolerance = 1e-3;  // m: free fall against semi-implicit Euler

const float not_a_number = std::numeric_limits<float>::quiet_NaN();

WorldDef awake_world() {
    WorldDef def;
    def.enable_sleep = false;  // sleeping bodies skip the solver, and so the check
    return def;
}

int32_t add_ground(World& world) {
    return add_box_body(world, BodyType::static_body, {0.0f, 0.0f}, 40.0f, ground_top);
}

int32_t add_dynamic_box(World& world, Vec2 at) {
    return add_box_body(world, BodyType::dynamic, at, half_size, half_size);
}

bool every_body_finite(const World& world) {
    for (int32_t i = 0; i < world.bodies().capacity(); ++i) {
        if (world.bodies().is_live(i) && !is_finite_body(world.bodies()[i])) {
            return false;
        }
    }
    return true;
}

// The core's id for a body (no C boundary installed an encoder).
uint64_t core_id(const World& world, int32_t body) {
    return (uint64_t(world.bodies().generation(body)) << 32) | uint32_t(body);
}

// Drop from rest after n substeps of semi-implicit Euler: g h^2 n (n + 1) / 2.
double euler_drop(double g, int32_t steps) {
    const double h = double(time_step) / substeps;
    const double n = double(steps) * substeps;
    return g * h * h * n * (n + 1.0) / 2.0;
}

bool same_pose(const Transform& a, const Transform& b) {
    return a.p.x == b.p.x && a.p.y == b.p.y && a.q.c == b.q.c && a.q.s == b.q.s;
}

}  // namespace

I2D_TEST(unit_quarantine_freezes_a_non_finite_body_where_the_step_found_it) {
    World world{awake_world()};
    add_ground(world);
    const int32_t poisoned = add_dynamic_box(world, {-5.0f, resting_y});
    step(world, 30);
    I2D_REQUIRE(world.counters().contact_count == 1);
    const Transform before = world.bodies()[poisoned].transform;

    i2d::WorldProbe::body(world, poisoned).linear_velocity = {not_a_number, 0.0f};
    step(world, 1);

    const Body& b = world.bodies()[poisoned];
    I2D_CHECK(world.is_quarantined(poisoned));
    I2D_CHECK(b.type == BodyType::static_body);
    I2D_CHECK(same_pose(b.transform, before));
    I2D_CHECK(b.linear_velocity.x == 0.0f && b.linear_velocity.y == 0.0f && b.angular_velocity == 0.0f);
    I2D_CHECK(every_body_finite(world));
    const std::vector<BodyQuarantineEvent>& frozen = world.events().body_quarantines;
    I2D_REQUIRE(frozen.size() == 1);
    I2D_CHECK(frozen[0].body == core_id(world, poisoned));
    I2D_CHECK(frozen[0].former_type == int32_t(BodyType::dynamic));
    I2D_CHECK(same_pose(frozen[0].transform, before));
    // Its contact with the ground ended, reported in this step's arrays.
    I2D_CHECK(world.counters().contact_count == 0);
    I2D_CHECK(world.events().contact_end.size() == 1);

    step(world, 60);
    I2D_CHECK(world.events().body_quarantines.empty());
    I2D_CHECK(same_pose(world.bodies()[poisoned].transform, before));
    I2D_CHECK(every_body_finite(world));
}

I2D_TEST(unit_quarantine_leaves_untouched_bodies_on_their_closed_forms) {
    World world{awake_world()};
    add_ground(world);
    const int32_t poisoned = add_dynamic_box(world, {-5.0f, resting_y});
    const int32_t resting = add_dynamic_box(world, {5.0f, resting_y});
    step(world, 30);
    const int32_t falling = add_dynamic_box(world, {0.0f, 50.0f});

    i2d::WorldProbe::body(world, poisoned).angular_velocity = not_a_number;
    const int32_t steps = 60;
    step(world, steps);

    I2D_CHECK(world.is_quarantined(poisoned));
    I2D_CHECK(!world.is_quarantined(resting) && !world.is_quarantined(falling));
    I2D_CHECK(every_body_finite(world));
    I2D_CHECK_NEAR(world.bodies()[resting].transform.p.y, resting_y, rest_tolerance);
    I2D_CHECK_NEAR(world.bodies()[resting].transform.p.x, 5.0, rest_tolerance);
    I2D_CHECK_NEAR(50.0 - world.bodies()[falling].transform.p.y, euler_drop(10.0, steps), drop_tolerance);
}

I2D_TEST(unit_quarantine_takes_the_bodies_the_nan_reached_in_the_same_step) {
    World world{awake_world()};
    add_ground(world);
    const int32_t bottom = add_dynamic_box(world, {0.0f, resting_y});
    const int32_t top = add_dynamic_box(world, {0.0f, resting_y + 2.0f * half_size});
    const int32_t apart = add_dynamic_box(world, {6.0f, resting_y});
    step(world, 30);
    I2D_REQUIRE(world.counters().contact_count == 3);

    i2d::WorldProbe::body(world, bottom).linear_velocity = {0.0f, not_a_number};
    step(world, 1);

    // The contact between the two boxes carried the NaN up within the step.
    I2D_CHECK(world.is_quarantined(bottom) && world.is_quarantined(top));
    I2D_CHECK(!world.is_quarantined(apart));
    I2D_CHECK(world.events().body_quarantines.size() == 2);
    I2D_CHECK(every_body_finite(world));
    I2D_CHECK(world.counters().contact_count == 1);  // only the untouched box's
    step(world, 30);
    I2D_CHECK_NEAR(world.bodies()[apart].transform.p.y, resting_y, rest_tolerance);
}

I2D_TEST(unit_quarantine_clears_the_joints_impulses_and_a_new_type_revives_the_body) {
    World world{awake_world()};
    const int32_t anchor = add_body(world, BodyType::static_body, {0.0f, 10.0f});
    const int32_t bob = add_dynamic_box(world, {2.0f, 10.0f});
    JointDef def;
    def.type = JointType::revolute;
    def.body_a = anchor;
    def.body_b = bob;
    def.local_anchor_a = {0.0f, 0.0f};
    def.local_anchor_b = {-2.0f, 0.0f};
    const int32_t hinge = world.create_joint(def);
    I2D_REQUIRE(hinge != null_index);
    step(world, 20);
    I2D_REQUIRE(length(world.joints()[hinge].reaction_force) > 0.0f);  // it holds the swinging bob

    i2d::WorldProbe::body(world, bob).linear_velocity = {not_a_number, not_a_number};
    step(world, 1);
    I2D_CHECK(world.is_quarantined(bob));
    const Joint& j = world.joints()[hinge];
    I2D_CHECK(j.reaction_force.x == 0.0f && j.reaction_force.y == 0.0f && j.reaction_torque == 0.0f);
    I2D_CHECK(j.impulses.linear.x == 0.0f && j.impulses.linear.y == 0.0f);
    I2D_CHECK(every_body_finite(world));

    // Brought back as the event says: a pose, then its former type. It swings again
    // from rest at the side: the hinge holds it at 2 m from the anchor.
    world.set_transform(bob, Transform{{2.0f, 10.0f}, Rot{}});
    world.set_type(bob, BodyType::dynamic);
    I2D_CHECK(!world.is_quarantined(bob));
    step(world, 30);
    const Vec2 from_anchor = world.bodies()[bob].transform.p - Vec2{0.0f, 10.0f};
    I2D_CHECK_NEAR(length(from_anchor), 2.0, 0.01);
    I2D_CHECK(world.bodies()[bob].transform.p.y < 9.0f);  // it swung down
    I2D_CHECK(world.events().body_quarantines.empty());
}

I2D_TEST(unit_quarantine_ends_when_the_type_is_set_even_to_static) {
    World world{awake_world()};
    add_ground(world);
    const int32_t poisoned = add_dynamic_box(world, {0.0f, resting_y});
    step(world, 10);
    i2d::WorldProbe::body(world, poisoned).linear_velocity = {not_a_number, 0.0f};
    step(world, 1);
    I2D_REQUIRE(world.is_quarantined(poisoned));
    world.set_type(poisoned, BodyType::static_body);  // kept as scenery, acknowledged
    I2D_CHECK(!world.is_quarantined(poisoned));
    I2D_CHECK(world.bodies()[poisoned].type == BodyType::static_body);
}
