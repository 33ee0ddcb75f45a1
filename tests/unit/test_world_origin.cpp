// SPDX-License-Identifier: MIT
// World::shift_origin in the core: every box (shapes' tight, fat and ahead boxes, the
// trees' nodes) is the old one less the origin, bit for bit, the world's cross-checks
// (World::validate, under I2D_VALIDATE) hold right after the shift and at every step
// after it, and bodies asleep stay asleep.
#include <cstring>
#include <vector>

#include "check.h"
#include "world_fixture.hpp"

using namespace i2d;
using unit::add_body;
using unit::add_box_body;
using unit::add_circle;
using unit::step_validated;

namespace {

constexpr Vec2 new_origin{1000.0f, -500.0f};

bool same_box(const AABB& a, const AABB& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every slot of a pool, live or not, by index.
template <class T>
std::vector<T> copy_of(const Pool<T>& pool) {
    std::vector<T> out;
    for (int32_t i = 0; i < pool.capacity(); ++i) {
        out.push_back(pool[i]);
    }
    return out;
}

// A ground, a stack left to fall asleep, a pendulum, a fast bullet and a kinematic
// platform: sleeping and awake islands, a joint, contacts, every tree.
struct OriginScene {
    World world{WorldDef{}};
    int32_t pendulum = null_index, stack_top = null_index;

    OriginScene() {
        add_box_body(world, BodyType::static_body, {0.0f, -0.5f}, 30.0f, 0.5f);
        for (int32_t i = 0; i < 4; ++i) {
            stack_top = add_box_body(world, BodyType::dynamic, {-10.0f, 0.5f + float(i)}, 0.5f, 0.5f);
        }
        const int32_t pivot = add_body(world, BodyType::static_body, {4.0f, 6.0f});
        pendulum = add_body(world, BodyType::dynamic, {6.0f, 6.0f});
        add_circle(world, pendulum, {0.0f, 0.0f}, 0.25f);
        JointDef hinge;
        hinge.type = JointType::revolute;
        hinge.body_a = pivot;
        hinge.body_b = pendulum;
        hinge.local_anchor_b = {-2.0f, 0.0f};
        world.create_joint(hinge);
        const int32_t bullet = add_box_body(world, BodyType::dynamic, {-5.0f, 3.0f}, 0.1f, 0.1f);
        world.set_linear_velocity(bullet, {200.0f, -30.0f});
        const int32_t platform = add_box_body(world, BodyType::kinematic, {12.0f, 2.0f}, 2.0f, 0.2f);
        world.set_linear_velocity(platform, {-1.0f, 0.0f});
    }
};

}  // namespace

I2D_TEST(unit_world_origin_shift_moves_every_box_exactly) {
    OriginScene scene;
    World& world = scene.world;
    step_validated(world, 60);
    I2D_REQUIRE(!world.is_awake(scene.stack_top) && world.is_awake(scene.pendulum));
    const std::vector<Shape> before = copy_of(world.shapes());
    const std::vector<Body> bodies = copy_of(world.bodies());
    world.shift_origin(new_origin);
    world.validate();
    const BroadPhase& broad_phase = WorldProbe::broad_phase(world);
    for (int32_t i = 0; i < world.shapes().capacity(); ++i) {
        if (!world.shapes().is_live(i)) {
            continue;
        }
        const Shape& s = world.shapes()[i];
        I2D_CHECK(same_box(s.aabb, relative_to(before[std::size_t(i)].aabb, new_origin)));
        I2D_CHECK(same_box(s.fat_aabb, relative_to(before[std::size_t(i)].fat_aabb, new_origin)));
        I2D_CHECK(same_box(s.ahead_aabb, relative_to(before[std::size_t(i)].ahead_aabb, new_origin)));
        I2D_CHECK(same_box(broad_phase.fat_aabb(s.proxy_key), s.fat_aabb));
        I2D_CHECK(same_box(broad_phase.ahead_aabb(s.proxy_key), s.ahead_aabb));
    }
    for (int32_t i = 0; i < world.bodies().capacity(); ++i) {
        if (world.bodies().is_live(i)) {
            const Body& b = world.bodies()[i];
            I2D_CHECK(b.transform.p == bodies[std::size_t(i)].transform.p - new_origin);
            I2D_CHECK(b.center == bodies[std::size_t(i)].center - new_origin);
            I2D_CHECK(b.center0 == bodies[std::size_t(i)].center0 - new_origin);
        }
    }
    I2D_CHECK(!world.is_awake(scene.stack_top) && world.is_awake(scene.pendulum));
    step_validated(world, 100);
    I2D_CHECK(!world.is_awake(scene.stack_top));
}
