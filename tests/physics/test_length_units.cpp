// SPDX-License-Identifier: MIT
// Length units per world: a scene built in pixels (50 to the metre, every length, speed
// and acceleration times 50, the world def from i2d_default_world_def_in_units) moves as
// the same scene in metres, scaled: the engine's own tolerances (slop, speculative
// distance, box margins, manifold-keeping distances, continuous collision) follow the
// world's unit. The two worlds live side by side and are stepped in turn, so the unit is
// each world's own, not the process's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

/// The pixel world's unit, and how long both worlds run.
constexpr float pixels_per_meter = 50.0f;
constexpr int scene_steps = 300;
/// Positions agree within this share of their size (at least a metre's worth).
constexpr double position_tolerance = 1e-3;
/// Each body falls asleep within this many steps in both worlds.
constexpr int sleep_step_tolerance = 5;

/// Rolling resistance of the balls, so that they stop on the ground and sleep.
constexpr float ball_rolling_resistance = 0.2f;

/// A scene in a world of `units` length units to the metre: every length and speed of it
/// times `units`, and the density divided by units^2 so that the masses are the same.
class ScaledScene {
public:
    explicit ScaledScene(float units) : scene_(world_def(units)), units_(units) {}

    bool build() {
        // The ground (top at y = 0) and a ramp of 0.35 rad whose lower end meets it.
        add(I2D_BODY_STATIC, {0.0f, -0.5f}, 0.0, 15.0f, 0.5f);
        add(I2D_BODY_STATIC, {-6.0f, 1.2f}, 0.35, 4.0f, 0.25f);
        // Boxes dropped on the ground and on the ramp (friction 0.6 holds them there),
        // one turned so that it lands on a corner and tips over.
        add(I2D_BODY_DYNAMIC, {1.0f, 2.0f}, 0.0, 0.5f, 0.5f);
        add(I2D_BODY_DYNAMIC, {1.2f, 4.0f}, 0.0, 0.4f, 0.3f);
        add(I2D_BODY_DYNAMIC, {4.0f, 3.0f}, 0.6, 0.5f, 0.25f);
        add(I2D_BODY_DYNAMIC, {-6.5f, 3.5f}, 0.35, 0.5f, 0.5f);
        // Balls: one on the ground, one on a box, one rolling down the ramp.
        ball({7.0f, 1.5f}, 0.4f);
        ball({1.0f, 6.0f}, 0.3f);
        ball({-8.0f, 3.5f}, 0.35f);
        return ok_;
    }

    bool step() { return scene_.step(); }

    /// The dynamic bodies' positions, back in metres.
    std::vector<Point> positions_in_meters() const {
        std::vector<Point> out;
        for (const i2d_body_id b : dynamic_) {
            const i2d_vec2 p = position(b);
            out.push_back(Point{double(p.x) / units_, double(p.y) / units_});
        }
        return out;
    }

    const std::vector<i2d_body_id>& dynamic_bodies() const { return dynamic_; }
    i2d_world_id world() const { return scene_.world; }

private:
public:
    static i2d_world_def world_def(float units) {
        // gravity, slop and the speed thresholds in the world's unit
        return units == 1.0f ? i2d_default_world_def() : i2d_default_world_def_in_units(units);
    }

private:

    i2d_vec2 scaled(i2d_vec2 v) const { return i2d_vec2{units_ * v.x, units_ * v.y}; }
    float density() const { return 1.0f / (units_ * units_); }

    void add(i2d_body_type type, i2d_vec2 position, double angle, float half_width, float half_height) {
        const i2d_body_def def = turned_body_def(type, scaled(position), angle);
        const i2d_body_id body = scene_.box(def, units_ * half_width, units_ * half_height, with_density(density()));
        keep(type, body);
    }

    void ball(i2d_vec2 position, float radius) {
        const i2d_body_def def = body_def(I2D_BODY_DYNAMIC, scaled(position));
        const i2d_body_id body = i2d_body_create(scene_.world, &def);
        i2d_shape_def sd = shape_def(with_density(density()));
        sd.rolling_resistance = ball_rolling_resistance;
        const i2d_circle circle{i2d_vec2{0, 0}, units_ * radius};
        if (I2D_IS_NULL(body) || I2D_IS_NULL(i2d_shape_create_circle(body, &sd, &circle))) {
            fprintf(stderr, "    ball creation failed: %s\n", i2d_last_error_message());
            ok_ = false;
            return;
        }
        keep(I2D_BODY_DYNAMIC, body);
    }

    void keep(i2d_body_type type, i2d_body_id body) {
        ok_ = ok_ && !I2D_IS_NULL(body);
        if (type == I2D_BODY_DYNAMIC && !I2D_IS_NULL(body)) {
            dynamic_.push_back(body);
        }
    }

    Scene scene_;
    float units_;
    std::vector<i2d_body_id> dynamic_;
    bool ok_ = true;
};

}  // namespace

I2D_TEST(phys_units_pixel_scene_moves_as_metre_scene) {
    ScaledScene metres(1.0f), pixels(pixels_per_meter);
    I2D_REQUIRE(metres.build() && pixels.build());
    const size_t count = metres.dynamic_bodies().size();
    // The step at which each body was last seen awake; -1 while it is.
    std::vector<int> asleep_m(count, -1), asleep_p(count, -1);
    for (int s = 1; s <= scene_steps; ++s) {
        I2D_REQUIRE(metres.step() && pixels.step());
        for (size_t i = 0; i < count; ++i) {
            const bool awake_m = i2d_body_is_awake(metres.dynamic_bodies()[i]);
            const bool awake_p = i2d_body_is_awake(pixels.dynamic_bodies()[i]);
            asleep_m[i] = awake_m ? -1 : (asleep_m[i] < 0 ? s : asleep_m[i]);
            asleep_p[i] = awake_p ? -1 : (asleep_p[i] < 0 ? s : asleep_p[i]);
        }
    }
    const std::vector<Point> pm = metres.positions_in_meters(), pp = pixels.positions_in_meters();
    double worst = 0.0;
    for (size_t i = 0; i < count; ++i) {
        const double size = std::max(1.0, std::hypot(pm[i].x, pm[i].y));
        const double off = std::hypot(pp[i].x - pm[i].x, pp[i].y - pm[i].y) / size;
        worst = std::max(worst, off);
        I2D_CHECK(off <= position_tolerance);
        // Every body came to rest, at about the same step in both worlds.
        I2D_CHECK(asleep_m[i] > 0 && asleep_p[i] > 0);
        I2D_CHECK(std::abs(asleep_m[i] - asleep_p[i]) <= sleep_step_tolerance);
        printf("    body %zu: (%.4f, %.4f) m and (%.4f, %.4f) m in pixels; asleep at steps %d and %d\n", i, pm[i].x,
               pm[i].y, pp[i].x, pp[i].y, asleep_m[i], asleep_p[i]);
    }
    printf("    largest relative difference: %.3g\n", worst);
}

// A snapshot of a world in pixels loads (its shapes' margins and bodies' extents are
// checked against its own unit's tolerances) and steps on as the world it was taken of.
I2D_TEST(phys_units_pixel_world_snapshot_continues) {
    ScaledScene pixels(pixels_per_meter);
    I2D_REQUIRE(pixels.build());
    constexpr int before = 40, after = 60;
    for (int s = 0; s < before; ++s) {
        I2D_REQUIRE(pixels.step());
    }
    std::vector<unsigned char> bytes(i2d_world_get_snapshot_size(pixels.world()));
    size_t written = 0;
    I2D_CHECK_STATUS(i2d_world_save_snapshot(pixels.world(), bytes.data(), bytes.size(), &written), I2D_OK);
    const i2d_world_def runtime = ScaledScene::world_def(pixels_per_meter);
    Scene copy(runtime);
    i2d_world_destroy(copy.world);
    copy.world = i2d_world_create_from_snapshot(bytes.data(), written, &runtime);
    I2D_REQUIRE(!I2D_IS_NULL(copy.world));
    for (int s = 0; s < after; ++s) {
        I2D_REQUIRE(pixels.step() && copy.step());
    }
    I2D_CHECK(i2d_world_get_state_hash(copy.world) == i2d_world_get_state_hash(pixels.world()));
}
