// SPDX-License-Identifier: MIT
// The determinism suite's scenes: built through the public API, identical in every test
// and process that builds them.
//
// mixed_scene exercises every branch the contact kernels blend per lane: boxes, circles,
// capsules, rounded and plain polygons; one- and two-point manifolds; restitution
// (bouncing balls), rolling resistance and a conveyor (tangent speed); a kinematic
// platform; a heavy plank carrying more contacts than there are colours (the overflow
// colour); and a pile that falls asleep while the rest moves.
//
// snapshot_scene adds to it a chain, a sensor, a bullet and a joint of every kind, for
// the snapshot tests.
//
// sleeping_bin is large enough for every stage of the step to be shared by workers
// (several hundred awake bodies, thousands of contacts) and comes to rest: a bin of
// mixed shapes, some bouncy, with a heavy plank (the overflow colour), that all sleep.
//
// tall_pyramid is large enough that each worker's part of a colour (placed apart from the
// others in memory, contact_solver.cpp) is longer than the gap after it: 70 rows of boxes,
// 2485 bodies and about 7000 contacts, about 1000 a colour.
//
// ragdoll_heap drops 60 of the bench's ragdolls (bench/ragdoll.c: 660 bodies, 600 revolute
// joints with limits, springs and motors) onto a ground in overlapping layers, so that
// joints are solved in every stage the workers share; ragdoll_crowd drops 100.
//
// hinge_net is made of revolute joints, which the hinge kernels solve W at a time: a net
// of 280 boxes and circles hung from a static bar and a moving kinematic one, some of its
// hinges with a limit or a spring; a hub whose 30 spokes (limits, motors, springs that
// relax or not) overflow the colours (the overflow colour solves its hinges one at a
// time); a body held at two places at once (two hinges that cannot both hold: the guard
// undoes their passes); and boxes falling onto the net.
//
// hung_bridges hangs 24 taut bridges at both ends: loops that the exact solve cuts and
// the loops' position projection moves after every step.
#pragma once

#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <unordered_set>

#include "ragdoll.h"

namespace det {

constexpr float time_step = 1.0f / 60.0f;
constexpr int substeps = 4;

// A scene: builds itself in a new world made from the def, or gives the null id.
using Scene = i2d_world_id (*)(const i2d_world_def&);

inline i2d_body_id add_body(i2d_world_id world, i2d_body_type type, i2d_vec2 position, float angle = 0.0f) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = position;
    def.rotation = i2d_make_rot(angle);
    return i2d_body_create(world, &def);
}

inline i2d_shape_def material(float friction, float restitution, float rolling = 0.0f, float tangent_speed = 0.0f) {
    i2d_shape_def def = i2d_default_shape_def();
    def.friction = friction;
    def.restitution = restitution;
    def.rolling_resistance = rolling;
    def.tangent_speed = tangent_speed;
    return def;
}

// A static body at the origin holding a floor 1 m thick and 2 * half_width wide whose top
// is at y = 0.
inline i2d_body_id add_ground(i2d_world_id world, const i2d_shape_def& def, float half_width) {
    const i2d_body_id ground = add_body(world, I2D_BODY_STATIC, i2d_vec2{0, 0});
    i2d_shape_create_offset_box(ground, &def, half_width, 0.5f, i2d_vec2{0, -0.5f}, i2d_make_rot(0));
    return ground;
}

// Walls 1 m thick and 2 * half_height tall standing at the ends of the ground's floor.
inline void add_walls(i2d_body_id ground, const i2d_shape_def& def, float half_width, float half_height) {
    const float x = half_width + 0.5f;
    i2d_shape_create_offset_box(ground, &def, 0.5f, half_height, i2d_vec2{-x, half_height}, i2d_make_rot(0));
    i2d_shape_create_offset_box(ground, &def, 0.5f, half_height, i2d_vec2{x, half_height}, i2d_make_rot(0));
}

// One of four shapes, by index.
inline void add_mixed_shape(i2d_body_id body, int kind, const i2d_shape_def* def) {
    switch (kind % 4) {
        case 0: i2d_shape_create_box(body, def, 0.3f, 0.2f); break;
        case 1: {
            const i2d_circle circle = {{0.0f, 0.0f}, 0.25f};
            i2d_shape_create_circle(body, def, &circle);
            break;
        }
        case 2: i2d_shape_create_capsule(body, def, i2d_vec2{-0.2f, 0.0f}, i2d_vec2{0.2f, 0.0f}, 0.15f); break;
        default: {
            i2d_vec2 hexagon[6];
            for (int k = 0; k < 6; ++k) {
                // The engine's trigonometry, not libm's: the scene is the same everywhere.
                const i2d_rot q = i2d_make_rot(1.0472f * float(k));
                hexagon[k] = i2d_vec2{0.28f * q.c, 0.28f * q.s};
            }
            i2d_shape_create_polygon(body, def, hexagon, 6);
            break;
        }
    }
}

inline i2d_world_id mixed_scene(const i2d_world_def& wd) {
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def ground_material = material(0.6f, 0.0f);
    const i2d_body_id ground = add_ground(world, ground_material, 30.0f);
    add_walls(ground, ground_material, 30.0f, 10.0f);
    const i2d_shape_def conveyor = material(0.8f, 0.0f, 0.0f, 1.5f);
    i2d_shape_create_offset_box(ground, &conveyor, 4.0f, 0.25f, i2d_vec2{-20.0f, 3.0f}, i2d_make_rot(0.1f));

    // A rain of mixed shapes, some bouncy, some rolling, with a little spin.
    for (int i = 0; i < 160; ++i) {
        const float x = -18.0f + 0.75f * float(i % 48) + 0.05f * float(i % 7);
        const float y = 2.0f + 0.9f * float(i / 48);
        const i2d_body_id body = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{x, y}, 0.1f * float(i % 11));
        const i2d_shape_def def = material(0.3f + 0.1f * float(i % 5), (i % 6 == 0) ? 0.7f : 0.0f,
                                           (i % 9 == 0) ? 0.2f : 0.0f);
        add_mixed_shape(body, i, &def);
        i2d_body_set_angular_velocity(body, 0.5f * float(i % 5) - 1.0f);
    }
    // A heavy plank with a row of 30 boxes on it: more contacts on one body than colours.
    const i2d_body_id plank = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{12.0f, 0.6f});
    const i2d_shape_def heavy = material(0.6f, 0.0f);
    i2d_shape_create_box(plank, &heavy, 9.5f, 0.1f);
    for (int i = 0; i < 30; ++i) {
        const i2d_body_id box = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{3.0f + 0.62f * float(i), 0.95f});
        i2d_shape_create_box(box, &heavy, 0.3f, 0.25f);
    }
    // A kinematic platform sweeping under falling rounded boxes.
    const i2d_body_id platform = add_body(world, I2D_BODY_KINEMATIC, i2d_vec2{-8.0f, 6.0f});
    i2d_shape_create_box(platform, &heavy, 2.0f, 0.2f);
    i2d_body_set_linear_velocity(platform, i2d_vec2{1.0f, 0.0f});
    i2d_body_set_angular_velocity(platform, 0.2f);
    const i2d_vec2 corners[4] = {{-0.2f, -0.2f}, {0.2f, -0.2f}, {0.2f, 0.2f}, {-0.2f, 0.2f}};
    i2d_polygon rounded;
    i2d_make_polygon(corners, 4, 0.05f, &rounded);
    for (int i = 0; i < 6; ++i) {
        const i2d_body_id body = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{-9.5f + 0.6f * float(i), 7.0f});
        i2d_shape_create_polygon_from(body, &heavy, &rounded);
    }
    // A small pile off to the side that falls asleep while the rest moves.
    for (int i = 0; i < 4; ++i) {
        const i2d_body_id box = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{26.0f, 0.5f + float(i)});
        i2d_shape_create_box(box, &heavy, 0.5f, 0.5f);
    }
    return world;
}

// mixed_scene with what it lacks for snapshots: a chain, a sensor, a bullet, and one
// joint of every kind, with motors, limits and springs on.
inline i2d_world_id snapshot_scene(const i2d_world_def& wd) {
    const i2d_world_id world = mixed_scene(wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def plain = material(0.6f, 0.0f);
    // A chain landscape the rain lands on, and a sensor strip it falls through.
    const i2d_body_id terrain = add_body(world, I2D_BODY_STATIC, i2d_vec2{0, 0});
    const i2d_vec2 hills[] = {{-17, 9}, {-16, 8}, {-14, 8.6f}, {-12, 8.2f}, {-10, 8.8f}, {-8, 8.4f}, {-7, 9}};
    i2d_chain_def chain = i2d_default_chain_def();
    chain.points = hills;
    chain.count = int32_t(sizeof hills / sizeof hills[0]);
    i2d_chain_create(terrain, &chain);
    i2d_shape_def sensor = plain;
    sensor.is_sensor = true;
    sensor.enable_sensor_events = true;
    i2d_shape_create_offset_box(terrain, &sensor, 6.0f, 0.2f, i2d_vec2{6.0f, 1.5f}, i2d_make_rot(0));
    // A bullet fired at a thin wall.
    i2d_shape_create_offset_box(terrain, &plain, 0.02f, 2.0f, i2d_vec2{28.0f, 4.0f}, i2d_make_rot(0));
    i2d_body_def bullet_def = i2d_default_body_def();
    bullet_def.type = I2D_BODY_DYNAMIC;
    bullet_def.position = i2d_vec2{20.0f, 4.0f};
    bullet_def.linear_velocity = i2d_vec2{200.0f, 0.0f};
    bullet_def.is_bullet = true;
    const i2d_body_id bullet = i2d_body_create(world, &bullet_def);
    const i2d_circle pellet = {{0, 0}, 0.05f};
    i2d_shape_create_circle(bullet, &plain, &pellet);
    // One joint of every kind, hung from a frame above the scene.
    const i2d_body_id frame = add_body(world, I2D_BODY_STATIC, i2d_vec2{0, 16});
    i2d_body_id links[8];
    for (int k = 0; k < 8; ++k) {
        links[k] = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{-14.0f + 4.0f * float(k), 14.0f});
        add_mixed_shape(links[k], k, &plain);
    }
    const auto anchor = [](i2d_joint_base& base, i2d_body_id a, i2d_body_id b, i2d_vec2 local_a) {
        base.body_a = a;
        base.body_b = b;
        base.local_anchor_a = local_a;
    };
    i2d_revolute_joint_def revolute = i2d_default_revolute_joint_def();
    anchor(revolute.base, frame, links[0], i2d_vec2{-14, -2});
    revolute.enable_limit = true, revolute.lower_angle = -0.5f, revolute.upper_angle = 0.5f;
    revolute.enable_motor = true, revolute.motor_speed = 1.0f, revolute.max_motor_torque = 5.0f;
    revolute.enable_spring = true, revolute.hertz = 2.0f, revolute.damping_ratio = 0.3f;
    i2d_joint_create_revolute(world, &revolute);
    i2d_prismatic_joint_def prismatic = i2d_default_prismatic_joint_def();
    anchor(prismatic.base, frame, links[1], i2d_vec2{-10, -2});
    prismatic.local_axis_a = i2d_vec2{0, 1};
    prismatic.enable_limit = true, prismatic.lower_translation = -1.0f, prismatic.upper_translation = 0.5f;
    prismatic.enable_motor = true, prismatic.motor_speed = -0.5f, prismatic.max_motor_force = 20.0f;
    i2d_joint_create_prismatic(world, &prismatic);
    i2d_distance_joint_def distance = i2d_default_distance_joint_def();
    anchor(distance.base, frame, links[2], i2d_vec2{-6, -1});
    distance.length = 1.5f;
    distance.enable_spring = true, distance.hertz = 3.0f, distance.damping_ratio = 0.2f;
    distance.enable_limit = true, distance.min_length = 1.0f, distance.max_length = 2.0f;
    i2d_joint_create_distance(world, &distance);
    i2d_weld_joint_def weld = i2d_default_weld_joint_def();
    anchor(weld.base, links[2], links[3], i2d_vec2{2, 0});
    weld.linear_hertz = 5.0f, weld.angular_hertz = 5.0f;
    i2d_joint_create_weld(world, &weld);
    i2d_wheel_joint_def wheel = i2d_default_wheel_joint_def();
    anchor(wheel.base, links[3], links[4], i2d_vec2{2, -1});
    wheel.enable_motor = true, wheel.motor_speed = 4.0f, wheel.max_motor_torque = 2.0f;
    wheel.enable_limit = true, wheel.lower_translation = -0.3f, wheel.upper_translation = 0.3f;
    i2d_joint_create_wheel(world, &wheel);
    i2d_motor_joint_def motor = i2d_default_motor_joint_def();
    anchor(motor.base, frame, links[5], i2d_vec2{6, -2});
    motor.linear_offset = i2d_vec2{6, -2.5f}, motor.angular_offset = 0.4f, motor.max_force = 50.0f;
    i2d_joint_create_motor(world, &motor);
    i2d_mouse_joint_def mouse = i2d_default_mouse_joint_def();
    anchor(mouse.base, frame, links[6], i2d_vec2{0, 0});
    mouse.target = i2d_vec2{10.5f, 13.0f};
    i2d_joint_create_mouse(world, &mouse);
    i2d_filter_joint_def filter = i2d_default_filter_joint_def();
    anchor(filter.base, links[6], links[7], i2d_vec2{0, 0});
    i2d_joint_create_filter(world, &filter);
    return world;
}

constexpr float bin_rolling_resistance = 0.02f;

inline i2d_world_id sleeping_bin(const i2d_world_def& wd) {
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def wall = material(0.6f, 0.0f);
    add_walls(add_ground(world, wall, 12.0f), wall, 12.0f, 15.0f);
    const i2d_body_id plank = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{0.0f, 0.2f});
    const i2d_shape_def heavy = material(0.6f, 0.0f);
    i2d_shape_create_box(plank, &heavy, 11.5f, 0.2f);
    for (int i = 0; i < 600; ++i) {
        const float x = -11.0f + 0.72f * float(i % 30) + 0.04f * float(i % 7);
        const float y = 1.0f + 0.7f * float(i / 30);
        const i2d_body_id body = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{x, y}, 0.13f * float(i % 11));
        // Every shape resists rolling a little: without it about one bin in five (shifted
        // by a millimetre or so) never sleeps, a hexagon rocking on circles that roll
        // without slipping, which nothing else in a rigid contact damps.
        i2d_shape_def def = material(0.4f + 0.1f * float(i % 4), (i % 7 == 0) ? 0.5f : 0.0f,
                                     (i % 9 == 0) ? 0.1f : bin_rolling_resistance);
        // Tags that name bodies and shapes the same way in every world (ids name the world).
        def.user_data = reinterpret_cast<void*>(std::intptr_t(i + 1));
        i2d_body_set_user_data(body, def.user_data);
        add_mixed_shape(body, i, &def);
    }
    return world;
}

inline i2d_world_id tall_pyramid(const i2d_world_def& wd) {
    constexpr int rows = 70;
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def def = material(0.6f, 0.0f);
    const i2d_body_id ground = add_body(world, I2D_BODY_STATIC, i2d_vec2{0, -1.0f});
    i2d_shape_create_box(ground, &def, 0.6f * float(rows), 1.0f);
    for (int row = 0; row < rows; ++row) {
        for (int k = 0; k < rows - row; ++k) {
            const float x = -0.5f * float(rows) + 0.5f * float(row + 1) + float(k);
            const i2d_body_id box = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{x, 0.5f + float(row)});
            i2d_shape_create_box(box, &def, 0.5f, 0.5f);
        }
    }
    return world;
}

// Bullets ricocheting in a room of thin walls among boxes, and fast balls that are not
// bullets: the continuous stage has work every step (both of its passes, bullets against
// bullets and against boxes; more than enough fast balls that its sweeps are shared),
// with enough awake bodies that the solver shares its stages. Thin sensor strips across
// the room are crossed within a step, which only the sweeps see.
inline i2d_world_id bullet_room(const i2d_world_def& wd) {
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def wall = material(0.0f, 0.0f);
    const i2d_body_id room = add_body(world, I2D_BODY_STATIC, i2d_vec2{0, 0});
    i2d_shape_create_offset_box(room, &wall, 10.0f, 0.02f, i2d_vec2{0, -0.02f}, i2d_make_rot(0));
    i2d_shape_create_offset_box(room, &wall, 10.0f, 0.02f, i2d_vec2{0, 20.02f}, i2d_make_rot(0));
    i2d_shape_create_offset_box(room, &wall, 0.02f, 10.0f, i2d_vec2{-10.02f, 10.0f}, i2d_make_rot(0));
    i2d_shape_create_offset_box(room, &wall, 0.02f, 10.0f, i2d_vec2{10.02f, 10.0f}, i2d_make_rot(0));
    for (int strip = 0; strip < 3; ++strip) {
        i2d_shape_def sensor = i2d_default_shape_def();
        sensor.is_sensor = true;
        sensor.user_data = reinterpret_cast<void*>(std::intptr_t(1000 + strip));
        i2d_shape_create_offset_box(room, &sensor, 9.5f, 0.01f, i2d_vec2{0, 5.0f + 5.0f * float(strip)},
                                    i2d_make_rot(0));
    }
    for (int i = 0; i < 300; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        def.position = i2d_vec2{-9.0f + 0.9f * float(i % 20), 1.0f + 1.2f * float(i / 20)};
        const float angle = 0.61803f * float(i) * 6.2831853f;
        const float speed = 100.0f + float(i % 7) * 30.0f;
        def.linear_velocity = i2d_vec2{speed * std::cos(angle), speed * std::sin(angle)};
        def.is_bullet = i % 3 != 0;
        def.user_data = reinterpret_cast<void*>(std::intptr_t(i + 1));
        const i2d_body_id body = i2d_body_create(world, &def);
        i2d_shape_def shape = material(0.2f, 0.8f);
        shape.user_data = def.user_data;
        if (i % 5 == 0) {
            i2d_shape_create_box(body, &shape, 0.25f, 0.25f);
        } else {
            const i2d_circle circle{i2d_vec2{0, 0}, 0.05f};
            i2d_shape_create_circle(body, &shape, &circle);
        }
    }
    return world;
}

// The rows a hinge of hinge_net has, by number: none, a limit, a motor, a spring that
// relaxes (stiff for the substep), one that does not (soft).
inline i2d_revolute_joint_def hinge_rows(int kind) {
    i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
    switch (kind % 5) {
        case 1:
            def.enable_limit = true;
            def.lower_angle = -0.3f;
            def.upper_angle = 0.2f;
            break;
        case 2:
            def.enable_motor = true;
            def.motor_speed = 1.5f;
            def.max_motor_torque = 4.0f;
            break;
        case 3:
            def.enable_spring = true;
            def.hertz = 60.0f;
            def.damping_ratio = 0.7f;
            def.target_angle = 0.25f;
            break;
        case 4:
            def.enable_spring = true;
            def.hertz = 1.5f;
            def.damping_ratio = 0.1f;
            def.target_angle = -0.4f;
            break;
        default: break;
    }
    return def;
}

// A hinge holding the world point at_a of a on the world point at_b of b.
inline void add_hinge(i2d_world_id world, i2d_body_id a, i2d_body_id b, i2d_vec2 at_a, i2d_vec2 at_b,
                      int kind = 0) {
    i2d_revolute_joint_def def = hinge_rows(kind);
    def.base.body_a = a;
    def.base.body_b = b;
    def.base.local_anchor_a = i2d_body_get_local_point(a, at_a);
    def.base.local_anchor_b = i2d_body_get_local_point(b, at_b);
    i2d_joint_create_revolute(world, &def);
}

inline void add_hinge(i2d_world_id world, i2d_body_id a, i2d_body_id b, i2d_vec2 at, int kind = 0) {
    add_hinge(world, a, b, at, at, kind);
}

inline i2d_world_id hinge_net(const i2d_world_def& wd) {
    constexpr int columns = 20, rows = 14, spokes = 30;
    constexpr float spacing = 0.5f, top = 12.0f, left = -5.0f;
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def shape = material(0.6f, 0.0f);
    const i2d_body_id ground = add_ground(world, shape, 30.0f);
    const i2d_body_id bar = add_body(world, I2D_BODY_STATIC, i2d_vec2{0, top + spacing});
    const i2d_body_id carrier = add_body(world, I2D_BODY_KINEMATIC, i2d_vec2{left + spacing * columns, top + spacing});
    i2d_shape_create_box(carrier, &shape, 0.3f, 0.3f);
    i2d_body_set_linear_velocity(carrier, i2d_vec2{0.4f, 0.0f});
    i2d_body_set_angular_velocity(carrier, 0.3f);
    // Held at two places 2 m apart: neither hinge can hold. Made first, so that its
    // hinges start their colours' runs and the wide kernels meet the guard too.
    const i2d_vec2 torn_at{-9.0f, 8.0f};
    const i2d_body_id torn = add_body(world, I2D_BODY_DYNAMIC, torn_at);
    add_mixed_shape(torn, 0, &shape);
    add_hinge(world, ground, torn, torn_at);
    add_hinge(world, bar, torn, i2d_vec2{torn_at.x + 2.0f, torn_at.y}, torn_at);
    i2d_body_id net[rows][columns];
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const i2d_vec2 at{left + spacing * float(c), top - spacing * float(r)};
            net[r][c] = add_body(world, I2D_BODY_DYNAMIC, at);
            add_mixed_shape(net[r][c], (r + c) % 2, &shape);
        }
    }
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const i2d_vec2 at = i2d_body_get_position(net[r][c]);
            // One hinge in seven with a limit or a spring; the rest plain.
            const int kind = (r * columns + c) % 7 == 0 ? 1 + (r + c) % 4 : 0;
            if (c + 1 < columns) {
                add_hinge(world, net[r][c], net[r][c + 1], i2d_vec2{at.x + 0.5f * spacing, at.y}, kind == 2 ? 0 : kind);
            }
            if (r + 1 < rows) {
                add_hinge(world, net[r][c], net[r + 1][c], i2d_vec2{at.x, at.y - 0.5f * spacing});
            }
        }
    }
    for (int c = 0; c < columns; c += 4) {
        const i2d_vec2 at = i2d_body_get_position(net[0][c]);
        add_hinge(world, bar, net[0][c], i2d_vec2{at.x, at.y + 0.5f * spacing});
    }
    add_hinge(world, carrier, net[0][columns - 1], i2d_body_get_position(carrier));
    // The hub and its spokes, to the right of the net.
    const i2d_vec2 hub_at{9.0f, 6.0f};
    const i2d_body_id hub = add_body(world, I2D_BODY_DYNAMIC, hub_at);
    add_mixed_shape(hub, 1, &shape);
    add_hinge(world, ground, hub, hub_at);
    for (int k = 0; k < spokes; ++k) {
        // The engine's own trigonometry: the same bits on every platform, as the recorded
        // hash needs.
        const i2d_rot turn = i2d_make_rot(6.2831853f * float(k) / float(spokes));
        const i2d_vec2 tip{hub_at.x + 1.5f * turn.c, hub_at.y + 1.5f * turn.s};
        const i2d_body_id spoke = add_body(world, I2D_BODY_DYNAMIC, tip);
        add_mixed_shape(spoke, k, &shape);
        add_hinge(world, hub, spoke, hub_at, k);
    }
    for (int k = 0; k < 24; ++k) {
        const i2d_body_id box = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{left + 0.4f * float(k), top + 3.0f});
        add_mixed_shape(box, k, &shape);
    }
    return world;
}

// 24 taut bridges of ten planks, in four columns of six, hung from the ground at both
// ends; a box and a few shapes fall onto each. Each bridge closes a loop through the
// ground, which the exact solve cuts and the loops' projection moves back onto its joints
// after every step: more trees than a block of work holds (joint_trees_per_work_block).
inline i2d_world_id hung_bridges(const i2d_world_def& wd) {
    constexpr int columns = 4, rows = 6, planks = 10;
    constexpr float plank_length = 1.0f, column_spacing = 12.0f, row_spacing = 3.0f;
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    const i2d_shape_def shape = material(0.6f, 0.0f);
    const i2d_body_id ground = add_ground(world, shape, 30.0f);
    for (int b = 0; b < columns * rows; ++b) {
        const float left = -24.0f + column_spacing * float(b % columns);
        const float y = row_spacing * float(1 + b / columns);
        i2d_body_id previous = ground;
        for (int k = 0; k < planks; ++k) {
            const float x = left + plank_length * (float(k) + 0.5f);
            const i2d_body_id plank = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{x, y});
            i2d_shape_create_box(plank, &shape, 0.5f * plank_length, 0.0625f);
            add_hinge(world, previous, plank, i2d_vec2{x - 0.5f * plank_length, y});
            previous = plank;
        }
        add_hinge(world, previous, ground, i2d_vec2{left + plank_length * float(planks), y});
        const float middle = left + 0.5f * plank_length * float(planks);
        const i2d_body_id box = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{middle + 0.3f * float(b % 3), y + 1.0f});
        i2d_shape_create_box(box, &shape, 0.4f, 0.4f);
        for (int k = 0; k < 3; ++k) {
            const i2d_body_id piece = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{left + 2.0f + 3.0f * float(k), y + 0.6f});
            add_mixed_shape(piece, b + k, &shape);
        }
    }
    return world;
}

// `count` ragdolls in layers of 12 (ragdoll_heap, ragdoll_crowd).
inline i2d_world_id ragdoll_layers(const i2d_world_def& wd, int count) {
    constexpr int per_layer = 12;
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    add_ground(world, material(0.6f, 0.0f), 20.0f);
    for (int i = 0; i < count; ++i) {
        const int layer = i / per_layer, column = i % per_layer;
        // Odd layers shifted by half a spacing, so that ragdolls land across the ones below.
        const float x = -6.6f + 1.2f * float(column) + 0.6f * float(layer % 2);
        bench_ragdoll_def def = bench_default_ragdoll_def(i2d_vec2{x, 1.0f + 2.2f * float(layer)}, i + 1);
        bench_ragdoll ragdoll;
        if (!bench_ragdoll_create(world, &def, &ragdoll)) {
            i2d_world_destroy(world);
            return I2D_NULL_WORLD_ID;
        }
    }
    return world;
}

inline i2d_world_id ragdoll_heap(const i2d_world_def& wd) { return ragdoll_layers(wd, 60); }

// 100 ragdolls, 1100 bodies: enough awake bodies that the workers share gathering the
// joints to solve (constraint_graph.cpp).
inline i2d_world_id ragdoll_crowd(const i2d_world_def& wd) { return ragdoll_layers(wd, 100); }

// The contact hooks' table for one hooked_bin world: its shapes' ghost groups and its
// one-way platforms, by id. The hooks read it and nothing else (every call on the world
// is locked while they run), so their answers depend on their arguments alone.
struct HookTable {
    std::unordered_map<uint64_t, int> ghost_group;  // 0 or missing: meets every shape
    std::unordered_set<uint64_t> platforms;
};

// Shapes of two different ghost groups pass through each other.
inline bool ghosts_apart(i2d_shape_id a, i2d_shape_id b, void* context) {
    const HookTable& t = *static_cast<const HookTable*>(context);
    const auto group = [&](i2d_shape_id s) {
        const auto found = t.ghost_group.find(s.bits);
        return found == t.ghost_group.end() ? 0 : found->second;
    };
    const int ga = group(a), gb = group(b);
    return ga == 0 || gb == 0 || ga == gb;
}

// A platform holds only what lands on it from above.
inline bool one_way_platforms(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* manifold, void* context) {
    const HookTable& t = *static_cast<const HookTable*>(context);
    const float up = t.platforms.count(a.bits) != 0 ? 1.0f : t.platforms.count(b.bits) != 0 ? -1.0f : 0.0f;
    return up == 0.0f || up * manifold->normal.y > 0.95f;
}

// sleeping_bin's bin with one-way platforms across it and its shapes in three ghost
// groups, both hooks set: pairs reach them from every stage the workers share (pair
// finding, the narrowphase, continuous sweeps of the fast ones falling through).
inline i2d_world_id hooked_bin(const i2d_world_def& wd) {
    static std::deque<HookTable> tables;  // one per world built, alive to the end
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    HookTable& table = tables.emplace_back();
    i2d_world_set_custom_filter_callback(world, ghosts_apart, &table);
    i2d_world_set_pre_solve_callback(world, one_way_platforms, &table);
    const i2d_shape_def wall = material(0.6f, 0.0f);
    add_walls(add_ground(world, wall, 12.0f), wall, 12.0f, 20.0f);
    i2d_shape_def platform = material(0.6f, 0.0f);
    platform.enable_pre_solve_events = true;
    for (int k = 0; k < 3; ++k) {
        const i2d_body_id body = add_body(world, I2D_BODY_STATIC, i2d_vec2{-6.0f + 6.0f * float(k), 3.0f + 3.0f * float(k)});
        table.platforms.insert(i2d_shape_create_box(body, &platform, 3.0f, 0.1f).bits);
    }
    for (int i = 0; i < 450; ++i) {
        const float x = -11.0f + 0.72f * float(i % 30) + 0.04f * float(i % 7);
        const float y = 1.0f + 0.8f * float(i / 30);
        const i2d_body_id body = add_body(world, I2D_BODY_DYNAMIC, i2d_vec2{x, y}, 0.13f * float(i % 11));
        i2d_shape_def def = material(0.5f, (i % 7 == 0) ? 0.5f : 0.0f, bin_rolling_resistance);
        def.enable_custom_filtering = true;
        add_mixed_shape(body, i, &def);
        i2d_shape_id shape = I2D_NULL_SHAPE_ID;
        i2d_body_get_shapes(body, &shape, 1);
        table.ghost_group[shape.bits] = i % 3;
    }
    return world;
}

}  // namespace det
