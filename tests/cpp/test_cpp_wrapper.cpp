// SPDX-License-Identifier: MIT
// The C++17 wrappers (include/impulse2d/impulse2d.hpp): ownership, value handles, and both
// error styles, checked against the C calls they wrap.
#include <impulse2d/impulse2d.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "check.h"

namespace {

static_assert(!std::is_copy_constructible_v<impulse2d::World>, "a World owns its world");
static_assert(std::is_nothrow_move_constructible_v<impulse2d::World>, "and moves cheaply");
static_assert(sizeof(impulse2d::Body) == sizeof(i2d_body_id) && sizeof(impulse2d::Shape) == sizeof(i2d_shape_id),
              "handles are the 8-byte ids");

impulse2d::Body make_ground(impulse2d::World& world) {
    impulse2d::Body ground = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, -1.0f}));
    ground.create_box(20.0f, 1.0f);
    return ground;
}

bool message_has(const std::string& message, const char* text) { return message.find(text) != std::string::npos; }

}  // namespace

I2D_TEST(cpp_world_owns_and_destroys) {
    i2d_world_id raw{0};
    impulse2d::Body body;
    {
        impulse2d::World world;
        raw = world.id();
        body = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC));
        I2D_CHECK(world.valid() && body.valid());
        impulse2d::World moved = std::move(world);
        I2D_CHECK(moved.id().bits == raw.bits && world.id().bits == 0);
        I2D_CHECK(i2d_world_is_valid(raw));
    }
    I2D_CHECK(!i2d_world_is_valid(raw));  // destroyed at the end of the scope
    I2D_CHECK(!body.valid());

    impulse2d::World a, b;
    const i2d_world_id first = a.id();
    a = std::move(b);  // a's old world is destroyed, b's is now a's
    I2D_CHECK(!i2d_world_is_valid(first) && a.valid() && !b.valid());
    const i2d_world_id released = a.release();
    I2D_CHECK(i2d_world_is_valid(released));
    i2d_world_destroy(released);
}

I2D_TEST(cpp_handles_match_the_c_calls) {
    impulse2d::World world;
    impulse2d::Body ground = make_ground(world);
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 4.0f}, 0.25f));
    i2d_shape_def bouncy = i2d_default_shape_def();
    bouncy.restitution = 0.5f;
    impulse2d::Shape shape = ball.create_circle(0.5f, {0.0f, 0.0f}, bouncy);
    I2D_CHECK(shape.body() == ball && ball.shapes().size() == 1 && ball.shapes()[0] == shape);
    I2D_CHECK(shape.type() == I2D_SHAPE_CIRCLE && shape.restitution() == 0.5f);
    I2D_CHECK_NEAR(ball.angle(), 0.25, 1e-6);
    for (int i = 0; i < 120; ++i) {
        world.step(1.0f / 60.0f, 4);
    }
    I2D_CHECK_NEAR(ball.position().y, 0.5, 0.01);
    const i2d_vec2 c = i2d_body_get_position(ball.id());
    I2D_CHECK(ball.position().x == c.x && ball.position().y == c.y);
    I2D_CHECK(ground.type() == I2D_BODY_STATIC && ground.mass() == 0.0f);
    I2D_CHECK(!ball.quarantined() && world.body_events().quarantine_count == 0);
    I2D_CHECK(world.counters().body_count == 2);
    I2D_CHECK(world.overlap_aabb(i2d_aabb{{-1.0f, 0.0f}, {1.0f, 1.0f}}).size() == 2);
    I2D_CHECK(world.cast_ray_closest({0.0f, 5.0f}, {0.0f, -10.0f}).shape.bits == shape.id().bits);

    std::vector<impulse2d::Body> bodies = {ground, ball};
    std::vector<i2d_transform> xf = world.transforms(bodies);
    const i2d_transform ball_xf = ball.transform();
    I2D_CHECK(xf.size() == 2 && std::memcmp(&xf[1], &ball_xf, sizeof ball_xf) == 0);
    xf[1].p.y = 3.0f;
    world.set_transforms(bodies, xf);
    world.set_velocities(bodies, {{0.0f, 0.0f}, {1.0f, 0.0f}}, {0.0f, 2.0f});
    I2D_CHECK(ball.position().y == 3.0f && ball.linear_velocity().x == 1.0f && ball.angular_velocity() == 2.0f);
    world.shift_origin({100.0f, -20.0f});
    I2D_CHECK(ball.position().x == xf[1].p.x - 100.0f && ball.position().y == 23.0f);
}

I2D_TEST(cpp_errors_throw_by_default) {
    impulse2d::World world;
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC));
    bool threw = false;
    try {
        ball.set_linear_velocity({NAN, 0.0f});
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT && message_has(e.what(), "velocity.x is NaN");
    }
    I2D_CHECK(threw);
    ball.destroy();
    threw = false;
    try {
        (void)ball.position();
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_HANDLE;
    }
    I2D_CHECK(threw);
    threw = false;
    try {
        world.set_velocities({ball}, {}, {});
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT && message_has(e.what(), "1 bodies but 0 values");
    }
    I2D_CHECK(threw);
    i2d_world_def bad = i2d_default_world_def();
    bad.gravity.x = INFINITY;
    threw = false;
    try {
        impulse2d::World refused(bad);
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT && message_has(e.what(), "gravity.x");
    }
    I2D_CHECK(threw);
}

I2D_TEST(cpp_errors_as_status_when_asked) {
    impulse2d::World world;
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC));
    impulse2d::Status status;
    ball.set_linear_velocity({1.0f, 2.0f}, status);
    I2D_CHECK(status.ok() && static_cast<bool>(status) && status.message.empty());
    ball.set_linear_velocity({NAN, 0.0f}, status);
    I2D_CHECK(!status && status.code == I2D_ERR_INVALID_ARGUMENT && message_has(status.message, "NaN"));
    I2D_CHECK(ball.linear_velocity().x == 1.0f);  // untouched
    impulse2d::Shape none = ball.create_circle(-1.0f, {0.0f, 0.0f}, i2d_default_shape_def(), status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && none.id().bits == 0);
    world.step(NAN, 4, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT);
    i2d_body_def undefined;
    std::memset(&undefined, 0, sizeof undefined);
    impulse2d::Body refused = world.create_body(undefined, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && !refused.valid() && message_has(status.message, "i2d_default_body_def"));
    i2d_world_def bad = i2d_default_world_def();
    bad.contact_hertz = -1.0f;
    impulse2d::World null_world(bad, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && !null_world.valid());
}

I2D_TEST(cpp_joints) {
    static_assert(sizeof(impulse2d::Joint) == sizeof(i2d_joint_id), "a Joint is the 8-byte id");
    impulse2d::World world;
    impulse2d::Body ground = make_ground(world);
    impulse2d::Body box = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 3.0f}));
    box.create_box(0.5f, 0.5f);

    i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
    def.base.body_a = ground.id();
    def.base.body_b = box.id();
    def.base.local_anchor_a = {0.0f, 4.0f};
    def.base.local_anchor_b = {0.0f, 1.0f};
    impulse2d::Joint hinge = world.create_joint(def);
    I2D_CHECK(hinge.valid() && hinge.type() == I2D_JOINT_REVOLUTE && world.joint_count() == 1);
    I2D_CHECK(hinge.body_a() == ground && hinge.body_b() == box);
    hinge.set(i2d_revolute_joint_set_motor_speed, 2.0f);
    hinge.set(i2d_revolute_joint_set_enable_motor, true);
    hinge.set(i2d_revolute_joint_set_limits, -0.5f, 0.5f);
    I2D_CHECK(hinge.get(i2d_revolute_joint_get_motor_speed) == 2.0f);
    I2D_CHECK(hinge.get(i2d_revolute_joint_get_enable_motor));
    I2D_CHECK(hinge.get(i2d_revolute_joint_get_upper_angle) == 0.5f);
    int marker = 0;
    hinge.set_user_data(&marker);
    I2D_CHECK(hinge.user_data() == &marker);

    // Both error styles.
    bool threw = false;
    try {
        hinge.set(i2d_revolute_joint_set_hertz, -1.0f);
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT && message_has(e.what(), "hertz");
    }
    I2D_CHECK(threw);
    threw = false;
    try {
        (void)hinge.get(i2d_distance_joint_get_length);
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT;
    }
    I2D_CHECK(threw);
    impulse2d::Status status;
    def.base.body_b = ground.id();
    impulse2d::Joint refused = world.create_joint(def, status);
    I2D_CHECK(!status.ok() && message_has(status.message, "same body") && !refused.valid());
    hinge.set(i2d_revolute_joint_set_max_motor_torque, -1.0f, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT);

    world.step();
    I2D_CHECK(world.joint_events().count == 0);
    box.destroy();
    I2D_CHECK(!hinge.valid() && world.joint_count() == 0);
}
