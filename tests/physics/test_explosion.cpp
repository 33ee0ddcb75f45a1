// SPDX-License-Identifier: MIT
// i2d_world_explode against its closed form: a disc of radius r and mass m at distance d
// from the blast (to its closest point) leaves at impulse_per_length x 2r x scale / m,
// straight away from the blast, where scale is 1 within the radius and falls linearly to
// 0 over the falloff.
#include "physics_fixture.hpp"

using namespace phys;

namespace {

constexpr float disc_radius = 0.25f;
constexpr double speed_tolerance = 1e-5;  // relative: one float rounding or two

double disc_mass() { return circle_mass(disc_radius, 1.0); }

// The speed a disc gets from the blast at full strength.
double full_speed(const i2d_explosion_def& def) {
    return double(def.impulse_per_length) * 2.0 * disc_radius / disc_mass();
}

i2d_explosion_def blast_at_origin(float radius, float falloff, float impulse_per_length) {
    i2d_explosion_def def = i2d_default_explosion_def();
    def.position = i2d_vec2{0, 0};
    def.radius = radius;
    def.falloff = falloff;
    def.impulse_per_length = impulse_per_length;
    return def;
}

// A disc whose closest point is `gap` from the origin, in direction `angle`.
i2d_body_id disc_at(Scene& s, double gap, double angle, const Material& m = Material{}) {
    const double d = gap + disc_radius;
    return s.dynamic_circle(i2d_vec2{float(d * std::cos(angle)), float(d * std::sin(angle))}, disc_radius, m);
}

}  // namespace

I2D_TEST(phys_explosion_gives_equal_speeds_at_equal_distances_away_from_the_blast) {
    Scene s(Scene::zero_gravity_def());
    const int count = 8;
    std::vector<i2d_body_id> discs;
    for (int i = 0; i < count; ++i) {
        discs.push_back(disc_at(s, 1.5, 2 * pi * i / count));
    }
    const i2d_explosion_def def = blast_at_origin(2.0f, 0.0f, 3.0f);
    I2D_REQUIRE(i2d_world_explode(s.world, &def) == I2D_OK);
    for (const i2d_body_id disc : discs) {
        const i2d_vec2 v = velocity(disc), p = position(disc);
        I2D_CHECK_NEAR(speed(v), full_speed(def), speed_tolerance * full_speed(def));
        // Along the line from the blast: v parallel to p, pointing away.
        I2D_CHECK_NEAR((double(v.x) * p.y - double(v.y) * p.x) / (speed(v) * speed(p)), 0.0, 1e-5);
        I2D_CHECK(double(v.x) * p.x + double(v.y) * p.y > 0);
        // Pushed through its centre: no spin beyond the rounding of the lever arm.
        I2D_CHECK(std::fabs(i2d_body_get_angular_velocity(disc)) < speed_tolerance * full_speed(def) / disc_radius);
    }
}

I2D_TEST(phys_explosion_fades_linearly_over_the_falloff_and_stops_beyond_it) {
    Scene s(Scene::zero_gravity_def());
    const i2d_explosion_def def = blast_at_origin(1.0f, 2.0f, 1.0f);
    const i2d_body_id inside = disc_at(s, 0.5, 0.0);
    const i2d_body_id halfway = disc_at(s, 2.0, pi / 2);     // 1 m into a 2 m falloff
    const i2d_body_id quarter = disc_at(s, 2.5, pi);         // 1.5 m in: a quarter left
    const i2d_body_id beyond = disc_at(s, 3.2, 3 * pi / 2);  // past radius + falloff
    I2D_REQUIRE(i2d_world_explode(s.world, &def) == I2D_OK);
    const double full = full_speed(def);
    I2D_CHECK_NEAR(speed(velocity(inside)), full, speed_tolerance * full);
    I2D_CHECK_NEAR(speed(velocity(halfway)), 0.5 * full, speed_tolerance * full);
    I2D_CHECK_NEAR(speed(velocity(quarter)), 0.25 * full, speed_tolerance * full);
    I2D_CHECK(speed(velocity(beyond)) == 0.0);
}

I2D_TEST(phys_explosion_is_linear_in_its_impulse_and_pulls_when_negative) {
    double speeds[3] = {};
    double outward[3] = {};
    const float impulses[3] = {1.0f, 2.0f, -1.0f};
    for (int k = 0; k < 3; ++k) {
        Scene s(Scene::zero_gravity_def());
        const i2d_body_id disc = disc_at(s, 0.5, 0.3);
        const i2d_explosion_def def = blast_at_origin(1.0f, 0.0f, impulses[k]);
        I2D_REQUIRE(i2d_world_explode(s.world, &def) == I2D_OK);
        const i2d_vec2 v = velocity(disc), p = position(disc);
        speeds[k] = speed(v);
        outward[k] = double(v.x) * p.x + double(v.y) * p.y;
    }
    I2D_CHECK(speeds[1] == 2.0 * speeds[0]);  // doubling a float is exact
    I2D_CHECK(speeds[2] == speeds[0]);
    I2D_CHECK(outward[0] > 0 && outward[2] < 0);
}

I2D_TEST(phys_explosion_pushes_by_the_width_a_shape_turns_to_the_blast) {
    // A 2 m x 0.2 m plank broadside to the blast shows 2 m of outline, end-on 0.2 m: the
    // same mass leaves ten times faster broadside.
    double speeds[2] = {};
    for (int k = 0; k < 2; ++k) {
        Scene s(Scene::zero_gravity_def());
        const bool broadside = k == 0;
        const i2d_body_id plank = broadside ? s.dynamic_box(i2d_vec2{1.1f, 0}, 0.1f, 1.0f)
                                            : s.dynamic_box(i2d_vec2{2.0f, 0}, 1.0f, 0.1f);
        const i2d_explosion_def def = blast_at_origin(3.0f, 0.0f, 1.0f);
        I2D_REQUIRE(i2d_world_explode(s.world, &def) == I2D_OK);
        speeds[k] = speed(velocity(plank));
        I2D_CHECK_NEAR(speeds[k], (broadside ? 2.0 : 0.2) / box_mass(1.0, 0.1, 1.0), 1e-5);
    }
    I2D_CHECK_NEAR(speeds[0] / speeds[1], 10.0, 1e-4);
}

I2D_TEST(phys_explosion_spares_what_its_mask_excludes_sensors_and_fixed_bodies_and_wakes_sleepers) {
    Scene s;
    s.ground();
    const i2d_body_id sleeper = s.dynamic_box(i2d_vec2{0, 0.5f}, 0.5f, 0.5f);
    i2d_body_set_awake(sleeper, false);
    I2D_REQUIRE(!i2d_body_is_awake(sleeper));
    // Category 2 against a blast that pushes only category 1.
    i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{2, 0.5f});
    const i2d_body_id other_category = i2d_body_create(s.world, &def);
    i2d_shape_def sd = i2d_default_shape_def();
    sd.filter.category_bits = 2;
    i2d_shape_create_box(other_category, &sd, 0.5f, 0.5f);
    def.position = i2d_vec2{-2, 0.5f};
    const i2d_body_id sensor_only = i2d_body_create(s.world, &def);
    sd = i2d_default_shape_def();
    sd.is_sensor = true;
    i2d_shape_create_box(sensor_only, &sd, 0.5f, 0.5f);
    const i2d_body_id kinematic = s.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, 2.5f}), 0.5f, 0.5f);

    i2d_explosion_def blast = i2d_default_explosion_def();
    blast.mask_bits = 1;
    blast.position = i2d_vec2{0, 1.5f};
    blast.radius = 5.0f;
    blast.impulse_per_length = 2.0f;
    I2D_REQUIRE(i2d_world_explode(s.world, &blast) == I2D_OK);
    I2D_CHECK(i2d_body_is_awake(sleeper));
    I2D_CHECK(speed(velocity(sleeper)) > 0.0);
    I2D_CHECK(speed(velocity(other_category)) == 0.0);
    I2D_CHECK(speed(velocity(sensor_only)) == 0.0);
    I2D_CHECK(speed(velocity(kinematic)) == 0.0);
}
