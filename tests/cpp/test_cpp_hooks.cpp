// SPDX-License-Identifier: MIT
// The C++17 wrappers of the contact hooks and explosions (issue 39): a one-way platform
// through Shape::enable_pre_solve_events and World::set_pre_solve, an explosion's closed
// form through World::explode, and refusals in both error styles.
#include <impulse2d/impulse2d.hpp>

#include <cmath>

#include "check.h"
#include "cpp_fixture.hpp"

using cpp_fixture::make_ground;
using cpp_fixture::step_seconds;
using cpp_fixture::throws;

namespace {

constexpr float kPlatformTop = 3.0f;
constexpr float kCrateHalf = 0.25f;

// The platform is the shape in context; the contact acts only when it pushes up.
bool pushes_up_only(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* m, void* context) {
    const i2d_shape_id platform = *static_cast<const i2d_shape_id*>(context);
    const float sign = a.bits == platform.bits ? 1.0f : b.bits == platform.bits ? -1.0f : 0.0f;
    return sign * m->normal.y > 0.95f;
}

// Where a crate launched up at 9 m/s from under the platform is after 3 s.
float crate_height_after_jump(bool hooked) {
    impulse2d::World world;
    make_ground(world);
    impulse2d::Body holder = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, kPlatformTop - 0.1f}));
    impulse2d::Shape platform = holder.create_box(2.0f, 0.1f);
    i2d_shape_id platform_id = platform.id();
    if (hooked) {
        platform.enable_pre_solve_events(true);
        world.set_pre_solve(pushes_up_only, &platform_id);
    }
    i2d_body_def def = impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, kCrateHalf});
    def.linear_velocity = {0.0f, 9.0f};
    impulse2d::Body crate = world.create_body(def);
    crate.create_box(kCrateHalf, kCrateHalf);
    step_seconds(world, 3.0f);
    return crate.position().y;
}

}  // namespace

I2D_TEST(cpp_hooks_one_way_platform) {
    I2D_CHECK_NEAR(crate_height_after_jump(true), kPlatformTop + kCrateHalf, 0.01);
    I2D_CHECK(crate_height_after_jump(false) < kPlatformTop);  // the control: stopped beneath
}

I2D_TEST(cpp_hooks_explosion_speed_and_refusals) {
    i2d_world_def def = i2d_default_world_def();
    def.gravity = {0.0f, 0.0f};
    impulse2d::World world(def);
    impulse2d::Body disc = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {1.5f, 0.0f}));
    disc.create_circle(0.5f);
    i2d_explosion_def blast = i2d_default_explosion_def();
    blast.radius = 2.0f;
    blast.impulse_per_length = 4.0f;
    world.explode(blast);
    // impulse_per_length x the disc's width (2r) over its mass (pi r^2 at density 1).
    const double expected = 4.0 * 1.0 / (3.14159265358979323846 * 0.25);
    I2D_CHECK_NEAR(disc.linear_velocity().x, expected, 1e-5 * expected);

    blast.radius = -1.0f;
    I2D_CHECK(throws([&] { world.explode(blast); }, I2D_ERR_INVALID_ARGUMENT, "radius"));
    impulse2d::Status status;
    world.explode(blast, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT);
}
