// SPDX-License-Identifier: MIT
// World::draw, the C++ wrapper of i2d_world_draw: captureless lambdas as callbacks see
// each shape in its body's colour, and a refused def throws or fills the Status.
#include <impulse2d/impulse2d.hpp>

#include <cstring>
#include <string>
#include <vector>

#include "check.h"

namespace {

struct Drawn {
    std::vector<i2d_color> polygons;
    std::vector<i2d_vec2> circle_centers;
    int segments = 0;
};

i2d_debug_draw counting_draw(Drawn& drawn) {
    i2d_debug_draw draw = i2d_default_debug_draw();
    draw.draw_solid_polygon = [](i2d_transform, const i2d_vec2*, int32_t, float, i2d_color color, void* context) {
        static_cast<Drawn*>(context)->polygons.push_back(color);
    };
    draw.draw_solid_circle = [](i2d_transform xf, float, i2d_color, void* context) {
        static_cast<Drawn*>(context)->circle_centers.push_back(xf.p);
    };
    draw.draw_segment = [](i2d_vec2, i2d_vec2, i2d_color, void* context) { ++static_cast<Drawn*>(context)->segments; };
    draw.context = &drawn;
    return draw;
}

}  // namespace

I2D_TEST(cpp_debug_draw_sees_each_shape) {
    impulse2d::World world;
    impulse2d::Body ground = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, -1.0f}));
    ground.create_box(10.0f, 1.0f);
    impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {2.0f, 3.0f}));
    ball.create_circle(0.5f);

    Drawn drawn;
    const i2d_debug_draw draw = counting_draw(drawn);
    world.draw(draw);
    I2D_CHECK(drawn.polygons.size() == 1 && drawn.polygons[0] == I2D_COLOR_STATIC);
    I2D_REQUIRE(drawn.circle_centers.size() == 1);
    I2D_CHECK(drawn.circle_centers[0].x == 2.0f && drawn.circle_centers[0].y == 3.0f);
    I2D_CHECK(drawn.segments == 0);

    impulse2d::Status status;
    drawn = Drawn{};
    world.draw(draw, status);
    I2D_CHECK(status.ok() && drawn.polygons.size() == 1 && drawn.circle_centers.size() == 1);
}

I2D_TEST(cpp_debug_draw_refuses_an_uninitialised_def) {
    impulse2d::World world;
    world.create_body(impulse2d::body_def(I2D_BODY_STATIC)).create_box(1.0f, 1.0f);
    Drawn drawn;
    i2d_debug_draw draw = counting_draw(drawn);
    draw.internal_cookie = 0;
    bool threw = false;
    try {
        world.draw(draw);
    } catch (const impulse2d::Error& e) {
        threw = e.status() == I2D_ERR_INVALID_ARGUMENT && std::string(e.what()).find("debug_draw") != std::string::npos;
    }
    I2D_CHECK(threw);
    impulse2d::Status status;
    world.draw(draw, status);
    I2D_CHECK(status.code == I2D_ERR_INVALID_ARGUMENT && !status.message.empty());
    I2D_CHECK(drawn.polygons.empty());
}
