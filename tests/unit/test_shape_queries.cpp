// SPDX-License-Identifier: MIT
// Ray casts, point containment and box overlap of every kind of rotated shape, against
// dense sampling along the ray and double-precision brute-force distances.
#include <cmath>
#include <cstdio>

#include "brute_geometry.hpp"
#include "check.h"
#include "collision/geometry.hpp"
#include "world_fixture.hpp"

using namespace i2d;
using brute::random_kind_count;

namespace {

// First sample along the ray inside the shape (brute-force signed distance), or -1.
double sampled_entry(const brute::Core& core, Vec2 origin, Vec2 translation, int32_t samples) {
    for (int32_t i = 0; i <= samples; ++i) {
        const double t = double(i) / samples;
        const brute::P q{origin.x + t * translation.x, origin.y + t * translation.y};
        if (brute::signed_distance(core, q) <= 0.0) {
            return t;
        }
    }
    return -1.0;
}

// Crossing of a ray with a segment in double precision, or -1.
double segment_crossing(const brute::Core& core, Vec2 origin, Vec2 translation) {
    const brute::P o = brute::p(origin), d = brute::p(translation);
    const brute::P a = core.pts[0], e = core.pts[1] - core.pts[0];
    const double denom = brute::cross(d, e);
    if (denom == 0.0) return -1.0;
    const double t = brute::cross(a - o, e) / denom, s = brute::cross(a - o, d) / denom;
    return t >= 0.0 && t <= 1.0 && s >= 0.0 && s <= 1.0 ? t : -1.0;
}

const char* kind_name(ShapeType t) {
    static const char* names[] = {"circle", "capsule", "segment", "polygon"};
    return names[static_cast<int32_t>(t)];
}

}  // namespace

I2D_TEST(unit_queries_ray_cast_every_kind_matches_sampling) {
    TestRng rng(7);
    const int32_t samples = 20000;
    const double step = 1.0 / samples;
    for (int32_t k = 0; k < random_kind_count; ++k) {
        const ShapeType type = static_cast<ShapeType>(k);
        int32_t hits = 0;
        double worst = 0.0;
        for (int32_t trial = 0; trial < 400; ++trial) {
            const Geometry g = brute::random_geometry(rng, type);
            const Transform xf = brute::random_transform(rng, 2.0f);
            const brute::Core core = brute::core_of(g, xf);
            const Vec2 origin{rng.uniform(-6.0f, 6.0f), rng.uniform(-6.0f, 6.0f)};
            const Vec2 target = xf.p + Vec2{rng.uniform(-1.5f, 1.5f), rng.uniform(-1.5f, 1.5f)};
            const Vec2 translation = rng.uniform(0.3f, 1.6f) * (target - origin);
            const RayHit hit = ray_cast(g, xf, origin, translation, 1.0f);
            const double entry = type == ShapeType::segment ? segment_crossing(core, origin, translation)
                                                            : sampled_entry(core, origin, translation, samples);
            if (type != ShapeType::segment && brute::signed_distance(core, brute::p(origin)) < -1e-5) {
                I2D_CHECK(!hit.hit);  // starts strictly inside: no hit
                continue;
            }
            if (entry < 0.0) {
                I2D_CHECK(!hit.hit);
                continue;
            }
            I2D_REQUIRE(hit.hit);
            ++hits;
            const double err = std::fabs(hit.fraction - entry);
            worst = std::fmax(worst, err);
            // Sampling finds the first sample inside: the entry is within one step before it.
            I2D_CHECK(hit.fraction <= entry + 1e-5 && hit.fraction >= entry - step - 1e-5);
            I2D_CHECK_NEAR(length(hit.normal), 1.0, 1e-5);
            I2D_CHECK(dot(hit.normal, translation) <= 0.0f);
            // The point is on the surface and the normal points out of the shape.
            I2D_CHECK(std::fabs(brute::signed_distance(core, brute::p(hit.point))) <= 1e-4);
            if (type != ShapeType::segment) {
                const Vec2 out = hit.point + 1e-3f * hit.normal;
                I2D_CHECK(brute::signed_distance(core, brute::p(out)) > 0.0);
            }
        }
        std::printf("ray cast %s: %d hits, max fraction error vs sampling %.3g (step %.3g)\n", kind_name(type),
                    int(hits), worst, step);
        I2D_CHECK(hits > 50);  // the generator must produce hits of every kind
    }
}

I2D_TEST(unit_queries_ray_cast_edge_cases) {
    const Geometry box = unit::box_geometry(1.0f, 1.0f);
    const Transform turned{{0.0f, 0.0f}, Rot{std::cos(0.7853982f), std::sin(0.7853982f)}};
    // A 45-degree diamond: its right corner at (sqrt 2, 0).
    const RayHit corner = ray_cast(box, turned, {-3.0f, 0.0f}, {6.0f, 0.0f}, 1.0f);
    I2D_REQUIRE(corner.hit);
    I2D_CHECK_NEAR(corner.fraction, (3.0 - std::sqrt(2.0)) / 6.0, 1e-6);
    I2D_CHECK(!ray_cast(box, turned, {-3.0f, 0.0f}, {6.0f, 0.0f}, 0.2f).hit);  // clipped
    I2D_CHECK(!ray_cast(box, turned, {0.1f, 0.1f}, {6.0f, 0.0f}, 1.0f).hit);   // inside
    I2D_CHECK(!ray_cast(box, turned, {-3.0f, 0.0f}, {0.0f, 0.0f}, 1.0f).hit);  // no length
    // Segments are hit from both sides, the normal facing the ray.
    const Geometry seg = unit::segment_geometry({-1.0f, 0.0f}, {1.0f, 0.0f});
    const RayHit down = ray_cast(seg, Transform{}, {0.0f, 2.0f}, {0.0f, -4.0f}, 1.0f);
    const RayHit up = ray_cast(seg, Transform{}, {0.0f, -2.0f}, {0.0f, 4.0f}, 1.0f);
    I2D_REQUIRE(down.hit && up.hit);
    I2D_CHECK(down.normal == (Vec2{0.0f, 1.0f}) && up.normal == (Vec2{0.0f, -1.0f}));
    I2D_CHECK_NEAR(down.fraction, 0.5, 1e-6);
    // A capsule from inside its cap: no hit; from outside along its axis: the cap.
    const Geometry cap = unit::capsule_geometry({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f);
    I2D_CHECK(!ray_cast(cap, Transform{}, {1.2f, 0.0f}, {5.0f, 0.0f}, 1.0f).hit);
    const RayHit axial = ray_cast(cap, Transform{}, {4.0f, 0.0f}, {-4.0f, 0.0f}, 1.0f);
    I2D_REQUIRE(axial.hit);
    I2D_CHECK_NEAR(axial.fraction, 2.5 / 4.0, 1e-6);
    I2D_CHECK_NEAR(axial.normal.x, 1.0, 1e-6);
}

I2D_TEST(unit_queries_contains_point_matches_brute_force) {
    TestRng rng(19);
    for (int32_t k = 0; k < random_kind_count; ++k) {
        const ShapeType type = static_cast<ShapeType>(k);
        int32_t inside = 0;
        for (int32_t trial = 0; trial < 200; ++trial) {
            const Geometry g = brute::random_geometry(rng, type);
            const Transform xf = brute::random_transform(rng, 2.0f);
            const brute::Core core = brute::core_of(g, xf);
            for (int32_t i = 0; i < 200; ++i) {
                const Vec2 q = xf.p + Vec2{rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f)};
                const double sd = brute::signed_distance(core, brute::p(q));
                const bool got = contains_point(g, xf, q);
                if (type == ShapeType::segment) {
                    I2D_CHECK(!got);
                } else if (std::fabs(sd) > 1e-5) {
                    I2D_CHECK(got == (sd < 0.0));
                }
                inside += got ? 1 : 0;
            }
        }
        I2D_CHECK(type == ShapeType::segment || inside > 1000);
    }
}

I2D_TEST(unit_queries_overlaps_aabb_matches_brute_force) {
    TestRng rng(23);
    for (int32_t k = 0; k < random_kind_count; ++k) {
        const ShapeType type = static_cast<ShapeType>(k);
        int32_t overlaps_seen = 0, misses_seen = 0;
        for (int32_t trial = 0; trial < 3000; ++trial) {
            const Geometry g = brute::random_geometry(rng, type);
            const Transform xf = brute::random_transform(rng, 2.0f);
            const brute::Core core = brute::core_of(g, xf);
            const Vec2 c = xf.p + Vec2{rng.uniform(-2.5f, 2.5f), rng.uniform(-2.5f, 2.5f)};
            const Vec2 h{rng.uniform(0.01f, 1.0f), rng.uniform(0.01f, 1.0f)};
            const AABB box{c - h, c + h};
            const std::vector<brute::P> corners = {brute::p(box.lower), {box.upper.x, box.lower.y},
                                                   brute::p(box.upper), {box.lower.x, box.upper.y}};
            const double gap = brute::core_gap(core.pts, corners) - core.radius;
            const bool got = overlaps_aabb(g, xf, box);
            if (std::fabs(gap) > 1e-5) {
                I2D_CHECK(got == (gap < 0.0));
            }
            overlaps_seen += got ? 1 : 0;
            misses_seen += got ? 0 : 1;
            // The tight bounds contain every overlapping box's overlap with the shape.
            if (got) {
                I2D_CHECK(overlaps(compute_aabb(g, xf), box));
            }
        }
        I2D_CHECK(overlaps_seen > 300 && misses_seen > 300);
    }
}

I2D_TEST(unit_queries_aabb_is_tight_for_rotated_shapes) {
    TestRng rng(29);
    for (int32_t k = 0; k < random_kind_count; ++k) {
        for (int32_t trial = 0; trial < 300; ++trial) {
            const Geometry g = brute::random_geometry(rng, static_cast<ShapeType>(k));
            const Transform xf = brute::random_transform(rng, 5.0f);
            const brute::Core core = brute::core_of(g, xf);
            double lx = 1e30, ly = 1e30, ux = -1e30, uy = -1e30;
            for (const brute::P& q : core.pts) {
                lx = std::fmin(lx, q.x - core.radius), ux = std::fmax(ux, q.x + core.radius);
                ly = std::fmin(ly, q.y - core.radius), uy = std::fmax(uy, q.y + core.radius);
            }
            const AABB b = compute_aabb(g, xf);
            I2D_CHECK_NEAR(b.lower.x, lx, 1e-5);
            I2D_CHECK_NEAR(b.lower.y, ly, 1e-5);
            I2D_CHECK_NEAR(b.upper.x, ux, 1e-5);
            I2D_CHECK_NEAR(b.upper.y, uy, 1e-5);
        }
    }
}
