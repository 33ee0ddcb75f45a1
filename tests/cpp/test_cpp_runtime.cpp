// SPDX-License-Identifier: MIT
// The C++17 wrappers of the run-time API (issue 40): body and shape settings, contact
// data, sensor overlaps, shape distance and the world's settings, each checked by a
// closed-form figure or a round trip, and a refused call in both error styles.
#include <impulse2d/impulse2d.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "check.h"
#include "cpp_fixture.hpp"

using cpp_fixture::make_ground;
using cpp_fixture::step_seconds;
using cpp_fixture::throws;

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

I2D_TEST(cpp_runtime_mass_override_gives_f_equals_m_a) {
    impulse2d::World world;
    world.set_gravity({0.0f, 0.0f});
    impulse2d::Body box = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC));
    box.create_box(0.5f, 0.5f);  // 1 kg from its density
    I2D_CHECK_NEAR(box.mass_data().mass, 1.0, 1e-6);
    box.set_mass_data({4.0f, {0.0f, 0.0f}, 2.0f});
    const i2d_mass_data data = box.mass_data();
    I2D_CHECK(data.mass == 4.0f && data.rotational_inertia == 2.0f);
    box.apply_force_to_center({8.0f, 0.0f});
    world.step(1.0f / 60.0f, 4);
    I2D_CHECK_NEAR(box.linear_velocity().x, 8.0 / 4.0 / 60.0, 1e-6);  // a = F / m for one step
    box.apply_mass_from_shapes();
    I2D_CHECK_NEAR(box.mass(), 1.0, 1e-6);

    I2D_CHECK(throws([&] { box.set_mass_data({-1.0f, {0.0f, 0.0f}, 1.0f}); }, I2D_ERR_INVALID_ARGUMENT, "mass"));
    impulse2d::Body ground = world.create_body(impulse2d::body_def(I2D_BODY_STATIC));
    impulse2d::Status status;
    ground.set_mass_data({1.0f, {0.0f, 0.0f}, 1.0f}, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && ground.mass() == 0.0f);
}

I2D_TEST(cpp_runtime_body_settings_round_trip) {
    impulse2d::World world;
    impulse2d::Body body = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC));
    body.create_circle(0.5f);
    body.set_bullet(true);
    body.enable_sleep(false);
    body.set_sleep_threshold(0.25f);
    body.set_gravity_scale(-0.5f);
    body.set_linear_damping(0.75f);
    body.set_angular_damping(1.5f);
    body.set_fixed_rotation(true);
    I2D_CHECK(body.bullet() && !body.sleep_enabled() && body.fixed_rotation());
    I2D_CHECK(body.sleep_threshold() == 0.25f && body.gravity_scale() == -0.5f);
    I2D_CHECK(body.linear_damping() == 0.75f && body.angular_damping() == 1.5f);
    impulse2d::Status status;
    body.set_linear_damping(-1.0f, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && body.linear_damping() == 0.75f);
    I2D_CHECK(throws([&] { body.set_gravity_scale(NAN); }, I2D_ERR_INVALID_ARGUMENT, "NaN"));

    // A kinematic body sent to a target arrives there in one step.
    impulse2d::Body platform = world.create_body(impulse2d::body_def(I2D_BODY_KINEMATIC));
    platform.create_box(1.0f, 0.1f);
    platform.set_target_transform({{0.5f, 0.25f}, i2d_make_rot(0.0f)}, 1.0f / 60.0f);
    world.step(1.0f / 60.0f, 4);
    I2D_CHECK_NEAR(platform.position().x, 0.5, 1e-5);
    I2D_CHECK_NEAR(platform.position().y, 0.25, 1e-5);
    I2D_CHECK(throws([&] { body.set_target_transform({{0.0f, 0.0f}, i2d_make_rot(0.0f)}, 1.0f); },
                     I2D_ERR_INVALID_ARGUMENT, ""));
}

I2D_TEST(cpp_runtime_disable_lets_what_rests_on_it_fall) {
    impulse2d::World world;
    impulse2d::Body shelf = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, 5.0f}));
    shelf.create_box(2.0f, 0.1f);
    impulse2d::Body box = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 5.6f}));
    box.create_box(0.5f, 0.5f);
    step_seconds(world, 1.0f);
    const float resting = box.position().y;
    I2D_CHECK_NEAR(resting, 5.6, 0.02);
    shelf.disable();
    I2D_CHECK(!shelf.enabled() && box.enabled());
    step_seconds(world, 0.5f);
    I2D_CHECK(box.position().y < resting - 1.0f);  // g t^2 / 2 = 1.25 m
    shelf.enable();
    I2D_CHECK(shelf.enabled());
    shelf.destroy();
    impulse2d::Status status;
    shelf.disable(status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(throws([&] { (void)shelf.enabled(); }, I2D_ERR_INVALID_HANDLE, ""));
}

I2D_TEST(cpp_runtime_contact_data_of_a_resting_box) {
    impulse2d::World world;
    impulse2d::Shape ground = make_ground(world);
    impulse2d::Body box = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 0.5f}));
    impulse2d::Shape shape = box.create_box(0.5f, 0.5f);
    step_seconds(world, 1.0f);
    const std::vector<i2d_contact_data> contacts = box.contact_data();
    I2D_REQUIRE(contacts.size() == 1);
    const i2d_contact_data& c = contacts[0];
    I2D_CHECK(c.shape_a.bits == ground.id().bits && c.shape_b.bits == shape.id().bits);
    I2D_CHECK(c.manifold.point_count == 2);
    I2D_CHECK_NEAR(c.manifold.normal.x, 0.0, 1e-6);
    I2D_CHECK_NEAR(c.manifold.normal.y, 1.0, 1e-6);
    // Normal impulses of the last substep: m g time_step / substep_count in all.
    I2D_CHECK_NEAR(c.normal_impulses[0] + c.normal_impulses[1], 1.0 * 10.0 / 60.0 / 4.0, 1e-3);
    I2D_CHECK(shape.contact_data().size() == 1 && ground.contact_data().size() == 1);
}

I2D_TEST(cpp_runtime_shape_settings) {
    impulse2d::World world;
    make_ground(world);
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 0.5f}));
    impulse2d::Shape circle = ball.create_circle(0.5f);
    step_seconds(world, 0.5f);
    I2D_CHECK_NEAR(ball.position().y, 0.5, 0.02);
    circle.set_circle({{0.0f, 0.0f}, 1.0f});  // grown: pushed up to rest on its new radius
    step_seconds(world, 1.0f);
    I2D_CHECK_NEAR(ball.position().y, 1.0, 0.02);
    I2D_CHECK_NEAR(ball.mass(), kPi, 1e-4);
    circle.set_density(2.0f);
    I2D_CHECK(circle.density() == 2.0f);
    I2D_CHECK_NEAR(ball.mass(), 2.0 * kPi, 1e-4);
    circle.set_capsule({{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f});
    I2D_CHECK(circle.type() == I2D_SHAPE_CAPSULE);
    circle.set_polygon(i2d_make_box(0.5f, 0.5f));
    I2D_CHECK(circle.type() == I2D_SHAPE_POLYGON);
    circle.set_segment({{-1.0f, 0.0f}, {1.0f, 0.0f}});
    I2D_CHECK(circle.type() == I2D_SHAPE_SEGMENT);
    impulse2d::Status status;
    circle.set_circle({{0.0f, 0.0f}, -1.0f}, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && circle.type() == I2D_SHAPE_SEGMENT);

    const i2d_surface_material material = {0.25f, 0.5f, 0.125f, 1.5f};
    circle.set_material(material);
    const i2d_surface_material back = circle.material();
    I2D_CHECK(back.friction == 0.25f && back.restitution == 0.5f && back.rolling_resistance == 0.125f &&
              back.tangent_speed == 1.5f);
    I2D_CHECK(throws([&] { circle.set_material({-1.0f, 0.0f, 0.0f, 0.0f}); }, I2D_ERR_INVALID_ARGUMENT, "friction"));
    circle.enable_sensor_events(false);
    circle.enable_contact_events(false);
    circle.enable_hit_events(true);
    I2D_CHECK(!circle.sensor_events_enabled() && !circle.contact_events_enabled() && circle.hit_events_enabled());

    circle.set_circle({{0.0f, 0.0f}, 0.5f});
    const i2d_vec2 p = ball.position();
    const i2d_vec2 closest = circle.closest_point({p.x + 3.0f, p.y});
    I2D_CHECK_NEAR(closest.x, p.x + 0.5f, 1e-5);
    I2D_CHECK_NEAR(closest.y, p.y, 1e-5);
}

I2D_TEST(cpp_runtime_sensor_overlaps) {
    impulse2d::World world;
    impulse2d::Shape ground = make_ground(world);
    impulse2d::Body zone = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, 1.0f}));
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    impulse2d::Shape sensor = zone.create_box(2.0f, 2.0f, sensor_def);
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 0.5f}));
    impulse2d::Shape visitor = ball.create_circle(0.5f);
    world.step();
    const std::vector<impulse2d::Shape> overlaps = sensor.sensor_overlaps();
    I2D_CHECK(overlaps.size() == 1 && overlaps[0] == visitor);
    I2D_CHECK(throws([&] { (void)ground.sensor_overlaps(); }, I2D_ERR_INVALID_ARGUMENT, "sensor"));
}

I2D_TEST(cpp_runtime_shape_distance) {
    const i2d_vec2 center = {0.0f, 0.0f};
    const i2d_shape_proxy circle = i2d_make_proxy(&center, 1, 0.5f);
    const i2d_transform at_origin = {{0.0f, 0.0f}, i2d_make_rot(0.0f)};
    const i2d_transform apart = {{3.0f, 0.0f}, i2d_make_rot(0.0f)};
    const i2d_distance_result d = impulse2d::shape_distance(circle, at_origin, circle, apart);
    I2D_CHECK_NEAR(d.distance, 2.0, 1e-5);
    I2D_CHECK_NEAR(d.normal.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(d.point_a.x, 0.5, 1e-5);
    I2D_CHECK_NEAR(d.point_b.x, 2.5, 1e-5);
    i2d_shape_proxy none = circle;
    none.count = 0;
    I2D_CHECK(throws([&] { (void)impulse2d::shape_distance(none, at_origin, circle, apart); },
                     I2D_ERR_INVALID_ARGUMENT, ""));
    impulse2d::Status status;
    (void)impulse2d::shape_distance(circle, at_origin, circle, apart, status);
    I2D_CHECK(status.ok());
}

I2D_TEST(cpp_runtime_world_settings) {
    impulse2d::World world;
    int marker = 0;
    I2D_CHECK(world.user_data() == nullptr);
    world.set_user_data(&marker);
    I2D_CHECK(world.user_data() == &marker);
    world.enable_sleeping(false);
    world.enable_continuous(false);
    world.enable_impact_chains(false);
    world.set_contact_tuning(20.0f, 5.0f, 2.0f);
    world.set_joint_tuning(30.0f, 1.5f);
    world.set_restitution_threshold(0.5f);
    world.set_hit_event_threshold(2.5f);
    const i2d_world_def s = world.settings();
    I2D_CHECK(!s.enable_sleep && !s.enable_continuous && !s.enable_impact_chains);
    I2D_CHECK(s.contact_hertz == 20.0f && s.contact_damping_ratio == 5.0f && s.contact_push_max_speed == 2.0f);
    I2D_CHECK(s.joint_hertz == 30.0f && s.joint_damping_ratio == 1.5f);
    I2D_CHECK(s.restitution_threshold == 0.5f && s.hit_event_threshold == 2.5f);
    impulse2d::World like(s);  // the settings make a world like it
    I2D_CHECK(like.settings().contact_hertz == 20.0f);
    impulse2d::Status status;
    world.set_contact_tuning(-1.0f, 5.0f, 2.0f, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && world.settings().contact_hertz == 20.0f);
    I2D_CHECK(throws([&] { world.set_hit_event_threshold(NAN); }, I2D_ERR_INVALID_ARGUMENT, ""));
    world.shift_origin({NAN, 0.0f}, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT);
}

I2D_TEST(cpp_runtime_world_in_units) {
    const i2d_world_def metres = i2d_default_world_def();
    const i2d_world_def def = impulse2d::world_def_in_units(50.0f);
    I2D_CHECK(def.length_units_per_meter == 50.0f && def.gravity.y == 50.0f * metres.gravity.y);
    impulse2d::World world(def);
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 1000.0f}));
    ball.create_circle(25.0f);
    step_seconds(world, 1.0f);
    // The same fall as in metres, in units: g t^2 / 2 = 5 m = 250 units.
    I2D_CHECK_NEAR(ball.position().y, 1000.0 - 250.0, 5.0);
    I2D_CHECK(world.settings().length_units_per_meter == 50.0f);
    I2D_CHECK(throws([] { (void)impulse2d::world_def_in_units(0.0f); }, I2D_ERR_INVALID_ARGUMENT, ""));
    impulse2d::Status status;
    (void)impulse2d::world_def_in_units(1e5f, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT);
}
