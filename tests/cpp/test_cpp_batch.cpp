// SPDX-License-Identifier: MIT
// impulse2d::step_worlds: a vector of Worlds stepped in one call, each as World::step
// steps it alone; a bad entry throws with the library's message and nothing moves.
#include <vector>

#include "check.h"
#include "cpp_fixture.hpp"

namespace {

// A ball dropped from 1 + index metres onto a ground.
impulse2d::World make_drop(int index) {
    impulse2d::World world;
    cpp_fixture::make_ground(world);
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 1.0f + float(index)}));
    ball.create_circle(0.25f);
    return world;
}

}  // namespace

I2D_TEST(cpp_step_worlds_matches_each_world_stepped_alone) {
    std::vector<impulse2d::World> batch, alone;
    for (int i = 0; i < 8; ++i) {
        batch.push_back(make_drop(i));
        alone.push_back(make_drop(i));
    }
    i2d_batch_def def = i2d_default_batch_def();
    def.worker_count = 2;
    for (int s = 0; s < 90; ++s) {
        impulse2d::step_worlds(batch, 1.0f / 60.0f, 4, def);
        for (impulse2d::World& world : alone) {
            world.step(1.0f / 60.0f, 4);
        }
    }
    for (std::size_t i = 0; i < batch.size(); ++i) {
        I2D_CHECK(batch[i].state_hash() == alone[i].state_hash());
    }
}

I2D_TEST(cpp_step_worlds_throws_on_a_repeated_world_and_steps_none) {
    std::vector<impulse2d::World> worlds;
    worlds.push_back(make_drop(0));
    worlds.push_back(make_drop(1));
    const uint64_t before = worlds[0].state_hash();
    std::vector<i2d_world_id> ids = {worlds[0].id(), worlds[1].id(), worlds[0].id()};
    struct IdsAsWorlds {
        i2d_world_id id_;
        i2d_world_id id() const { return id_; }
    };
    std::vector<IdsAsWorlds> repeated = {{ids[0]}, {ids[1]}, {ids[2]}};
    I2D_CHECK(cpp_fixture::throws([&] { impulse2d::step_worlds(repeated); }, I2D_ERR_INVALID_ARGUMENT,
                                  "worlds[2]: the world is listed twice"));
    I2D_CHECK(worlds[0].state_hash() == before);
    impulse2d::Status status;
    impulse2d::step_worlds(repeated, 1.0f / 60.0f, 4, i2d_default_batch_def(), status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(worlds[0].state_hash() == before);
}
