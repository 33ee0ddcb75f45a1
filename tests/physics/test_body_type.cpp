// SPDX-License-Identifier: MIT
// i2d_body_set_type: a body changed between static, kinematic and dynamic moves as its
// new type must (free fall from rest, a stop, velocity kept), its contacts follow the
// new type (and report their end), and what touched it wakes.
#include <impulse2d/impulse2d.h>

#include <cmath>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// Drop after n substeps of semi-implicit Euler from rest: g h^2 n (n + 1) / 2.
double euler_drop(double g, int steps) {
    const int n = steps * substeps;
    return g * substep * substep * double(n) * double(n + 1) / 2.0;
}

bool touching(i2d_world_id world) { return i2d_world_get_counters(world).contact_count > 0; }

}  // namespace

I2D_TEST(phys_body_type_static_made_dynamic_falls_from_rest) {
    Scene s;
    const i2d_body_id box = s.box(body_def(I2D_BODY_STATIC, i2d_vec2{0, 10}), 0.5f, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(s.step(30));
    I2D_CHECK(position(box).y == 10.0f);
    I2D_CHECK(i2d_body_get_mass(box) == 0.0f);
    I2D_REQUIRE(i2d_body_set_type(box, I2D_BODY_DYNAMIC) == I2D_OK);
    I2D_CHECK(i2d_body_get_type(box) == I2D_BODY_DYNAMIC);
    I2D_CHECK_NEAR(i2d_body_get_mass(box), box_mass(0.5, 0.25, 1.0), 1e-6);
    I2D_CHECK(i2d_body_is_awake(box));
    const int steps = steps_for(1.0);
    I2D_REQUIRE(s.step(steps));
    I2D_CHECK_NEAR(10.0 - position(box).y, euler_drop(g, steps), 1e-3);
}

I2D_TEST(phys_body_type_dynamic_made_static_stops_and_carries_a_box) {
    Scene s(Scene::zero_gravity_def());
    const i2d_body_id plank = s.dynamic_box(i2d_vec2{0, 0}, 3.0f, 0.25f, Material{}, i2d_vec2{1.0f, -2.0f});
    I2D_REQUIRE(!I2D_IS_NULL(plank));
    I2D_REQUIRE(s.step(10));
    I2D_REQUIRE(i2d_body_set_type(plank, I2D_BODY_STATIC) == I2D_OK);
    I2D_CHECK(speed(velocity(plank)) == 0.0);
    I2D_CHECK(i2d_body_get_angular_velocity(plank) == 0.0f);
    const i2d_vec2 at = position(plank);
    I2D_REQUIRE(i2d_world_set_gravity(s.world, i2d_vec2{0, -10}) == I2D_OK);
    // A box dropped on it comes to rest on its top face, and the plank never moves.
    const i2d_body_id box = s.dynamic_box(i2d_vec2{at.x, at.y + 2.0f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(s.step(steps_for(2.0)));
    I2D_CHECK(position(plank).x == at.x && position(plank).y == at.y);
    I2D_CHECK_NEAR(position(box).y, at.y + 0.25 + 0.5, 0.01);
    I2D_CHECK(speed(velocity(box)) < 1e-3);
}

I2D_TEST(phys_body_type_kinematic_made_dynamic_keeps_its_velocity) {
    Scene s;
    const i2d_body_id body = s.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, 50}, i2d_vec2{2.0f, 0.0f}), 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    I2D_REQUIRE(s.step(30));
    I2D_CHECK(velocity(body).y == 0.0f);  // gravity does not move a kinematic body
    I2D_REQUIRE(i2d_body_set_type(body, I2D_BODY_DYNAMIC) == I2D_OK);
    I2D_CHECK(velocity(body).x == 2.0f);
    const int steps = steps_for(0.5);
    I2D_REQUIRE(s.step(steps));
    I2D_CHECK_NEAR(velocity(body).x, 2.0, 1e-6);
    I2D_CHECK_NEAR(velocity(body).y, -g * 0.5, 1e-4);
    // And back: kinematic bodies keep their velocity and ignore gravity.
    I2D_REQUIRE(i2d_body_set_type(body, I2D_BODY_KINEMATIC) == I2D_OK);
    const i2d_vec2 v = velocity(body);
    I2D_REQUIRE(s.step(30));
    I2D_CHECK(velocity(body).x == v.x && velocity(body).y == v.y);
    I2D_CHECK(i2d_body_get_mass(body) == 0.0f);
}

// A sleeping pile on a static floor made dynamic wakes and falls with its floor.
I2D_TEST(phys_body_type_floor_made_dynamic_wakes_the_pile_on_it) {
    Scene s;
    const i2d_body_id floor = s.box(body_def(I2D_BODY_STATIC, i2d_vec2{0, 0}), 5.0f, 0.5f);
    const std::vector<i2d_body_id> boxes = s.column(0.0f, 3, 0.5f);  // on the floor's top face
    I2D_REQUIRE(boxes.size() == 3);
    I2D_REQUIRE(s.step(steps_for(3.0)));
    I2D_REQUIRE(!i2d_body_is_awake(boxes[2]));
    const double top = position(boxes[2]).y;
    I2D_REQUIRE(i2d_body_set_type(floor, I2D_BODY_DYNAMIC) == I2D_OK);
    for (const i2d_body_id box : boxes) {
        I2D_CHECK(i2d_body_is_awake(box));
    }
    I2D_REQUIRE(s.step(steps_for(1.0)));
    // Everything falls together, about as far as a free fall.
    I2D_CHECK(top - position(boxes[2]).y > 4.5);
    I2D_CHECK(position(floor).y < -4.5f);
}

// A box resting on a static floor made static: the pair can no longer collide, so its
// contact ends (reported at the next step) and does not begin again.
I2D_TEST(phys_body_type_resting_box_made_static_ends_its_contact) {
    Scene s;
    I2D_REQUIRE(!I2D_IS_NULL(s.ground()));
    const i2d_body_id box = s.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box));
    I2D_REQUIRE(s.step(30));
    I2D_REQUIRE(touching(s.world));
    I2D_REQUIRE(i2d_body_set_type(box, I2D_BODY_STATIC) == I2D_OK);
    I2D_REQUIRE(s.step());
    const i2d_contact_events events = i2d_world_get_contact_events(s.world);
    I2D_CHECK(events.end_count == 1);
    I2D_CHECK(events.begin_count == 0);
    I2D_REQUIRE(s.step(10));
    I2D_CHECK(!touching(s.world));
    // Made dynamic again, it rests on the floor once more and its contact begins anew.
    I2D_REQUIRE(i2d_body_set_type(box, I2D_BODY_DYNAMIC) == I2D_OK);
    I2D_REQUIRE(s.step());
    I2D_CHECK(i2d_world_get_contact_events(s.world).begin_count == 1);
    I2D_REQUIRE(s.step(30));
    I2D_CHECK(touching(s.world));
    I2D_CHECK_NEAR(position(box).y, 0.5, 0.01);
}

// Every change of type, in a pile being stepped, leaves a world that steps on (the
// Debug build cross-checks every structure after each step).
I2D_TEST(phys_body_type_every_change_in_a_moving_pile) {
    Scene s;
    I2D_REQUIRE(!I2D_IS_NULL(s.ground()));
    i2d_body_id bodies[12];
    for (int i = 0; i < 12; ++i) {
        bodies[i] = s.dynamic_box(i2d_vec2{-2.5f + float(i % 4) * 1.2f, 0.6f + float(i / 4) * 1.1f}, 0.5f, 0.5f);
        I2D_REQUIRE(!I2D_IS_NULL(bodies[i]));
    }
    const i2d_body_type order[] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC, I2D_BODY_KINEMATIC,
                                   I2D_BODY_STATIC, I2D_BODY_DYNAMIC};
    for (int round = 0; round < 6; ++round) {
        for (int i = round % 3; i < 12; i += 3) {
            I2D_REQUIRE(i2d_body_set_type(bodies[i], order[(round + i) % 6]) == I2D_OK);
            I2D_CHECK(i2d_body_get_type(bodies[i]) == order[(round + i) % 6]);
        }
        I2D_REQUIRE(s.step(20));
        for (const i2d_body_id b : bodies) {
            I2D_CHECK(std::isfinite(position(b).x) && std::isfinite(position(b).y));
        }
    }
}
