// SPDX-License-Identifier: MIT
// Contact hit events against closed form: a ball dropped from h meets the ground at
// sqrt(2 g h); impacts below the world's threshold, or on shapes that did not opt in,
// report nothing. And sensors report fast bodies that crossed them within one step.
#include <cmath>
#include <initializer_list>
#include <cstdio>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

struct Hits {
    int count = 0;
    double speed = 0.0;  // of the last hit
    double normal_y = 0.0;
    double point_y = 0.0;
    int begins = 0;                // contact begin events
    int begin_points = 0;          // manifold points of the last one
    double begin_normal_y = 0.0;   // its normal
    double begin_point_y = 1e9;    // and its first point
};

// A ball of radius 0.1 whose bottom starts `height` above the ground (top at y = 0),
// dropped with restitution 0 and stepped for 2 s; every hit event is counted.
Hits drop_ball(double height, float threshold, bool opt_in) {
    i2d_world_def def = i2d_default_world_def();
    def.hit_event_threshold = threshold;
    Scene scene(def);
    scene.ground();
    constexpr float radius = 0.1f;
    const i2d_body_def ball_def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0.0f, float(height) + radius});
    i2d_body_id ball = i2d_body_create(scene.world, &ball_def);
    i2d_shape_def sd = i2d_default_shape_def();
    sd.enable_hit_events = opt_in;
    const i2d_circle circle{i2d_vec2{0, 0}, radius};
    Hits hits;
    if (I2D_IS_NULL(i2d_shape_create_circle(ball, &sd, &circle))) {
        ++i2d_check_failures;
        return hits;
    }
    for (int s = 0; s < steps_for(2.0) && scene.step(); ++s) {
        const i2d_contact_events e = i2d_world_get_contact_events(scene.world);
        for (int k = 0; k < e.begin_count; ++k) {
            ++hits.begins;
            hits.begin_points = e.begin_events[k].manifold.point_count;
            hits.begin_normal_y = e.begin_events[k].manifold.normal.y;
            hits.begin_point_y = e.begin_events[k].manifold.points[0].point.y;
        }
        for (int k = 0; k < e.hit_count; ++k) {
            ++hits.count;
            hits.speed = e.hit_events[k].approach_speed;
            hits.normal_y = e.hit_events[k].normal.y;
            hits.point_y = e.hit_events[k].point.y;
        }
    }
    return hits;
}

}  // namespace

I2D_TEST(phys_hit_event_speed_is_free_fall_speed) {
    for (const double h : {0.5, 2.0, 7.5}) {
        const int before = i2d_check_failures;
        const Hits hits = drop_ball(h, 1.0f, true);
        const double expected = std::sqrt(2.0 * g * h);
        fprintf(stderr, "    h = %.1f m: %d hit(s), speed %.4f m/s, expected %.4f\n", h, hits.count, hits.speed, expected);
        I2D_CHECK(hits.count == 1);
        I2D_CHECK_NEAR(hits.speed, expected, 0.01 * expected);
        I2D_CHECK_NEAR(std::fabs(hits.normal_y), 1.0, 1e-3);  // straight down onto the ground
        I2D_CHECK_NEAR(hits.point_y, 0.0, 0.05);              // where the ball met the ground
        // The landing's begin event carries the contact's manifold.
        I2D_CHECK(hits.begins == 1 && hits.begin_points == 1);
        I2D_CHECK_NEAR(std::fabs(hits.begin_normal_y), 1.0, 1e-3);
        I2D_CHECK_NEAR(hits.begin_point_y, 0.0, 0.05);
        char what[64];
        snprintf(what, sizeof what, "dropped from %.1f m", h);
        report_case(before, what);
    }
}

I2D_TEST(phys_hit_events_none_below_threshold_or_without_opt_in) {
    // sqrt(2 g 0.02) = 0.63 m/s: below the default 1 m/s.
    I2D_CHECK(drop_ball(0.02, 1.0f, true).count == 0);
    // 6.3 m/s against a threshold of 10 m/s.
    I2D_CHECK(drop_ball(2.0, 10.0f, true).count == 0);
    // Fast enough, but the shapes did not ask for hit events.
    I2D_CHECK(drop_ball(2.0, 1.0f, false).count == 0);
    // The same drop above the threshold does report (so the three above can fail).
    I2D_CHECK(drop_ball(2.0, 5.0f, true).count == 1);
}

namespace {

// A thin sensor strip and a ball at 300 m/s that crosses it within one step.
struct SensorCount {
    int begins = 0, ends = 0;
    bool same_step = false;
};

SensorCount fire_through_sensor(bool continuous) {
    i2d_world_def def = Scene::zero_gravity_def();
    def.enable_continuous = continuous;
    Scene scene(def);
    const i2d_body_def strip_def = body_def(I2D_BODY_STATIC, i2d_vec2{0, 0});
    i2d_body_id strip = i2d_body_create(scene.world, &strip_def);
    i2d_shape_def sensor = i2d_default_shape_def();
    sensor.is_sensor = true;
    i2d_shape_create_box(strip, &sensor, 0.05f, 1.0f);
    i2d_body_id ball = scene.dynamic_circle(i2d_vec2{-2.2f, 0.1f}, 0.05f, Material{}, i2d_vec2{300.0f, 0.0f});
    SensorCount count;
    if (I2D_IS_NULL(ball)) {
        ++i2d_check_failures;
        return count;
    }
    for (int s = 0; s < 4 && scene.step(); ++s) {
        const i2d_sensor_events e = i2d_world_get_sensor_events(scene.world);
        count.begins += e.begin_count;
        count.ends += e.end_count;
        count.same_step = count.same_step || (e.begin_count == 1 && e.end_count == 1);
    }
    return count;
}

}  // namespace

I2D_TEST(phys_sensor_reports_a_fast_body_that_crossed_it_within_a_step) {
    const SensorCount with = fire_through_sensor(true);
    const SensorCount without = fire_through_sensor(false);
    fprintf(stderr, "    with continuous: %d begin, %d end; without: %d begin, %d end\n", with.begins, with.ends,
            without.begins, without.ends);
    I2D_CHECK(with.begins == 1 && with.ends == 1 && with.same_step);
    I2D_CHECK(without.begins == 0);  // the control: the ball is never inside at a step's end
}
