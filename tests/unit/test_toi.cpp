// SPDX-License-Identifier: MIT
// Shape proxies, the exact core distance and the time of impact, against brute force:
// core_gap of brute_geometry.hpp for distances, and fine sampling of the motion for the
// time of impact (never late, and touching within the tolerance when it says so).
#include <cmath>
#include <cstdio>
#include <initializer_list>

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

// ---- Casts that start overlapping: the normal and point come from the overlap --------

namespace {

// Translations from rounding noise to a metre, along a direction none of the exits
// below takes, so that a normal copied from the translation shows.
constexpr float cast_lengths[] = {1e-30f, 1e-6f, 1.0f};
const Vec2 cast_direction{0.6f, -0.8f};
// A unit normal and an exit direction agree to float rounding.
constexpr float normal_tolerance = 1e-5f;
// A point counts as inside a proxy within this of its surface, m.
constexpr float inside_tolerance = 1e-5f;

ShapeProxy disc(Vec2 center, float radius) {
    ShapeProxy p;
    p.points[0] = center;
    p.count = 1;
    p.radius = radius;
    return p;
}

ShapeProxy hull_of(std::initializer_list<Vec2> points, float radius) {
    return make_query_proxy(points.begin(), int32_t(points.size()), radius);
}

bool inside(const ShapeProxy& p, Vec2 point) {
    return core_distance(disc(point, 0.0f), p).distance <= p.radius + inside_tolerance;
}

// The moving proxy starts in the shape (world space, placed by the identity): every cast
// length hits at fraction 0 with a unit normal along `exit` and a point inside both.
void check_overlap_exit(const ShapeProxy& shape, const ShapeProxy& moving, Vec2 exit) {
    for (float cast_length : cast_lengths) {
        const CastHit hit = shape_cast(shape, Transform{}, moving, cast_length * cast_direction, 1.0f);
        const bool ok = hit.hit && hit.fraction == 0.0f &&
                        std::fabs(length(hit.normal) - 1.0f) <= normal_tolerance &&
                        length(hit.normal - exit) <= normal_tolerance && inside(shape, hit.point) &&
                        inside(moving, hit.point);
        if (!ok) {
            ++i2d_check_failures;
            std::fprintf(stderr, "    cast %g: hit %d at %g, normal (%g, %g) (expected (%g, %g)), point (%g, %g)\n",
                         double(cast_length), int(hit.hit), double(hit.fraction), double(hit.normal.x),
                         double(hit.normal.y), double(exit.x), double(exit.y), double(hit.point.x),
                         double(hit.point.y));
        }
    }
}

}  // namespace

// A disc at (1.5, 0.2) inside the box [-2, 2] x [-1, 1] is 0.5 m from the right face,
// 0.8 from the top: it leaves soonest by +x.
I2D_TEST(unit_shape_cast_overlap_disc_in_box_leaves_by_the_nearest_face) {
    Geometry box;
    box.type = ShapeType::polygon;
    box.polygon = make_box(2.0f, 1.0f);
    check_overlap_exit(make_shape_proxy(box), disc({1.5f, 0.2f}, 0.25f), {1.0f, 0.0f});
}

// The box [0.8, 2.8] x [0.5, 1.5] over the unit box reaches 0.2 m into it along x and
// 0.5 m along y: it leaves soonest by +x.
I2D_TEST(unit_shape_cast_overlap_box_on_box_leaves_along_the_shallower_axis) {
    Geometry box;
    box.type = ShapeType::polygon;
    box.polygon = make_box(1.0f, 1.0f);
    const ShapeProxy moving = hull_of({{0.8f, 0.5f}, {2.8f, 0.5f}, {2.8f, 1.5f}, {0.8f, 1.5f}}, 0.0f);
    check_overlap_exit(make_shape_proxy(box), moving, {1.0f, 0.0f});
}

// A capsule from (0, -0.2) to (0, 0.6) across the segment from (-1, 0) to (1, 0): 0.2 m
// (plus its radius) up clears it, 0.6 m down, 1 m sideways: it leaves soonest by +y.
I2D_TEST(unit_shape_cast_overlap_capsule_across_segment_leaves_the_shorter_way) {
    const ShapeProxy segment = hull_of({{-1.0f, 0.0f}, {1.0f, 0.0f}}, 0.0f);
    const ShapeProxy capsule = hull_of({{0.0f, -0.2f}, {0.0f, 0.6f}}, 0.1f);
    check_overlap_exit(segment, capsule, {0.0f, 1.0f});
}

// Discs on one centre: every way out is as short, and the cast faces back the way it came.
I2D_TEST(unit_shape_cast_overlap_coincident_discs_face_back_along_the_cast) {
    check_overlap_exit(disc({0.0f, 0.0f}, 0.5f), disc({0.0f, 0.0f}, 0.25f), -cast_direction);
}

// Random pairs that overlap (or touch, within the cast's tolerance) at the start: the
// reported normal is unit and clears the overlap as soon as the best of 720 sampled
// directions (in double, brute force), and the point lies inside both shapes.
I2D_TEST(unit_shape_cast_overlap_exit_beats_every_sampled_direction) {
    constexpr int32_t sampled_directions = 720;
    // Float rounding of coordinates about 1 m, m.
    constexpr double push_tolerance = 1e-4;
    const Vec2 tiny_cast{0.6e-6f, -0.8e-6f};
    TestRng rng(4404);
    int overlaps = 0, failures = 0;
    for (int c = 0; c < 3000; ++c) {
        const Geometry ga = random_geometry(rng, ShapeType(rng.below(random_kind_count)));
        const Geometry gb = random_geometry(rng, ShapeType(rng.below(random_kind_count)));
        const Transform xa = random_transform(rng, 0.6f), xb = random_transform(rng, 0.6f);
        const ShapeProxy moving = transformed(make_shape_proxy(gb), xb);
        const CastHit hit = shape_cast(make_shape_proxy(ga), xa, moving, tiny_cast, 1.0f);
        if (!hit.hit || hit.fraction > 0.0f) {
            continue;
        }
        ++overlaps;
        const Core a = core_of(ga, xa), b = core_of(gb, xb);
        // How far B must move along unit n to clear A.
        auto push = [&](P n) {
            double reach_a = -DBL_MAX, reach_b = DBL_MAX;
            for (const P& q : a.pts) reach_a = std::max(reach_a, dot(q, n));
            for (const P& q : b.pts) reach_b = std::min(reach_b, dot(q, n));
            return reach_a - reach_b + a.radius + b.radius;
        };
        double least = DBL_MAX;
        for (int32_t k = 0; k < sampled_directions; ++k) {
            const double angle = 2.0 * 3.14159265358979323846 * k / sampled_directions;
            least = std::min(least, push({std::cos(angle), std::sin(angle)}));
        }
        const P n = p(hit.normal), point = p(hit.point);
        // Shapes within the cast's tolerance count as touching though still apart (push
        // below 0): the point then lies between them, outside each by at most the gap.
        const double slack = inside_tolerance + std::max(0.0, -push(n));
        const bool ok = std::fabs(len(n) - 1.0) <= normal_tolerance && push(n) <= least + push_tolerance &&
                        signed_distance(a, point) <= slack && signed_distance(b, point) <= slack;
        if (!ok && failures++ < 5) {
            std::fprintf(stderr, "    case %d: normal (%g, %g) pushes %.6f, least sampled %.6f; point out by %g, %g\n",
                         c, n.x, n.y, push(n), least, signed_distance(a, point), signed_distance(b, point));
        }
    }
    std::fprintf(stderr, "    %d of 3000 pairs overlap at the start\n", overlaps);
    I2D_CHECK(overlaps > 500);
    I2D_CHECK(failures == 0);
}
