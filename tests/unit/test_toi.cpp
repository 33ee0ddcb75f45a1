// SPDX-License-Identifier: MIT
// Shape proxies, the exact core distance and the time of impact, against brute force:
// core_gap of brute_geometry.hpp for distances, and fine sampling of the motion for the
// time of impact (never late, and touching within the tolerance when it says so).
#include <cmath>
#include <cstdio>

#include "brute_geometry.hpp"
#include "check.h"
#include "collision/shape_proxy.hpp"
#include "collision/toi.hpp"
#include "test_rng.hpp"
#include "world_fixture.hpp"

using namespace i2d;
using namespace brute;
using unit::box_geometry;

namespace {

std::vector<P> core_points(const ShapeProxy& p) {
    std::vector<P> out;
    for (int32_t i = 0; i < p.count; ++i) {
        out.push_back({p.points[i].x, p.points[i].y});
    }
    return out;
}

}  // namespace

I2D_TEST(unit_core_distance_matches_brute_force) {
    TestRng rng(77);
    int failures = 0;
    for (int c = 0; c < 4000; ++c) {
        const Geometry ga = random_geometry(rng, ShapeType(rng.below(random_kind_count)));
        const Geometry gb = random_geometry(rng, ShapeType(rng.below(random_kind_count)));
        const ShapeProxy a = transformed(make_shape_proxy(ga), random_transform(rng, 2.0f));
        const ShapeProxy b = transformed(make_shape_proxy(gb), random_transform(rng, 2.0f));
        const ProxyDistance d = core_distance(a, b);
        const double expected = core_gap(core_points(a), core_points(b));
        if (std::fabs(d.distance - expected) > 1e-4) {
            if (failures++ < 5) {
                fprintf(stderr, "    case %d: distance %.7f, brute force %.7f\n", c, double(d.distance), expected);
            }
        }
        // The witness points are that far apart, along the normal.
        if (d.distance > 1e-3f) {
            I2D_CHECK(std::fabs(length(d.point_b - d.point_a) - d.distance) < 1e-4f);
            I2D_CHECK(dot(d.point_b - d.point_a, d.normal) > 0.0f);
        }
    }
    I2D_CHECK(failures == 0);
}

I2D_TEST(unit_time_of_impact_is_never_late) {
    TestRng rng(99);
    constexpr int samples = 2000;
    constexpr float tolerance = 0.25f * linear_slop;
    int hits = 0, late = 0, far = 0;
    for (int c = 0; c < 600; ++c) {
        const ShapeProxy a = make_shape_proxy(random_geometry(rng, ShapeType(rng.below(random_kind_count))));
        const ShapeProxy b = make_shape_proxy(random_geometry(rng, ShapeType(rng.below(random_kind_count))));
        // A turns a little and drifts; B flies across it, turning fast.
        const Sweep sa{Vec2{}, Vec2{rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)},
                       Vec2{rng.uniform(-0.5f, 0.5f), rng.uniform(-0.5f, 0.5f)}, make_rot(rng.uniform(-1.0f, 1.0f)),
                       make_rot(rng.uniform(-1.0f, 1.0f))};
        // Up to 2.5 rad in a sweep: nearly the most a step turns (four quarter turns).
        const float turn_from = rng.uniform(-3.0f, 3.0f);
        const Sweep sb{Vec2{rng.uniform(-0.1f, 0.1f), rng.uniform(-0.1f, 0.1f)},
                       Vec2{rng.uniform(-6.0f, -3.0f), rng.uniform(-2.0f, 2.0f)},
                       Vec2{rng.uniform(3.0f, 6.0f), rng.uniform(-2.0f, 2.0f)}, make_rot(turn_from),
                       make_rot(turn_from + rng.uniform(-2.5f, 2.5f))};
        const float target = a.radius + b.radius + linear_slop;
        const ToiResult r = time_of_impact(a, sa, b, sb, 1.0f, target, tolerance);
        // Brute force: the first sampled time the cores come within target.
        double first = 2.0;
        for (int k = 0; k <= samples && first > 1.0; ++k) {
            const float t = float(k) / samples;
            const ShapeProxy wa = transformed(a, sweep_transform(sa, t));
            const ShapeProxy wb = transformed(b, sweep_transform(sb, t));
            if (core_gap(core_points(wa), core_points(wb)) < target) {
                first = t;
            }
        }
        if (r.state == ToiState::overlapped) {
            I2D_CHECK(first == 0.0);
            continue;
        }
        if (r.state == ToiState::hit) {
            ++hits;
            // Not after the first sampled contact (one sample of slack), and the cores
            // are within target + tolerance there.
            late += r.fraction > first + 1.0 / samples ? 1 : 0;
            const ShapeProxy wa = transformed(a, sweep_transform(sa, r.fraction));
            const ShapeProxy wb = transformed(b, sweep_transform(sb, r.fraction));
            far += core_gap(core_points(wa), core_points(wb)) > target + tolerance + 1e-4 ? 1 : 0;
        } else {
            // Separated: no sample came within the target (a graze between samples aside).
            late += first <= 1.0 ? 1 : 0;
        }
    }
    fprintf(stderr, "    %d hits of 600 sweeps, %d late, %d stopped short\n", hits, late, far);
    I2D_CHECK(hits > 100);  // the sweeps do cross
    I2D_CHECK(late == 0);
    I2D_CHECK(far == 0);
}

I2D_TEST(unit_shape_cast_of_a_disc_has_a_closed_form) {
    // A disc of radius 0.5 from (-5, 0.3) along +x against a unit box at the origin: its
    // edge meets the face x = -1 after 3.5 of 10 m.
    ShapeProxy disc;
    disc.points[0] = Vec2{-5.0f, 0.3f};
    disc.count = 1;
    disc.radius = 0.5f;
    const Geometry box = box_geometry(1.0f, 1.0f);
    const CastHit hit = shape_cast(make_shape_proxy(box), Transform{}, disc, Vec2{10.0f, 0.0f}, 1.0f);
    I2D_REQUIRE(hit.hit);
    I2D_CHECK(hit.fraction <= 0.35f + 1e-6f);
    I2D_CHECK_NEAR(hit.fraction, 0.35, 0.25 * linear_slop / 10.0 + 1e-6);
    I2D_CHECK_NEAR(hit.point.x, -1.0, 1e-5);
    I2D_CHECK_NEAR(hit.normal.x, -1.0, 1e-5);
    // Cast away from the box: nothing.
    I2D_CHECK(!shape_cast(make_shape_proxy(box), Transform{}, disc, Vec2{-10.0f, 0.0f}, 1.0f).hit);
}

I2D_TEST(unit_query_proxy_is_a_convex_hull) {
    const Vec2 scattered[6] = {{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 0.5f}};
    const ShapeProxy p = make_query_proxy(scattered, 6, 0.1f);
    I2D_CHECK(p.count == 4);  // the square's corners
    for (int32_t i = 0; i < p.count; ++i) {
        const Vec2 e0 = p.points[(i + 1) % p.count] - p.points[i];
        const Vec2 e1 = p.points[(i + 2) % p.count] - p.points[(i + 1) % p.count];
        I2D_CHECK(cross(e0, e1) > 0.0f);  // counter-clockwise, convex
    }
    const Vec2 line[3] = {{0, 0}, {1, 1}, {3, 3}};
    const ShapeProxy segment = make_query_proxy(line, 3, 0.0f);
    I2D_CHECK(segment.count == 2);
    const Vec2 same[2] = {{1, 1}, {1, 1.001f}};
    I2D_CHECK(make_query_proxy(same, 2, 0.2f).count == 1);
}
