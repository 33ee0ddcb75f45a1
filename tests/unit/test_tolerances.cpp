// SPDX-License-Identifier: MIT
// Tolerances per length unit (dynamics/tolerances.hpp): at 1 unit per metre they are the
// constants' own bits; at other units, the constants times the unit. The manifolds of a
// scene scaled by 50, made with the margin and slop scaled by 50, are those of the scene
// in metres, scaled: the same points by feature, the same normal.
#include <cmath>
#include <cstdio>
#include <cstring>

#include "check.h"
#include "collision/manifold.hpp"
#include "dynamics/tolerances.hpp"
#include "world_fixture.hpp"

using namespace i2d;
using unit::box_geometry;
using unit::capsule_geometry;
using unit::circle_geometry;

namespace {

constexpr float pixels_per_meter = 50.0f;

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

Geometry scaled(Geometry g, float s) {
    switch (g.type) {
        case ShapeType::circle: g.circle = {s * g.circle.center, s * g.circle.radius}; break;
        case ShapeType::capsule: g.capsule = {s * g.capsule.center1, s * g.capsule.center2, s * g.capsule.radius}; break;
        case ShapeType::polygon:
            for (int32_t i = 0; i < g.polygon.count; ++i) {
                g.polygon.vertices[i] = s * g.polygon.vertices[i];
            }
            g.polygon.centroid = s * g.polygon.centroid;
            g.polygon.radius = s * g.polygon.radius;
            break;
        default: break;
    }
    return g;
}

}  // namespace

I2D_TEST(tolerances_in_meters_are_the_constants) {
    const Tolerances t(1.0f);
    I2D_CHECK(same_bits(t.linear_slop, linear_slop));
    I2D_CHECK(same_bits(t.speculative_distance, speculative_distance));
    I2D_CHECK(same_bits(t.max_aabb_margin, max_aabb_margin));
    I2D_CHECK(same_bits(t.recycle_touching_distance, recycle_touching_distance));
    I2D_CHECK(same_bits(t.recycle_apart_distance, recycle_apart_distance));
}

I2D_TEST(tolerances_scale_with_the_unit) {
    const Tolerances t(pixels_per_meter);
    I2D_CHECK(t.linear_slop == pixels_per_meter * linear_slop);
    I2D_CHECK(t.speculative_distance == pixels_per_meter * speculative_distance);
    I2D_CHECK(t.max_aabb_margin == pixels_per_meter * max_aabb_margin);
    I2D_CHECK(t.recycle_touching_distance == pixels_per_meter * recycle_touching_distance);
    I2D_CHECK(t.recycle_apart_distance == pixels_per_meter * recycle_apart_distance);
}

// A box, a rounded box and a capsule resting on (or hovering just above, or sunk just
// into) a box, a capsule and a circle, shifted along the face and tilted slightly: near
// ties between reference faces and between clipping and one closest point, which the
// slop decides. Scaled by 50 with the world's tolerances scaled too, every manifold is
// the metre one, scaled.
I2D_TEST(tolerances_scaled_manifolds_match) {
    const Geometry below[] = {box_geometry(2.0f, 0.5f), capsule_geometry({-2.0f, 0.0f}, {2.0f, 0.0f}, 0.5f),
                              circle_geometry({0.0f, 0.0f}, 0.5f)};
    const Geometry above[] = {box_geometry(0.5f, 0.5f), box_geometry(0.45f, 0.45f, 0.05f),
                              capsule_geometry({-0.3f, 0.0f}, {0.3f, 0.0f}, 0.2f)};
    const float reach_above[] = {0.5f, 0.5f, 0.2f};
    const float gaps[] = {-0.01f, -0.001f, 0.0f, 0.0004f, 0.003f, 0.015f};
    const float shifts[] = {0.0f, 0.3f, 1.7f, 2.45f};
    const float tilts[] = {0.0f, 0.0005f, -0.002f, 0.01f, 0.3f};
    const Tolerances metres(1.0f), pixels(pixels_per_meter);
    int32_t compared = 0, with_points = 0;
    for (const Geometry& a : below) {
        for (int32_t k = 0; k < 3; ++k) {
            for (const float gap : gaps) {
                for (const float shift : shifts) {
                    for (const float tilt : tilts) {
                        const Transform xa{{0.0f, 0.0f}, Rot{}};
                        const Transform xb{{shift, 0.5f + reach_above[k] + gap}, make_rot(tilt)};
                        const Manifold m = collide_shapes(a, xa, above[k], xb, metres.speculative_distance,
                                                          metres.linear_slop);
                        const float s = pixels_per_meter;
                        const Transform sxb{s * xb.p, xb.q};
                        const Manifold p = collide_shapes(scaled(a, s), xa, scaled(above[k], s), sxb,
                                                          pixels.speculative_distance, pixels.linear_slop);
                        ++compared;
                        with_points += m.point_count > 0 ? 1 : 0;
                        const int failures = i2d_check_failures;
                        I2D_CHECK(m.point_count == p.point_count);
                        if (m.point_count != p.point_count) {
                            continue;
                        }
                        I2D_CHECK(m.point_count == 0 || length(m.normal - p.normal) <= 1e-4f);
                        for (int32_t i = 0; i < m.point_count; ++i) {
                            I2D_CHECK(m.points[i].id == p.points[i].id);
                            I2D_CHECK(length(m.points[i].point - (1.0f / s) * p.points[i].point) <= 1e-4f);
                            I2D_CHECK_NEAR(m.points[i].penetration, p.points[i].penetration / s, 1e-5);
                        }
                        if (i2d_check_failures != failures) {
                            printf("    shapes %d/%d, gap %g, shift %g, tilt %g\n", int(a.type), int(k), double(gap),
                                   double(shift), double(tilt));
                        }
                    }
                }
            }
        }
    }
    printf("    %d pairs compared, %d with points\n", int(compared), int(with_points));
    I2D_CHECK(with_points > compared / 2);
}
