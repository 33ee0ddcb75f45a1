// SPDX-License-Identifier: MIT
// Chains: a box sliding over a 200-segment flat chain glides without bumps, where the same
// floor of separate segments bumps it (the control); chains are one-sided, and hold a
// shape that touched their free side when it is crushed through them.
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
    i2d_body_id box = scene.dynamic_box(i2d_vec2{1.0f, box_half}, box_half, box_half, with_friction(0.0f));
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

namespace {

// What happens to a shape resting on the chain floor when a wide kinematic plate comes
// down at 2 m/s until its underside is 5 cm below the floor's line (pressing the shape's
// centre behind the line), then rises at the same speed for 1.5 s, clear of the shape:
// where the shape's centre ends, and how low it went.
struct Crush {
    double lowest, final_y;
};

enum class CrushedShape { box, circle, capsule };

Crush crush_through_floor(CrushedShape kind) {
    constexpr float half = 0.2f;         // the shape's half height, m
    constexpr float plate_half = 0.5f;   // the plate's half height, m
    constexpr float plate_speed = 2.0f;  // m/s
    constexpr float deepest = -0.05f;    // m: where the plate's underside stops
    constexpr float start_gap = 0.01f;   // m between the shape's top and the plate at first
    constexpr double down_time = (2.0 * half + start_gap - deepest) / plate_speed;
    Scene scene;
    build_floor(scene, true);
    Material grip;
    i2d_body_id shape = I2D_NULL_BODY_ID;
    if (kind == CrushedShape::box) {
        shape = scene.dynamic_box(i2d_vec2{10.0f, half}, half, half, grip);
    } else if (kind == CrushedShape::circle) {
        shape = scene.dynamic_circle(i2d_vec2{10.0f, half}, half, grip);
    } else {
        const i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{10.0f, half});
        shape = i2d_body_create(scene.world, &def);
        i2d_shape_def sd = shape_def(grip);
        const i2d_vec2 end1{-0.3f, 0.0f}, end2{0.3f, 0.0f};
        I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_capsule(shape, &sd, end1, end2, half)));
    }
    i2d_body_def plate_def = body_def(I2D_BODY_KINEMATIC, i2d_vec2{10.0f, 2.0f * half + start_gap + plate_half});
    const i2d_body_id plate = scene.box(plate_def, 5.0f, plate_half, grip);
    Crush c{1e9, 0.0};
    if (I2D_IS_NULL(shape) || I2D_IS_NULL(plate)) {
        ++i2d_check_failures;
        return c;
    }
    scene.step(steps_for(0.5));  // the shape at rest on the floor
    i2d_body_set_linear_velocity(plate, i2d_vec2{0.0f, -plate_speed});
    for (int k = 0; k < steps_for(down_time) && scene.step(); ++k) {
        c.lowest = std::fmin(c.lowest, double(position(shape).y));
    }
    i2d_body_set_linear_velocity(plate, i2d_vec2{0.0f, plate_speed});
    scene.step(steps_for(1.5));  // the plate 2 m above the floor, the shape free
    i2d_body_set_linear_velocity(plate, i2d_vec2{0.0f, 0.0f});
    scene.step(steps_for(2.0));
    c.final_y = position(shape).y;
    return c;
}

}  // namespace

// A shape that rested on the free side and was crushed through the floor by a plate is
// held: the floor pushes it back up once the plate lifts, and it rests on the floor
// again (centre at its half height), where a one-sided floor that let go would have
// dropped it (it fell through before the chain held what it had touched).
I2D_TEST(phys_chain_holds_a_shape_crushed_through_it) {
    const char* names[] = {"box", "circle", "capsule"};
    const CrushedShape kinds[] = {CrushedShape::box, CrushedShape::circle, CrushedShape::capsule};
    for (int i = 0; i < 3; ++i) {
        const Crush c = crush_through_floor(kinds[i]);
        fprintf(stderr, "    %s: lowest centre %.3f m (behind the floor below 0), finally %.4f m\n", names[i],
                c.lowest, c.final_y);
        I2D_CHECK(c.lowest < 0.0);  // the plate did push its centre behind the floor's line
        I2D_CHECK_NEAR(c.final_y, 0.2, 0.01);
    }
}
