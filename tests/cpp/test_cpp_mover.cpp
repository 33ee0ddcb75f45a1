// SPDX-License-Identifier: MIT
// The C++17 wrappers of the character mover: a walk against a wall through
// World::move_character, the casts and planes of the low-level calls with their closed
// forms, and a refused move in both error styles.
#include <impulse2d/impulse2d.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "check.h"

namespace {

const i2d_capsule kCapsule{{0.0f, 0.3f}, {0.0f, 1.5f}, 0.3f};

// A ground with its top at y = 0 and a wall whose left face is at x = 3.
void build_room(impulse2d::World& world) {
    world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, -0.5f})).create_box(20.0f, 0.5f);
    world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {3.5f, 1.5f})).create_box(0.5f, 1.5f);
}

}  // namespace

// Walked at 4 m/s for a second, the character ends at the wall with the skin between
// them (and at most the slop more), on the ground, its velocity into the wall gone.
I2D_TEST(cpp_mover_walks_to_wall) {
    impulse2d::World world;
    build_room(world);
    const i2d_character_def def = i2d_default_character_def();
    i2d_vec2 position{0.0f, 0.02f};
    i2d_character_result r{};
    for (int i = 0; i < 60; ++i) {
        r = world.move_character(def, kCapsule, position, {4.0f, r.on_ground ? 0.0f : r.velocity.y - 10.0f / 60.0f});
        position = r.position;
    }
    const double gap = 3.0 - (double(position.x) + 0.3);
    I2D_CHECK(gap >= def.skin - 1e-5 && gap <= def.skin + 0.005);
    I2D_CHECK(r.on_ground);
    I2D_CHECK_NEAR(r.velocity.x, 0.0, 1e-6);
    I2D_CHECK(r.hit_count == 2);
}

// A capsule 1 m above the ground cast 2 m down goes 1 m less the stop gap (between a half
// and three quarters of the 5 mm slop); there, one plane: the ground's, facing up.
I2D_TEST(cpp_mover_cast_and_collide) {
    impulse2d::World world;
    build_room(world);
    const i2d_capsule high{{0.0f, 1.3f}, {0.0f, 2.5f}, 0.3f};  // its foot 1 m up
    const float fraction = world.cast_mover(high, {0.0f, -2.0f});
    I2D_CHECK(fraction * 2.0f >= 1.0f - 0.00375f && fraction * 2.0f <= 1.0f - 0.0025f);
    const float drop = fraction * 2.0f;
    const i2d_capsule landed{{0.0f, 1.3f - drop}, {0.0f, 2.5f - drop}, 0.3f};
    const std::vector<i2d_collision_plane> planes = world.collide_mover(landed);
    I2D_REQUIRE(planes.size() == 1);
    I2D_CHECK_NEAR(planes[0].plane.normal.y, 1.0, 1e-6);
    I2D_CHECK_NEAR(planes[0].plane.offset, 1.0 - drop, 1e-5);

    // Solving a move 1 m down against that plane stops at it, the plane pushing the rest.
    std::vector<i2d_collision_plane> solving = planes;
    const i2d_plane_result solved = impulse2d::solve_planes({0.5f, -1.0f}, solving);
    I2D_CHECK_NEAR(solved.translation.x, 0.5, 1e-6);
    I2D_CHECK_NEAR(solved.translation.y, -planes[0].plane.offset, 1e-6);
    I2D_CHECK_NEAR(solving[0].push, 1.0 - planes[0].plane.offset, 1e-6);
    const i2d_vec2 clipped = impulse2d::clip_vector({2.0f, -3.0f}, planes);
    I2D_CHECK(clipped.x == 2.0f && clipped.y == 0.0f);
}

I2D_TEST(cpp_mover_refused_in_both_styles) {
    impulse2d::World world;
    build_room(world);
    i2d_character_def def = i2d_default_character_def();
    def.skin = 0.0f;
    bool threw = false;
    try {
        world.move_character(def, kCapsule, {0.0f, 0.02f}, {1.0f, 0.0f});
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT && std::string(e.what()).find("skin") != std::string::npos;
    }
    I2D_CHECK(threw);
    impulse2d::Status status;
    const i2d_character_result r =
        world.move_character(i2d_default_character_def(), kCapsule, {0.0f, 0.02f}, {NAN, 0.0f}, 1.0f / 60.0f, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && !status.message.empty());
    I2D_CHECK(r.position.x == 0.0f && r.position.y == 0.0f && !r.on_ground);
}
