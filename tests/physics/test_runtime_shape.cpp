// SPDX-License-Identifier: MIT
// A shape's settings changed after creation (issue 40), against closed form: geometry
// (the kind may change), density, the surface material and the event flags.
#include <cmath>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

/** How far a resting shape may sit off its closed-form height: the contact slop the
 *  solver leaves (0.005 m) and a little. */
constexpr double resting_tolerance = 0.01;

i2d_surface_material surface(float friction, float restitution, float rolling = 0.0f, float tangent_speed = 0.0f) {
    i2d_surface_material m;
    m.friction = friction;
    m.restitution = restitution;
    m.rolling_resistance = rolling;
    m.tangent_speed = tangent_speed;
    return m;
}

}  // namespace

I2D_TEST(phys_runtime_circle_grown_on_the_ground_rises) {
    // A 0.5 m circle resting on the ground grows to 1 m: its centre rises by 0.5 m, to its
    // new radius, and its mass follows its area.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    const i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, 0.5f}, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    const double before = position(ball).y;
    I2D_CHECK_NEAR(before, 0.5, resting_tolerance);
    const i2d_circle grown{i2d_vec2{0, 0}, 1.0f};
    I2D_REQUIRE(i2d_shape_set_circle(only_shape(ball), &grown) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(ball));
    I2D_CHECK_NEAR(i2d_body_get_mass(ball), circle_mass(1.0, 1.0), 1e-5);
    I2D_REQUIRE(scene.step(steps_for(2.0)));
    I2D_CHECK_NEAR(position(ball).y - before, 0.5, resting_tolerance);
    I2D_CHECK(i2d_shape_get_circle(only_shape(ball)).radius == 1.0f);
}

I2D_TEST(phys_runtime_circle_turned_box_stops_rolling) {
    // The kind may change: a circle rolling at 2 m/s made a box of the same width slides
    // to rest by friction instead of rolling on, and rests flat at its half height.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    const i2d_body_id body = scene.dynamic_circle(i2d_vec2{0, 0.5f}, 0.5f, Material{}, i2d_vec2{2, 0});
    I2D_REQUIRE(!I2D_IS_NULL(body));
    I2D_REQUIRE(scene.step(steps_for(0.5)));
    const i2d_polygon square = i2d_make_box(0.5f, 0.5f);
    I2D_REQUIRE(i2d_shape_set_polygon(only_shape(body), &square) == I2D_OK);
    I2D_CHECK(i2d_shape_get_type(only_shape(body)) == I2D_SHAPE_POLYGON);
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(body), box_mass(0.5, 0.5, 1.0) / 6.0, 1e-5);
    I2D_REQUIRE(i2d_body_set_transform(body, position(body), rot(0.0)) == I2D_OK);
    I2D_REQUIRE(scene.step(steps_for(2.0)));
    I2D_CHECK_NEAR(speed(velocity(body)), 0.0, 1e-3);
    I2D_CHECK_NEAR(position(body).y, 0.5, resting_tolerance);
    I2D_CHECK_NEAR(angle_of(body), 0.0, 1e-3);
}

I2D_TEST(phys_runtime_density_moves_the_mass) {
    // Two 0.5 m circles at x = -1 and 1: the right one's density from 1 to 3 puts the
    // centre of mass at x = (3 - 1) / (3 + 1) = 0.5. Without the update the mass waits for
    // i2d_body_apply_mass_from_shapes.
    Scene scene(Scene::zero_gravity_def());
    const i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 0});
    const i2d_body_id body = i2d_body_create(scene.world, &def);
    const i2d_shape_def sd = shape_def(Material{});
    const i2d_circle left{i2d_vec2{-1, 0}, 0.5f}, right{i2d_vec2{1, 0}, 0.5f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(body, &sd, &left)));
    const i2d_shape_id heavy = i2d_shape_create_circle(body, &sd, &right);
    I2D_REQUIRE(!I2D_IS_NULL(heavy));
    const double unit = circle_mass(0.5, 1.0);
    I2D_CHECK_NEAR(i2d_body_get_local_center_of_mass(body).x, 0.0, 1e-6);

    I2D_REQUIRE(i2d_shape_set_density(heavy, 3.0f, false) == I2D_OK);
    I2D_CHECK(i2d_shape_get_density(heavy) == 3.0f);
    I2D_CHECK_NEAR(i2d_body_get_mass(body), 2.0 * unit, 1e-5);
    I2D_REQUIRE(i2d_body_apply_mass_from_shapes(body) == I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_mass(body), 4.0 * unit, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_local_center_of_mass(body).x, 0.5, 1e-5);

    I2D_REQUIRE(i2d_shape_set_density(heavy, 1.0f, true) == I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_mass(body), 2.0 * unit, 1e-5);
    I2D_CHECK_NEAR(i2d_body_get_local_center_of_mass(body).x, 0.0, 1e-6);
}

I2D_TEST(phys_runtime_material_turns_a_held_box_loose) {
    // A box on a 30 degree slope holds with friction 0.81 (box 2.2, slope 0.3: their
    // geometric mean; tan 30 = 0.577); its material changed to friction 0.3 (a mean of
    // 0.3), it slides down at g (sin - mu cos) = 2.40 m/s^2.
    const Slope slope{degrees(30.0), 10.0};
    Scene scene;
    const i2d_body_id ramp = scene.slope(slope, with_friction(0.3f));
    const i2d_body_id box = scene.turned_box(I2D_BODY_DYNAMIC, slope.at(0.0, 0.5), slope.theta, 0.5f, 0.5f,
                                             with_friction(2.2f));
    I2D_REQUIRE(!I2D_IS_NULL(ramp) && !I2D_IS_NULL(box));
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    I2D_CHECK_NEAR(slope.along(velocity(box)), 0.0, 1e-3);
    I2D_REQUIRE(i2d_shape_set_material(only_shape(box), surface(0.3f, 0.0f)) == I2D_OK);
    const i2d_surface_material read = i2d_shape_get_material(only_shape(box));
    I2D_CHECK(read.friction == 0.3f && read.restitution == 0.0f);
    const double v0 = slope.along(velocity(box));
    I2D_REQUIRE(scene.step(steps_for(1.0)));
    const double expected = -g * (std::sin(slope.theta) - 0.3 * std::cos(slope.theta));
    I2D_CHECK_NEAR(slope.along(velocity(box)) - v0, expected, 0.02 * std::fabs(expected));
}

I2D_TEST(phys_runtime_material_restitution_bounces) {
    // A ball made elastic (restitution 1, the floor's too; a contact takes the lower)
    // before its 2 m drop comes back up at its impact speed sqrt(2 g h), within 2 %.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f, with_restitution(1.0f))));
    const i2d_body_id ball = scene.dynamic_circle(i2d_vec2{0, 2.5f}, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(ball));
    I2D_REQUIRE(i2d_shape_set_material(only_shape(ball), surface(0.6f, 1.0f)) == I2D_OK);
    double fastest_up = 0.0;
    for (int s = 0; s < steps_for(1.2); ++s) {
        I2D_REQUIRE(scene.step());
        fastest_up = std::max(fastest_up, double(velocity(ball).y));
    }
    const double impact = std::sqrt(2.0 * g * 2.0);
    I2D_CHECK_NEAR(fastest_up, impact, 0.02 * impact);
}

I2D_TEST(phys_runtime_event_flags_take_effect) {
    // Hit events turned on for a falling box report its landing; contact events turned
    // off report no begin for a contact made afterwards.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground()));
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{0, 3}, 0.5f, 0.5f);
    const i2d_body_id quiet = scene.dynamic_box(i2d_vec2{5, 3}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(quiet));
    I2D_REQUIRE(i2d_shape_enable_hit_events(only_shape(box), true) == I2D_OK);
    I2D_REQUIRE(i2d_shape_enable_contact_events(only_shape(quiet), false) == I2D_OK);
    I2D_CHECK(i2d_shape_are_hit_events_enabled(only_shape(box)));
    I2D_CHECK(!i2d_shape_are_contact_events_enabled(only_shape(quiet)));
    int hits = 0, begins_box = 0, begins_quiet = 0;
    for (int s = 0; s < steps_for(1.5); ++s) {
        I2D_REQUIRE(scene.step());
        const i2d_contact_events events = i2d_world_get_contact_events(scene.world);
        hits += events.hit_count;
        for (int k = 0; k < events.begin_count; ++k) {
            const i2d_body_id a = i2d_shape_get_body(events.begin_events[k].shape_a);
            const i2d_body_id b = i2d_shape_get_body(events.begin_events[k].shape_b);
            begins_box += I2D_ID_EQUALS(a, box) || I2D_ID_EQUALS(b, box) ? 1 : 0;
            begins_quiet += I2D_ID_EQUALS(a, quiet) || I2D_ID_EQUALS(b, quiet) ? 1 : 0;
        }
    }
    I2D_CHECK(hits >= 1);
    I2D_CHECK(begins_box == 1);
    I2D_CHECK(begins_quiet == 0);
}
