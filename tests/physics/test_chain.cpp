// SPDX-License-Identifier: MIT
// Chains: a box sliding over a 200-segment flat chain glides without bumps, where the same
// floor of separate segments bumps it (the control); chains are one-sided.
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

constexpr int segments = 200;
constexpr float segment_length = 0.5f;
constexpr float box_half = 0.2f;  // smaller than a segment: it crosses a seam every 0.5 m
constexpr float slide_speed = 4.0f;

// The floor y = 0 from x = -1 to x = 99, as one chain (listed right to left, so that its
// normals point up) or as separate two-sided segments.
void build_floor(Scene& scene, bool chain) {
    const i2d_body_def def = body_def(I2D_BODY_STATIC, i2d_vec2{0, 0});
    i2d_body_id ground = i2d_body_create(scene.world, &def);
    std::vector<i2d_vec2> points;
    points.push_back(i2d_vec2{99.0f + segment_length, 0.0f});  // ghost
    for (int i = segments; i >= 0; --i) {
        points.push_back(i2d_vec2{-1.0f + float(i) * segment_length, 0.0f});
    }
    points.push_back(i2d_vec2{-1.0f - segment_length, 0.0f});  // ghost
    i2d_surface_material frictionless{0.0f, 0.0f, 0.0f, 0.0f};
    if (chain) {
        i2d_chain_def cd = i2d_default_chain_def();
        cd.points = points.data();
        cd.count = int32_t(points.size());
        cd.materials = &frictionless;
        cd.material_count = 1;
        I2D_CHECK(!I2D_IS_NULL(i2d_chain_create(ground, &cd)));
        return;
    }
    i2d_shape_def sd = i2d_default_shape_def();
    sd.friction = 0.0f;
    for (std::size_t i = 1; i + 2 < points.size(); ++i) {
        I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_segment(ground, &sd, points[i], points[i + 1])));
    }
}

struct Slide {
    double max_vertical_speed;  // m/s, over the slide
    double min_speed, max_speed;
    double distance;
};

// A frictionless box settles on the floor, then slides at 4 m/s for 10 s (80 seams).
Slide slide_box(bool chain) {
    Scene scene;
    build_floor(scene, chain);
    Material slick;
    slick.friction = 0.0f;
    i2d_body_id box = scene.dynamic_box(i2d_vec2{1.0f, box_half}, box_half, box_half, slick);
    Slide s{0.0, 1e9, 0.0, 0.0};
    if (I2D_IS_NULL(box)) {
        ++i2d_check_failures;
        return s;
    }
    scene.step(steps_for(0.5));  // at rest on the floor
    i2d_body_set_linear_velocity(box, i2d_vec2{slide_speed, 0.0f});
    const double x0 = position(box).x;
    for (int k = 0; k < steps_for(10.0) && scene.step(); ++k) {
        const i2d_vec2 v = velocity(box);
        s.max_vertical_speed = std::fmax(s.max_vertical_speed, std::fabs(double(v.y)));
        s.min_speed = std::fmin(s.min_speed, double(v.x));
        s.max_speed = std::fmax(s.max_speed, double(v.x));
    }
    s.distance = position(box).x - x0;
    return s;
}

}  // namespace

I2D_TEST(phys_chain_box_slides_over_seams_without_bumps) {
    const Slide chain = slide_box(true);
    const Slide separate = slide_box(false);
    fprintf(stderr, "    chain: |vy| <= %.3g m/s, vx in [%.4f, %.4f], %.2f m; separate segments: |vy| <= %.3g, vx in "
            "[%.4f, %.4f], %.2f m\n",
            chain.max_vertical_speed, chain.min_speed, chain.max_speed, chain.distance, separate.max_vertical_speed,
            separate.min_speed, separate.max_speed, separate.distance);
    I2D_CHECK(chain.max_vertical_speed <= 0.001);
    I2D_CHECK_NEAR(chain.min_speed, slide_speed, 0.001 * slide_speed);
    I2D_CHECK_NEAR(chain.max_speed, slide_speed, 0.001 * slide_speed);
    I2D_CHECK_NEAR(chain.distance, 10.0 * slide_speed, 0.01 * 10.0 * slide_speed);
    // The control: separate two-sided segments catch the box at their seams.
    I2D_CHECK(separate.max_vertical_speed > 0.001 || separate.min_speed < 0.99 * slide_speed);
}

namespace {

// A ball fired up at the floor chain from below (its back side), or dropped onto it.
double ball_end_height(bool from_below, bool continuous) {
    i2d_world_def def = i2d_default_world_def();
    def.enable_continuous = continuous;
    Scene scene(def);
    build_floor(scene, true);
    const float y = from_below ? -1.0f : 1.0f;
    const float vy = from_below ? 20.0f : -20.0f;
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{10.0f, y}, 0.1f, Material{}, i2d_vec2{0.0f, vy});
    if (I2D_IS_NULL(ball)) {
        ++i2d_check_failures;
        return 0.0;
    }
    scene.step(steps_for(0.25));
    return position(ball).y;
}

}  // namespace

I2D_TEST(phys_chain_is_one_sided) {
    // From below it passes and flies on (20 m/s up, 0.25 s: about 3.7 m above the start).
    const double below = ball_end_height(true, true);
    // From above it lands and rests on the floor (centre at its radius).
    const double above = ball_end_height(false, true);
    fprintf(stderr, "    from below: ends at y = %.3f; from above: ends at y = %.3f\n", below, above);
    I2D_CHECK(below > 1.0);
    I2D_CHECK_NEAR(above, 0.1, 0.01);
    // Without continuous collision the same holds (speculative contacts, one-sided too).
    I2D_CHECK(ball_end_height(true, false) > 1.0);
    I2D_CHECK_NEAR(ball_end_height(false, false), 0.1, 0.01);
}

I2D_TEST(phys_chain_loop_listed_clockwise_keeps_bodies_inside) {
    Scene scene;
    const i2d_body_def def = body_def(I2D_BODY_STATIC, i2d_vec2{0, 0});
    i2d_body_id ground = i2d_body_create(scene.world, &def);
    // A 4 m square, clockwise: top left, top right, bottom right, bottom left.
    const i2d_vec2 square[4] = {{-2.0f, 4.0f}, {2.0f, 4.0f}, {2.0f, 0.0f}, {-2.0f, 0.0f}};
    i2d_chain_def cd = i2d_default_chain_def();
    cd.points = square;
    cd.count = 4;
    cd.is_loop = true;
    i2d_chain_id chain = i2d_chain_create(ground, &cd);
    I2D_REQUIRE(!I2D_IS_NULL(chain));
    I2D_CHECK(i2d_chain_get_segments(chain, nullptr, 0) == 4);
    // Balls thrown at every wall at 30 m/s stay in the box.
    Material bouncy = with_restitution(0.8f);
    i2d_body_id balls[4];
    const i2d_vec2 throws[4] = {{30, 5}, {-30, 5}, {5, 30}, {-5, -30}};
    for (int i = 0; i < 4; ++i) {
        balls[i] = scene.dynamic_circle(i2d_vec2{-1.0f + 0.6f * float(i), 2.0f}, 0.1f, bouncy, throws[i]);
    }
    bool inside = true;
    for (int k = 0; k < steps_for(3.0) && scene.step(); ++k) {
        for (i2d_body_id b : balls) {
            const i2d_vec2 p = position(b);
            inside = inside && std::fabs(p.x) < 2.0f && p.y > 0.0f && p.y < 4.0f;
        }
    }
    I2D_CHECK(inside);
}
