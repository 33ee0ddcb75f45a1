// SPDX-License-Identifier: MIT
// The README's hello world through the C++17 wrappers: the World owns the world and
// destroys it at the end of main; errors throw, or fill a Status where asked.
#include <impulse2d/impulse2d.hpp>

#include <cmath>
#include <cstdio>

int main() {
    try {
        impulse2d::World world;  // gravity (0, -10)

        impulse2d::Body ground = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, -1.0f}));
        ground.create_box(50.0f, 1.0f);  // top face at y = 0

        i2d_shape_def bouncy = i2d_default_shape_def();
        bouncy.restitution = 0.5f;
        impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0.0f, 4.0f}));
        ball.create_circle(0.5f, {0.0f, 0.0f}, bouncy);

        for (int i = 0; i < 120; ++i) {
            world.step(1.0f / 60.0f, 4);
        }
        const i2d_vec2 p = ball.position();
        std::printf("ball at (%.2f, %.2f)\n", p.x, p.y);

        impulse2d::Status status;  // this call reports instead of throwing
        ball.set_linear_velocity({NAN, 0.0f}, status);
        std::printf("refused: %s\n", status.message.c_str());

        ball.set_linear_velocity({NAN, 0.0f});  // and this one throws
    } catch (const impulse2d::Error& e) {
        std::printf("thrown: %s\n", e.what());
        return 0;
    }
    return 1;
}
