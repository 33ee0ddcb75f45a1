// SPDX-License-Identifier: MIT
// Joints in the core world: their lists on the bodies, the collision filter they impose,
// the islands they join, and what creating, destroying and changing them does.
#include <cmath>

#include "check.h"
#include "world_fixture.hpp"
#include "math/math.hpp"

using namespace i2d;
using unit::add_body;
using unit::add_box_body;
using unit::step_validated;
using unit::without_gravity;

namespace {

int32_t add_joint(World& world, JointType type, int32_t a, int32_t b, bool collide_connected = false) {
    JointDef def;
    def.type = type;
    def.distance.length = length(world.bodies()[b].center - world.bodies()[a].center);  // holds them where they are
    def.body_a = a;
    def.body_b = b;
    def.collide_connected = collide_connected;
    return world.create_joint(def);
}

// Two 1 m boxes overlapping by half their width.
struct OverlappingPair {
    World world{without_gravity()};
    int32_t a = add_box_body(world, BodyType::dynamic, {0.0f, 0.0f}, 0.5f, 0.5f);
    int32_t b = add_box_body(world, BodyType::dynamic, {0.5f, 0.0f}, 0.5f, 0.5f);
    int32_t contacts() const { return world.counters().contact_count; }
};

}  // namespace

I2D_TEST(unit_joint_lists_hold_each_bodys_joints_through_create_and_destroy) {
    World world{WorldDef{}};
    const int32_t a = add_body(world, BodyType::dynamic, {0.0f, 0.0f});
    const int32_t b = add_body(world, BodyType::dynamic, {1.0f, 0.0f});
    const int32_t c = add_body(world, BodyType::dynamic, {2.0f, 0.0f});
    const int32_t ab = add_joint(world, JointType::revolute, a, b);
    const int32_t bc = add_joint(world, JointType::distance, b, c);
    const int32_t ca = add_joint(world, JointType::weld, c, a);
    I2D_CHECK(world.bodies()[a].joint_count == 2 && world.bodies()[b].joint_count == 2);
    world.destroy_joint(bc);
    world.validate();
    I2D_CHECK(world.bodies()[b].joint_count == 1 && world.bodies()[c].joint_count == 1);
    I2D_CHECK(world.joints().is_live(ab) && world.joints().is_live(ca) && !world.joints().is_live(bc));
    world.destroy_body(a);  // takes ab and ca with it
    world.validate();
    I2D_CHECK(world.joints().count() == 0);
    I2D_CHECK(world.bodies()[b].joint_count == 0 && world.bodies()[c].joint_count == 0);
}

I2D_TEST(unit_joined_bodies_do_not_collide_unless_collide_connected) {
    OverlappingPair pair;
    step_validated(pair.world, 1);
    I2D_CHECK(pair.contacts() == 1);
    const int32_t joint = add_joint(pair.world, JointType::filter, pair.a, pair.b);
    I2D_CHECK(pair.contacts() == 0);  // ended at once
    step_validated(pair.world, 2);
    I2D_CHECK(pair.contacts() == 0);
    JointDef def = pair.world.joints()[joint].def;
    def.collide_connected = true;
    pair.world.set_joint_def(joint, def);
    step_validated(pair.world, 1);
    I2D_CHECK(pair.contacts() == 1);
}

I2D_TEST(unit_destroying_a_joint_lets_its_bodies_collide_again) {
    OverlappingPair pair;
    const int32_t joint = add_joint(pair.world, JointType::revolute, pair.a, pair.b);
    step_validated(pair.world, 2);
    I2D_CHECK(pair.contacts() == 0);
    pair.world.destroy_joint(joint);
    step_validated(pair.world, 1);
    I2D_CHECK(pair.contacts() == 1);
}

I2D_TEST(unit_joined_bodies_share_an_island_and_wake_together) {
    World world{without_gravity()};
    const int32_t a = add_box_body(world, BodyType::dynamic, {0.0f, 0.0f}, 0.5f, 0.5f);
    const int32_t b = add_box_body(world, BodyType::dynamic, {5.0f, 0.0f}, 0.5f, 0.5f);
    const int32_t joint = add_joint(world, JointType::distance, a, b);
    I2D_CHECK(world.bodies()[a].island == world.bodies()[b].island);
    step_validated(world, 60);  // at rest: the pair sleeps after time_to_sleep
    I2D_CHECK(!world.is_awake(a) && !world.is_awake(b));
    I2D_CHECK(world.counters().sleeping_island_count == 1);
    world.wake_body(b);
    I2D_CHECK(world.is_awake(a));
    // Once the joint goes, the island splits when it next sleeps: two islands.
    world.destroy_joint(joint);
    step_validated(world, 60);
    I2D_CHECK(world.counters().sleeping_island_count == 2);
}

I2D_TEST(unit_a_joint_to_a_body_made_static_stops_linking_islands) {
    World world{WorldDef{}};
    const int32_t a = add_body(world, BodyType::dynamic, {0.0f, 0.0f});
    const int32_t b = add_body(world, BodyType::dynamic, {2.0f, 0.0f});
    const int32_t joint = add_joint(world, JointType::revolute, a, b);
    I2D_CHECK(world.joints()[joint].island_link);
    world.set_type(b, BodyType::static_body);
    world.validate();
    I2D_CHECK(!world.joints()[joint].island_link);
    world.set_type(b, BodyType::dynamic);
    world.validate();
    I2D_CHECK(world.joints()[joint].island_link);
    I2D_CHECK(world.bodies()[a].island == world.bodies()[b].island);
}

I2D_TEST(unit_joint_gathered_once_from_the_first_awake_body) {
    World world{WorldDef{}};
    const int32_t ground = add_body(world, BodyType::static_body, {0.0f, 0.0f});
    const int32_t a = add_body(world, BodyType::dynamic, {0.0f, 1.0f});
    const int32_t b = add_body(world, BodyType::dynamic, {0.0f, 2.0f});
    const int32_t held = add_joint(world, JointType::revolute, ground, a);
    const int32_t link = add_joint(world, JointType::revolute, a, b);
    add_joint(world, JointType::filter, a, b);  // never solved
    std::vector<int32_t> awake{a, b}, gathered;
    i2d::WorldProbe::joint_set(world).gather_awake(awake, gathered);
    I2D_CHECK(gathered.size() == 2);
    I2D_CHECK((gathered[0] == held && gathered[1] == link) || (gathered[0] == link && gathered[1] == held));
}

// Found by the API fuzzer: a wheel and a prismatic joint on one box and the ground ask
// for what no pose gives; the two pushed the box's spin past any bound within a step
// and the world filled with NaN. Now each gives up what it cannot hold, and the box
// never leaves a step faster than the world's speed limit (unguarded: 4.4e11 m/s).
I2D_TEST(unit_joints_that_cannot_both_hold_leave_the_world_finite) {
    World world{WorldDef{}};
    const int32_t ground = add_body(world, BodyType::static_body, {0.0f, -1.0f});
    const int32_t box = add_box_body(world, BodyType::dynamic, {-1.0f, -3.86f}, 0.25f, 0.25f);
    JointDef wheel;
    wheel.type = JointType::wheel;
    wheel.body_a = box;
    wheel.body_b = ground;
    world.create_joint(wheel);
    JointDef prismatic;
    prismatic.type = JointType::prismatic;
    prismatic.body_a = ground;
    prismatic.body_b = box;
    prismatic.local_anchor_a = {-1.0f, 0.5f};
    prismatic.local_anchor_b = {-4.0f, -3.25f};
    world.create_joint(prismatic);
    for (int32_t i = 0; i < 600; ++i) {
        unit::step(world, 1);
        const Body& b = world.bodies()[box];
        I2D_CHECK(unit::is_finite_body(b));
        I2D_CHECK(length(b.linear_velocity) <= world.settings().maximum_linear_speed);
    }
    world.validate();
}
