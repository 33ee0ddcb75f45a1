// SPDX-License-Identifier: MIT
// The installed C++ header against the installed library.
#include <impulse2d/impulse2d.hpp>

#include <cstdio>

int main() {
    try {
        impulse2d::World world;
        impulse2d::Body box = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 1.0f}));
        box.create_box(0.5f, 0.5f);
        world.step();
        std::printf("installed impulse2d.hpp works: box at y = %.3f\n", box.position().y);
        return box.position().y < 1.0f ? 0 : 1;
    } catch (const impulse2d::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
