// SPDX-License-Identifier: MIT
// World::draw below the C API: what no public call can set up. A quarantined body (a
// state made non-finite inside the core, as test_quarantine.cpp does) is drawn in its
// colour; graph colours name only live contacts, after a body is destroyed between steps
// and after a rollback state is restored (which forgets the colouring).
#include <cmath>
#include <limits>
#include <vector>

#include "check.h"
#include "dynamics/debug_draw.hpp"
#include "world_fixture.hpp"

using namespace i2d;

using unit::add_box_body;
using unit::step;

namespace {

constexpr float half_size = 0.5f;   // boxes, m
constexpr float ground_top = 0.5f;  // m

// The colours of the filled polygons and of the points, in the order drawn.
struct Seen {
    std::vector<DrawColor> polygons;
    std::vector<DrawColor> points;
    int non_finite = 0;
};

void on_polygon(const Transform& xf, const Vec2*, int32_t, float, DrawColor color, void* context) {
    auto* seen = static_cast<Seen*>(context);
    seen->polygons.push_back(color);
    seen->non_finite += !(std::isfinite(xf.p.x) && std::isfinite(xf.p.y));
}

void on_point(Vec2 p, float, DrawColor color, void* context) {
    auto* seen = static_cast<Seen*>(context);
    seen->points.push_back(color);
    seen->non_finite += !(std::isfinite(p.x) && std::isfinite(p.y));
}

DebugDraw counting(Seen& seen) {
    DebugDraw draw;
    draw.sink.solid_polygon = on_polygon;
    draw.sink.point = on_point;
    draw.sink.context = &seen;
    return draw;
}

int count_of(const std::vector<DrawColor>& colors, DrawColor color) {
    int n = 0;
    for (const DrawColor c : colors) {
        n += c == color;
    }
    return n;
}

bool in_palette(DrawColor color) {
    for (const DrawColor c : draw_colors::graph_palette) {
        if (c == color) {
            return true;
        }
    }
    return color == draw_colors::graph_overflow;
}

WorldDef awake_world() {
    WorldDef def;
    def.enable_sleep = false;
    return def;
}

}  // namespace

I2D_TEST(unit_world_draw_quarantined_body_in_its_colour) {
    World world{awake_world()};
    add_box_body(world, BodyType::static_body, {0.0f, 0.0f}, 40.0f, ground_top);
    const Vec2 left{-5.0f, ground_top + half_size}, right{5.0f, ground_top + half_size};
    const int32_t poisoned = add_box_body(world, BodyType::dynamic, left, half_size, half_size);
    add_box_body(world, BodyType::dynamic, right, half_size, half_size);
    step(world, 10);
    WorldProbe::body(world, poisoned).linear_velocity = {std::numeric_limits<float>::quiet_NaN(), 0.0f};
    step(world, 1);
    I2D_REQUIRE(world.is_quarantined(poisoned));

    Seen seen;
    world.draw(counting(seen));
    I2D_CHECK(seen.polygons.size() == 3);
    I2D_CHECK(count_of(seen.polygons, draw_colors::quarantined) == 1);
    I2D_CHECK(count_of(seen.polygons, draw_colors::static_body) == 1);  // the quarantined box is static now
    I2D_CHECK(count_of(seen.polygons, draw_colors::awake) == 1);
    I2D_CHECK(seen.non_finite == 0);
}

I2D_TEST(unit_world_draw_graph_colors_name_live_contacts) {
    World world{awake_world()};
    add_box_body(world, BodyType::static_body, {0.0f, 0.0f}, 40.0f, ground_top);
    std::vector<int32_t> boxes;
    for (int32_t i = 0; i < 4; ++i) {
        boxes.push_back(add_box_body(world, BodyType::dynamic, {0.0f, ground_top + half_size + 1.0f * float(i)},
                                     half_size, half_size));
    }
    step(world, 30);
    Seen seen;
    DebugDraw draw = counting(seen);
    draw.options.shapes = false;
    draw.options.graph_colors = true;
    world.draw(draw);
    I2D_REQUIRE(seen.points.size() >= 8);  // four contacts of two points
    for (const DrawColor c : seen.points) {
        I2D_CHECK(in_palette(c));
    }

    // Destroyed between steps: the colouring still names its contacts, which are gone.
    world.destroy_body(boxes[3]);
    world.destroy_body(boxes[1]);
    seen = Seen{};
    world.draw(draw);
    I2D_CHECK(seen.points.size() == 2);  // the bottom box on the ground
    I2D_CHECK(seen.non_finite == 0);

    // A restore forgets the colouring: the points take their plain colours.
    std::vector<unsigned char> state(world.state_size());
    I2D_REQUIRE(world.save_state(state.data(), state.size()) == state.size());
    I2D_REQUIRE(world.restore_state(state.data(), state.size(), [](const World&) { return true; }) == nullptr);
    seen = Seen{};
    world.draw(draw);
    I2D_CHECK(seen.points.size() == 2);
    const int plain = count_of(seen.points, draw_colors::contact_point) +
                      count_of(seen.points, draw_colors::speculative_point);
    I2D_CHECK(plain == 2);
}

I2D_TEST(unit_world_draw_is_locked_like_a_query) {
    World world{awake_world()};
    add_box_body(world, BodyType::static_body, {0.0f, 0.0f}, 4.0f, ground_top);
    struct Probe {
        const World* world;
        bool locked = false;
    } probe{&world};
    DebugDraw draw;
    draw.sink.solid_polygon = [](const Transform&, const Vec2*, int32_t, float, DrawColor, void* context) {
        auto* p = static_cast<Probe*>(context);
        p->locked = p->world->is_locked();
    };
    draw.sink.context = &probe;
    world.draw(draw);
    I2D_CHECK(probe.locked);
    I2D_CHECK(!world.is_locked());
}
