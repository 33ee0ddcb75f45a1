// SPDX-License-Identifier: MIT
// The character mover (toolkit.h) against closed forms: distances walked, the gap kept to
// walls, the slide along a wall, slopes and steps within and beyond the limits, the ground
// kept going down a slope, platforms ridden, crates pushed, no tunnelling, a move that
// changes nothing; and the plane solver and clipper on hand-computed planes.
//
// The character is a capsule 1.8 m tall of radius 0.3 m with its origin at its feet,
// moved the way a game does at 60 Hz: the player's input sets the level speed, gravity
// is added while it is in the air, and the velocity the move returns is fed back.
#include <cfloat>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

constexpr float radius = 0.3f;
constexpr float height = 1.8f;
/** The default def's gap to surfaces, m, and the world's contact slop (the default world's). */
constexpr float skin = 0.01f;
constexpr float slop = 0.005f;
/** Where a character rests above what it stands on: the skin and 7/8 of the slop, beyond
 *  the band its casts stop in (a half to three quarters of the slop). */
constexpr double rest_gap = skin + 0.875 * slop;

const i2d_capsule capsule{i2d_vec2{0.0f, radius}, i2d_vec2{0.0f, height - radius}, radius};

/** A character of the default def in a scene, moved frame by frame. */
struct Character {
    i2d_world_id world;
    i2d_character_def def = i2d_default_character_def();
    i2d_vec2 position;
    i2d_vec2 velocity{0.0f, 0.0f};
    i2d_character_result last{};
    bool failed = false;

    Character(i2d_world_id w, i2d_vec2 at) : world(w), position(at) {}

    /** One move with this velocity; the position follows the result. */
    const i2d_character_result& move(i2d_vec2 v) {
        const i2d_status s = i2d_world_move_character(world, &def, &capsule, position, v, time_step, &last);
        if (s != I2D_OK) {
            fprintf(stderr, "    move failed: %s (%s)\n", i2d_status_string(s), i2d_last_error_message());
            failed = true;
        }
        position = last.position;
        return last;
    }

    /** One game frame: the input sets the level speed, gravity pulls while airborne, the
     *  returned velocity is kept for the next frame. `world_gravity` is the world's pull. */
    const i2d_character_result& frame(float input_x, double world_gravity = g) {
        i2d_vec2 v{input_x, velocity.y};
        if (!last.on_ground) {
            v.y -= float(world_gravity * time_step);
        }
        move(v);
        velocity = last.velocity;
        return last;
    }
};

/** A static polygon body from points in world coordinates. */
i2d_body_id static_polygon(Scene& scene, const std::vector<i2d_vec2>& points) {
    const i2d_body_def bd = body_def(I2D_BODY_STATIC, i2d_vec2{0, 0});
    const i2d_body_id body = i2d_body_create(scene.world, &bd);
    const i2d_shape_def sd = i2d_default_shape_def();
    if (I2D_IS_NULL(i2d_shape_create_polygon(body, &sd, points.data(), int32_t(points.size())))) {
        fprintf(stderr, "    polygon creation failed: %s\n", i2d_last_error_message());
        return I2D_NULL_BODY_ID;
    }
    return body;
}

/** A static box whose corners are (x0, y0) and (x1, y1). */
i2d_body_id static_block(Scene& scene, float x0, float y0, float x1, float y1) {
    return scene.box(body_def(I2D_BODY_STATIC, i2d_vec2{0.5f * (x0 + x1), 0.5f * (y0 + y1)}), 0.5f * (x1 - x0),
                     0.5f * (y1 - y0));
}

i2d_collision_plane plane(float nx, float ny, float offset, float push_limit = FLT_MAX, bool clip = true) {
    return i2d_collision_plane{i2d_plane{i2d_vec2{nx, ny}, offset}, push_limit, 0.0f, clip};
}

}  // namespace

// 4 m/s for 2 s on level ground is 8 m, the feet kept at the rest gap every frame.
I2D_TEST(mover_walks_flat_ground) {
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f)));
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    c.move(i2d_vec2{0, 0});
    I2D_REQUIRE(c.last.on_ground);
    const int frames = steps_for(2.0);
    int grounded = 0;
    for (int i = 0; i < frames; ++i) {
        I2D_REQUIRE(scene.step());
        grounded += c.frame(4.0f).on_ground ? 1 : 0;
        I2D_CHECK_NEAR(c.position.y, rest_gap, 0.25 * slop);
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK_NEAR(grounded, frames, 0);
    I2D_CHECK_NEAR(c.position.x, 8.0, 0.01 * 8.0);
    // The ground's normal comes from closest points on a 100 m edge, which round to about
    // 4e-6 m: off by 1e-5 rad, it clips a few 1e-5 m/s of the level speed upward.
    I2D_CHECK_NEAR(c.velocity.x, 4.0, 1e-6);
    I2D_CHECK_NEAR(c.velocity.y, 0.0, 1e-4);
    I2D_CHECK_NEAR(c.last.ground_normal.y, 1.0, 1e-6);
    I2D_CHECK(c.last.hit_count == 1);
}

// A ground of 2.5 cm tiles puts more shapes around a move than it gathers (64), so every
// query walks the trees instead: the walk is the same, 8 m in 2 s at the rest gap.
I2D_TEST(mover_walks_dense_tiles) {
    Scene scene;
    const float tile = 0.025f;
    for (int i = 0; i < 480; ++i) {
        I2D_REQUIRE(!I2D_IS_NULL(static_block(scene, -1.0f + tile * float(i), -1.0f, -1.0f + tile * float(i + 1), 0.0f)));
    }
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    const int frames = steps_for(2.0);
    int grounded = 0;
    for (int i = 0; i < frames; ++i) {
        grounded += c.frame(4.0f).on_ground ? 1 : 0;
        I2D_CHECK_NEAR(c.position.y, rest_gap, 0.25 * slop);
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK_NEAR(grounded, frames, 0);
    I2D_CHECK_NEAR(c.position.x, 8.0, 0.01 * 8.0);
}

// Walked into a wall, it stops with the skin (and at most the slop) between them, and its
// velocity into the wall is gone.
I2D_TEST(mover_stops_at_wall_at_skin) {
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f)));
    I2D_REQUIRE(!I2D_IS_NULL(static_block(scene, 3.0f, 0.0f, 4.0f, 3.0f)));
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    for (int i = 0; i < steps_for(2.0); ++i) {
        c.frame(4.0f);
    }
    I2D_CHECK(!c.failed);
    const double gap = 3.0 - (double(c.position.x) + radius);
    I2D_CHECK(gap >= skin - 1e-5);
    I2D_CHECK(gap <= skin + slop);
    I2D_CHECK_NEAR(c.velocity.x, 0.0, 1e-6);
    I2D_CHECK(c.last.on_ground);
    I2D_CHECK(c.last.hit_count == 2);
}

// Without gravity (a top-down game), moving at 4 m/s into a wall at 45 degrees leaves the
// part along the wall, 4 cos 45 = 2.83 m/s, and it slides at that speed.
I2D_TEST(mover_slides_along_45_degree_wall) {
    Scene scene(Scene::zero_gravity_def());
    // The wall's face: the line x + y = 4 from (-6, 10) to (20, -16), solid beyond it
    // (normal (-1, -1) / sqrt 2).
    I2D_REQUIRE(!I2D_IS_NULL(static_polygon(scene, {{-6, 10}, {20, -16}, {36, -16}, {10, 10}})));
    Character c(scene.world, i2d_vec2{1.5f, -0.5f});  // 0.25 s from the face
    c.velocity = i2d_vec2{4.0f, 0.0f};
    const double s = std::sqrt(0.5);
    int sliding = 0;
    double travelled = 0.0;
    for (int i = 0; i < steps_for(1.0); ++i) {
        const i2d_vec2 before = c.position;
        const bool was_sliding = std::fabs(double(c.velocity.x) - 2.0) < 1e-4;
        c.move(c.velocity);
        c.velocity = c.last.velocity;
        if (was_sliding) {
            ++sliding;
            // Along the wall only: down its face, (1, -1) / sqrt 2, at 2.83 m/s.
            travelled += (double(c.position.x) - before.x) * s - (double(c.position.y) - before.y) * s;
            I2D_CHECK_NEAR(c.position.x - before.x, -(c.position.y - before.y), 1e-5);
        }
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK(sliding > 40);
    I2D_CHECK_NEAR(c.velocity.x, 4.0 * s * s, 1e-4);
    I2D_CHECK_NEAR(c.velocity.y, -4.0 * s * s, 1e-4);
    I2D_CHECK_NEAR(travelled, 4.0 * s * sliding * time_step, 1e-4);
    // The capsule's upper centre, the nearer, keeps radius + the rest gap from the face.
    const double centre_gap = (4.0 - (double(c.position.x) + capsule.center2.x + c.position.y + capsule.center2.y)) * s;
    I2D_CHECK_NEAR(centre_gap, radius + rest_gap, 0.5 * slop);
}

namespace {

/** Walks a character at 4 m/s toward a ramp of `degrees` rising from x = 2 to 14 for 2 s;
 *  returns its final position. */
i2d_vec2 walk_at_ramp(double degrees_up, bool* grounded_at_end) {
    Scene scene;
    scene.ground(0.0f, 50.0f);
    const float rise = float(12.0 * std::tan(degrees(degrees_up)));
    static_polygon(scene, {{2, 0}, {14, 0}, {14, rise}});
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    for (int i = 0; i < steps_for(2.0); ++i) {
        c.frame(4.0f);
    }
    I2D_CHECK(!c.failed);
    *grounded_at_end = c.last.on_ground;
    return c.position;
}

}  // namespace

// 30 degrees is within the default 45: the character walks up it, keeping to its surface.
// 60 is a wall: it stops at the foot, its feet on the level ground.
I2D_TEST(mover_climbs_30_degree_ramp_not_60) {
    bool grounded = false;
    const i2d_vec2 up30 = walk_at_ramp(30.0, &grounded);
    I2D_CHECK(grounded);
    // 1.5 s on the ramp at no less than 4 cos 30 m/s along it: at least 1.5 m up.
    I2D_CHECK(up30.y > 1.5f);
    // On the ramp's surface, y = (x - 2) tan 30, its round foot touching: the lower
    // centre at radius + rest gap from the face.
    const double t = std::tan(degrees(30.0));
    const double cx = up30.x, cy = double(up30.y) + radius;
    const double centre_gap = (cy - (cx - 2.0) * t) * std::cos(degrees(30.0));
    I2D_CHECK_NEAR(centre_gap, radius + rest_gap, slop);

    const i2d_vec2 up60 = walk_at_ramp(60.0, &grounded);
    I2D_CHECK(grounded);
    I2D_CHECK_NEAR(up60.y, rest_gap, 0.25 * slop);
    I2D_CHECK(up60.x < 2.0f);
    // Stopped against the face: its round foot at radius + rest gap from it.
    const double t60 = std::tan(degrees(60.0));
    const double gap60 = ((double(up60.y) + radius) - (double(up60.x) - 2.0) * t60) * std::cos(degrees(60.0));
    I2D_CHECK_NEAR(gap60, radius + rest_gap, slop);
}

namespace {

/** Walks a character at 2 m/s for 2 s toward a ledge of `ledge` m from x = 2 to 8. */
i2d_vec2 walk_at_ledge(float ledge, bool* grounded_at_end) {
    Scene scene;
    scene.ground(0.0f, 50.0f);
    static_block(scene, 2.0f, 0.0f, 8.0f, ledge);
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    for (int i = 0; i < steps_for(2.0); ++i) {
        c.frame(2.0f);
    }
    I2D_CHECK(!c.failed);
    *grounded_at_end = c.last.on_ground;
    return c.position;
}

}  // namespace

// With the default step of 0.25 m, a 0.2 m ledge is stepped onto and walked along; a
// 0.4 m one stops the character at its face.
I2D_TEST(mover_steps_onto_low_ledge_not_high) {
    bool grounded = false;
    const i2d_vec2 low = walk_at_ledge(0.2f, &grounded);
    I2D_CHECK(grounded);
    I2D_CHECK_NEAR(low.y, 0.2 + rest_gap, 0.25 * slop);
    // 2 s at 2 m/s; stepping may cost it a little, never gain it more than a radius.
    I2D_CHECK(low.x > 3.5f);
    I2D_CHECK(low.x < 4.0f + radius);

    const i2d_vec2 high = walk_at_ledge(0.4f, &grounded);
    I2D_CHECK(grounded);
    I2D_CHECK_NEAR(high.y, rest_gap, 0.25 * slop);
    I2D_CHECK_NEAR(high.x + radius, 2.0 - rest_gap, 0.75 * slop);
}

// Walking down a 30 degree slope at 4 m/s leaves the surface by 4 sin 30 / 60 = 3.3 cm a
// frame; the snap (0.2 m) brings it back every frame, so it is on the ground throughout.
I2D_TEST(mover_stays_on_ground_down_30_degree_slope) {
    Scene scene;
    const double t = std::tan(degrees(30.0));
    // Falls from y = 10 tan 30 at x = 0 to 0 at x = 10, then level ground.
    I2D_REQUIRE(!I2D_IS_NULL(static_polygon(scene, {{0, 0}, {10, 0}, {0, float(10.0 * t)}})));
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f)));
    Character c(scene.world, i2d_vec2{1.0f, float(9.0 * t + 0.1)});
    for (int i = 0; i < 30; ++i) {  // dropped onto the slope, then at rest on it
        c.frame(0.0f);
    }
    I2D_REQUIRE(c.last.on_ground);
    const double start_x = c.position.x;
    int grounded = 0;
    const int frames = steps_for(1.5);
    for (int i = 0; i < frames; ++i) {
        grounded += c.frame(4.0f).on_ground ? 1 : 0;
        const double cx = c.position.x, cy = double(c.position.y) + radius;
        if (cx < 9.0) {  // on the slope: its round foot at radius + rest gap from the face
            I2D_CHECK_NEAR((cy - (10.0 - cx) * t) * std::cos(degrees(30.0)), radius + rest_gap, slop);
        }
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK_NEAR(grounded, frames, 0);
    I2D_CHECK_NEAR(c.position.x - start_x, 4.0 * 1.5, 0.01 * 6.0);
}

// A kinematic platform moving at 2 m/s carries a character that adds the ground's
// velocity to its own (zero): it moves with the platform, on it every frame.
I2D_TEST(mover_rides_kinematic_platform) {
    Scene scene;
    const i2d_body_id platform = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, 1.0f}, i2d_vec2{2.0f, 0.0f}), 2.0f,
                                           0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(platform));
    Character c(scene.world, i2d_vec2{0.0f, float(1.25 + rest_gap)});
    c.move(i2d_vec2{0, 0});
    I2D_REQUIRE(c.last.on_ground);
    I2D_CHECK_NEAR(c.last.ground_velocity.x, 2.0, 1e-6);
    const double offset = double(c.position.x) - position(platform).x;
    int grounded = 0;
    for (int i = 0; i < steps_for(1.0); ++i) {
        I2D_REQUIRE(scene.step());
        grounded += c.move(c.last.ground_velocity).on_ground ? 1 : 0;
        I2D_CHECK_NEAR(double(c.position.x) - position(platform).x, offset, 1e-4);
        I2D_CHECK_NEAR(c.position.y, 1.25 + rest_gap, 0.25 * slop);
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK_NEAR(grounded, steps_for(1.0), 0);
    I2D_CHECK_NEAR(position(platform).x, 2.0, 1e-3);
}

// Rising at 1 m/s, the platform lifts a character that adds its velocity: it keeps its
// place on the platform.
I2D_TEST(mover_rides_rising_platform) {
    Scene scene;
    const i2d_body_id platform = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, 1.0f}, i2d_vec2{0.0f, 1.0f}), 2.0f,
                                           0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(platform));
    Character c(scene.world, i2d_vec2{0.0f, float(1.25 + rest_gap)});
    c.move(i2d_vec2{0, 0});
    I2D_REQUIRE(c.last.on_ground);
    for (int i = 0; i < steps_for(1.0); ++i) {
        I2D_REQUIRE(scene.step());
        I2D_CHECK(c.move(c.last.ground_velocity).on_ground);
        I2D_CHECK_NEAR(double(c.position.y) - position(platform).y, 0.25 + rest_gap, 0.25 * slop);
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK_NEAR(position(platform).y, 2.0, 1e-3);
}

// A 20 kg crate walked into at 2 m/s by a character pushing with 80 kg: the first push is
// a plastic collision, the crate's momentum at most what 80 kg at 2 m/s carry and its
// speed below the character's; walking on, the crate goes ahead of it and never overlaps it.
I2D_TEST(mover_pushes_crate) {
    Scene scene(Scene::no_sleep_def());
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f)));
    const i2d_body_id crate = scene.dynamic_box(i2d_vec2{2.0f, 0.5f}, 0.5f, 0.5f, with_density(20.0f));
    I2D_REQUIRE(!I2D_IS_NULL(crate));
    I2D_REQUIRE(scene.step(30));  // the crate settles
    const double mass = i2d_body_get_mass(crate);
    I2D_CHECK_NEAR(mass, 20.0, 1e-4);
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    const double push_mass = c.def.push_mass;
    bool pushed = false;
    const double start = position(crate).x;
    for (int i = 0; i < steps_for(2.0); ++i) {
        const i2d_vec2 before = velocity(crate);
        c.frame(2.0f);
        const i2d_vec2 after = velocity(crate);
        if (!pushed && after.x > before.x) {
            pushed = true;
            const double momentum = mass * (double(after.x) - before.x);
            I2D_CHECK(momentum > 0.0);
            I2D_CHECK(momentum <= push_mass * 2.0);
            I2D_CHECK(after.x < 2.0f);
        }
        I2D_REQUIRE(scene.step());
        const double crate_face = position(crate).x - 0.5;
        I2D_CHECK(double(c.position.x) + radius <= crate_face + 0.01);
    }
    I2D_CHECK(!c.failed);
    I2D_CHECK(pushed);
    I2D_CHECK(position(crate).x - start > 1.0);
}

// At 100 m/s (1.67 m a frame) toward a wall 2 cm thick the character never passes it: it
// stops at the skin in the frame that reaches it.
I2D_TEST(mover_does_not_tunnel_at_100_mps) {
    Scene scene(Scene::zero_gravity_def());
    I2D_REQUIRE(!I2D_IS_NULL(static_block(scene, 5.0f, -2.0f, 5.02f, 4.0f)));
    Character c(scene.world, i2d_vec2{0.0f, 0.0f});
    for (int i = 0; i < 10; ++i) {
        c.move(i2d_vec2{100.0f, 0.0f});
        I2D_CHECK(double(c.position.x) + radius <= 5.0);
    }
    I2D_CHECK(!c.failed);
    const double gap = 5.0 - (double(c.position.x) + radius);
    I2D_CHECK(gap >= skin - 1e-5);
    I2D_CHECK(gap <= skin + slop);
    I2D_CHECK_NEAR(c.last.velocity.x, 0.0, 1e-6);
}

// With push_mass 0 a move is a query: moves into boxes, through a pile and onto a crate
// leave the state hash and every body's sleep as they were.
I2D_TEST(mover_without_push_changes_nothing) {
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f, 50.0f)));
    const std::vector<i2d_body_id> pile = scene.pyramid(3.0f, 3);
    I2D_REQUIRE(pile.size() == 6);
    I2D_REQUIRE(scene.step(10));
    const uint64_t hash = i2d_world_get_state_hash(scene.world);
    const int awake = count_awake(pile);
    Character c(scene.world, i2d_vec2{0.0f, float(rest_gap)});
    c.def.push_mass = 0.0f;
    for (int i = 0; i < 60; ++i) {
        c.frame(6.0f);
    }
    c.move(i2d_vec2{0.0f, -100.0f});
    I2D_CHECK(!c.failed);
    I2D_CHECK(c.last.hit_count >= 2);  // the ground and the pile's first box
    I2D_CHECK(i2d_world_get_state_hash(scene.world) == hash);
    I2D_CHECK_NEAR(count_awake(pile), awake, 0);
}

// ---- The plane solver and the clipper, on planes worked out by hand -------------------

// A floor 0.1 m below: a move of (1, -0.3) keeps its level part and goes down 0.1; the
// floor pushed 0.2. The second sweep finds nothing left to change.
I2D_TEST(mover_solve_planes_floor) {
    i2d_collision_plane planes[] = {plane(0, 1, 0.1f)};
    const i2d_plane_result r = i2d_solve_planes(i2d_vec2{1.0f, -0.3f}, planes, 1);
    I2D_CHECK_NEAR(r.translation.x, 1.0, 1e-6);
    I2D_CHECK_NEAR(r.translation.y, -0.1, 1e-6);
    I2D_CHECK_NEAR(planes[0].push, 0.2, 1e-6);
    I2D_CHECK_NEAR(r.iteration_count, 2, 0);
}

// A floor touched and a wall 5 cm to the right: (0.3, -0.2) ends at (0.05, 0), the floor
// pushing 0.2 and the wall 0.25.
I2D_TEST(mover_solve_planes_corner) {
    i2d_collision_plane planes[] = {plane(0, 1, 0.0f), plane(-1, 0, 0.05f)};
    const i2d_plane_result r = i2d_solve_planes(i2d_vec2{0.3f, -0.2f}, planes, 2);
    I2D_CHECK_NEAR(r.translation.x, 0.05, 1e-6);
    I2D_CHECK_NEAR(r.translation.y, 0.0, 1e-6);
    I2D_CHECK_NEAR(planes[0].push, 0.2, 1e-6);
    I2D_CHECK_NEAR(planes[1].push, 0.25, 1e-6);
}

// A V of two planes 0.6 / 0.8: straight down into it stops at its bottom, each side
// pushing p with 2 (0.8 p) = 1: p = 0.625.
I2D_TEST(mover_solve_planes_valley) {
    i2d_collision_plane planes[] = {plane(-0.6f, 0.8f, 0.0f), plane(0.6f, 0.8f, 0.0f)};
    const i2d_plane_result r = i2d_solve_planes(i2d_vec2{0.0f, -1.0f}, planes, 2);
    I2D_CHECK_NEAR(r.translation.x, 0.0, 1e-5);
    I2D_CHECK_NEAR(r.translation.y, 0.0, 1e-5);
    I2D_CHECK_NEAR(planes[0].push, 0.625, 1e-5);
    I2D_CHECK_NEAR(planes[1].push, 0.625, 1e-5);
    I2D_CHECK(r.iteration_count > 2 && r.iteration_count <= 32);
}

// A soft plane 0.5 m into the mover that may push 0.2 pushes 0.2, no more; a plane that a
// move leaves behind does not pull; no planes, no change.
I2D_TEST(mover_solve_planes_soft_and_none) {
    i2d_collision_plane soft[] = {plane(0, 1, -0.5f, 0.2f)};
    const i2d_plane_result r = i2d_solve_planes(i2d_vec2{0.0f, 0.0f}, soft, 1);
    I2D_CHECK_NEAR(r.translation.y, 0.2, 1e-6);
    I2D_CHECK_NEAR(soft[0].push, 0.2, 1e-6);

    i2d_collision_plane behind[] = {plane(0, 1, 0.0f)};
    const i2d_plane_result up = i2d_solve_planes(i2d_vec2{0.5f, 0.5f}, behind, 1);
    I2D_CHECK_NEAR(up.translation.x, 0.5, 0.0);
    I2D_CHECK_NEAR(up.translation.y, 0.5, 0.0);
    I2D_CHECK_NEAR(behind[0].push, 0.0, 0.0);

    const i2d_plane_result none = i2d_solve_planes(i2d_vec2{0.25f, -2.0f}, nullptr, 0);
    I2D_CHECK_NEAR(none.translation.x, 0.25, 0.0);
    I2D_CHECK_NEAR(none.translation.y, -2.0, 0.0);
    I2D_CHECK_NEAR(none.iteration_count, 0, 0);
}

I2D_TEST(mover_clip_vector) {
    const i2d_collision_plane floor[] = {plane(0, 1, 0)};
    i2d_vec2 v = i2d_clip_vector(i2d_vec2{3, -4}, floor, 1);
    I2D_CHECK_NEAR(v.x, 3.0, 0.0);
    I2D_CHECK_NEAR(v.y, 0.0, 0.0);
    v = i2d_clip_vector(i2d_vec2{3, 4}, floor, 1);  // leaving: unchanged
    I2D_CHECK_NEAR(v.x, 3.0, 0.0);
    I2D_CHECK_NEAR(v.y, 4.0, 0.0);

    const i2d_collision_plane corner[] = {plane(0, 1, 0), plane(-1, 0, 0)};
    v = i2d_clip_vector(i2d_vec2{3, -4}, corner, 2);
    I2D_CHECK_NEAR(v.x, 0.0, 0.0);
    I2D_CHECK_NEAR(v.y, 0.0, 0.0);

    const i2d_collision_plane ignored[] = {plane(0, 1, 0, FLT_MAX, false)};
    v = i2d_clip_vector(i2d_vec2{3, -4}, ignored, 1);
    I2D_CHECK_NEAR(v.y, -4.0, 0.0);

    // A 45 degree face: (4, 0) keeps (2, 2).
    const float s = float(std::sqrt(0.5));
    const i2d_collision_plane slope[] = {plane(-s, s, 0)};
    v = i2d_clip_vector(i2d_vec2{4, 0}, slope, 1);
    I2D_CHECK_NEAR(v.x, 2.0, 1e-6);
    I2D_CHECK_NEAR(v.y, 2.0, 1e-6);

    // A floor and a steep face (0.8 across, 0.6 up): (1, -1) clipped by the floor alone
    // runs into the face, by the face alone into the floor; the nearest vector that runs
    // into neither is zero. (Clipping plane by plane would give (0.36, 0.48).)
    const i2d_collision_plane crease[] = {plane(0, 1, 0), plane(-0.8f, 0.6f, 0)};
    v = i2d_clip_vector(i2d_vec2{1, -1}, crease, 2);
    I2D_CHECK_NEAR(v.x, 0.0, 0.0);
    I2D_CHECK_NEAR(v.y, 0.0, 0.0);
    // (-1, -1) runs only into the floor: (-1, 0), which the face lets go.
    v = i2d_clip_vector(i2d_vec2{-1, -1}, crease, 2);
    I2D_CHECK_NEAR(v.x, -1.0, 0.0);
    I2D_CHECK_NEAR(v.y, 0.0, 0.0);
}
