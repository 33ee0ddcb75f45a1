// SPDX-License-Identifier: MIT
// World internals: mass from shapes, shape lists across destruction, filters, and the
// pair rules that keep static and kinematic bodies out of the narrowphase.
#include <cmath>

#include "check.h"
#include "world_fixture.hpp"

using namespace i2d;

using unit::add_body;
using unit::add_box;
using unit::add_box_body;
using unit::add_circle;
using unit::pi_d;
using unit::time_step;

I2D_TEST(unit_world_mass_and_center_follow_shapes) {
    World world{WorldDef{}};
    const int32_t body = add_body(world, BodyType::dynamic, {10.0f, 0.0f});
    I2D_CHECK(world.bodies()[body].mass == 1.0f);  // no shapes yet: 1 kg
    add_box(world, body, 1.0f, 1.0f);           // 4 kg at the origin
    add_circle(world, body, {3.0f, 0.0f}, 1.0f);  // pi kg at x = 3
    I2D_CHECK_NEAR(world.bodies()[body].mass, 4.0 + pi_d, 1e-5);
    I2D_CHECK_NEAR(world.bodies()[body].local_center.x, 3.0 * pi_d / (4.0 + pi_d), 1e-5);
    I2D_CHECK_NEAR(world.bodies()[body].center.x, 10.0 + 3.0 * pi_d / (4.0 + pi_d), 1e-5);
    I2D_CHECK_NEAR(world.bodies()[body].inv_mass, 1.0 / (4.0 + pi_d), 1e-6);
}

I2D_TEST(unit_world_static_and_kinematic_have_no_mass) {
    World world{WorldDef{}};
    const int32_t s = add_box_body(world, BodyType::static_body, {}, 1.0f, 1.0f);
    const int32_t k = add_box_body(world, BodyType::kinematic, {}, 1.0f, 1.0f);
    I2D_CHECK(world.bodies()[s].mass == 0.0f && world.bodies()[s].inv_mass == 0.0f);
    I2D_CHECK(world.bodies()[k].mass == 0.0f && world.bodies()[k].inv_mass == 0.0f);
}

// Extents bound how fast a body's points move when it turns; a static body never moves,
// so it has none, and adding or taking away its shapes costs the same however many it
// has. A kinematic body's follow its shapes (a spinning drum is not resting), and it
// keeps them when it is made static and gets them back when made kinematic again.
I2D_TEST(unit_world_static_bodies_have_no_extents) {
    World world{WorldDef{}};
    const int32_t s = add_box_body(world, BodyType::static_body, {}, 1.0f, 1.0f);
    const int32_t k = add_box_body(world, BodyType::kinematic, {}, 1.0f, 1.0f);
    add_circle(world, s, {5.0f, 0.0f}, 0.5f);
    add_circle(world, k, {5.0f, 0.0f}, 0.5f);
    I2D_CHECK(world.bodies()[s].max_extent == 0.0f && world.bodies()[s].min_extent == 0.0f);
    I2D_CHECK_NEAR(world.bodies()[k].max_extent, 5.5, 1e-6);
    I2D_CHECK_NEAR(world.bodies()[k].min_extent, 0.5, 1e-6);
    world.set_type(k, BodyType::static_body);
    I2D_CHECK(world.bodies()[k].max_extent == 0.0f && world.bodies()[k].min_extent == 0.0f);
    world.set_type(k, BodyType::kinematic);
    I2D_CHECK_NEAR(world.bodies()[k].max_extent, 5.5, 1e-6);
}

I2D_TEST(unit_world_destroying_shapes_keeps_lists_consistent) {
    World world{WorldDef{}};
    const int32_t body = add_body(world, BodyType::dynamic, {});
    const int32_t a = add_box(world, body, 1.0f, 1.0f);
    const int32_t b = add_box(world, body, 0.5f, 0.5f);
    const int32_t c = add_box(world, body, 0.25f, 0.25f);
    world.destroy_shape(b);  // from the middle of the list
    I2D_CHECK(world.bodies()[body].shape_count == 2);
    int32_t seen = 0;
    for (int32_t s = world.bodies()[body].head_shape; s != null_index; s = world.shapes()[s].next_in_body) {
        I2D_CHECK(s == a || s == c);
        ++seen;
    }
    I2D_CHECK(seen == 2);
    I2D_CHECK_NEAR(world.bodies()[body].mass, 4.0 + 0.25, 1e-6);
    world.destroy_body(body);
    I2D_CHECK(world.shapes().count() == 0 && world.bodies().count() == 0);
}

I2D_TEST(unit_world_filter_truth_table) {
    Filter a, b;
    I2D_CHECK(should_collide(a, b));
    b.mask_bits = 0x2;  // b ignores category 1
    I2D_CHECK(!should_collide(a, b));
    b.mask_bits = ~uint64_t(0);
    a.category_bits = 0x4, b.mask_bits = 0x4;
    I2D_CHECK(should_collide(a, b));
    a.mask_bits = 0x0;
    I2D_CHECK(!should_collide(a, b));
    // Groups override the bits: same positive group always, same negative group never.
    a.group_index = b.group_index = 3;
    I2D_CHECK(should_collide(a, b));
    a = b = Filter{};
    a.group_index = b.group_index = -3;
    I2D_CHECK(!should_collide(a, b));
    b.group_index = -4;  // different groups fall back to the bits
    I2D_CHECK(should_collide(a, b));
}

I2D_TEST(unit_world_no_contacts_between_static_and_kinematic) {
    World world{WorldDef{}};
    add_box_body(world, BodyType::static_body, {}, 1.0f, 1.0f);
    add_box_body(world, BodyType::kinematic, {0.5f, 0.0f}, 1.0f, 1.0f);
    unit::step(world, 1);
    I2D_CHECK(world.counters().pair_count == 0);
    add_box_body(world, BodyType::dynamic, {0.0f, 1.5f}, 0.5f, 0.6f);
    world.step(time_step, 1);
    I2D_CHECK(world.counters().pair_count == 2);
    I2D_CHECK(world.counters().contact_count == 2);
}

I2D_TEST(unit_world_shapes_on_one_body_never_collide) {
    World world{WorldDef{}};
    const int32_t d = add_body(world, BodyType::dynamic, {});
    add_box(world, d, 1.0f, 1.0f);
    add_box(world, d, 1.0f, 1.0f);
    world.step(time_step, 1);
    I2D_CHECK(world.counters().pair_count == 0);
}
