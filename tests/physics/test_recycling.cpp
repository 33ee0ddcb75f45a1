// SPDX-License-Identifier: MIT
// Contact recycling through the public API: worlds that keep manifolds of bodies that
// barely moved behave like worlds that make every manifold afresh, for a resting stack
// (the case recycling is for) and for a box that slides off a ledge and tips over its
// edge (the case where kept points would be wrong if they were kept too long).
#include <cmath>
#include <cstdio>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

i2d_world_def recycling(bool enabled) {
    i2d_world_def def = i2d_default_world_def();
    def.enable_contact_recycling = enabled;
    return def;
}

struct Pose {
    i2d_vec2 p;
    float angle;
};

Pose pose_of(i2d_body_id b) { return {position(b), float(angle_of(b))}; }

// A 10-box column resting 3 s; the top box's pose.
Pose stack_top(bool recycle) {
    Scene scene(recycling(recycle));
    scene.ground(0.0f);
    const std::vector<i2d_body_id> column = scene.column(0.0f, 10);
    if (column.empty()) {
        ++i2d_check_failures;
        return {};
    }
    scene.step(steps_for(3.0));
    return pose_of(column.back());
}

// A unit box sliding at 4 m/s, friction 0.3, its centre 1.5 m from the end of a ledge:
// it reaches the edge at sqrt(16 - 2 0.3 g 1.5) = 2.65 m/s, tips over it and falls 5 m to
// a floor. Its pose after 1.5 s.
Pose ledge_box(bool recycle) {
    Scene scene(recycling(recycle));
    const Material slippery = with_friction(0.3f);
    scene.box(body_def(I2D_BODY_STATIC, i2d_vec2{-5.0f, -0.5f}), 5.0f, 0.5f, slippery);
    scene.ground(-5.0f);
    const i2d_body_id box = scene.dynamic_box(i2d_vec2{-1.5f, 0.5f}, 0.5f, 0.5f, slippery, i2d_vec2{4.0f, 0.0f});
    scene.step(steps_for(1.5));
    return pose_of(box);
}

}  // namespace

I2D_TEST(phys_recycling_resting_stack_matches_fresh_manifolds) {
    const Pose kept = stack_top(true), fresh = stack_top(false);
    fprintf(stderr, "    10-box column after 3 s, top box: kept (%.6f, %.6f) %.2e rad, fresh (%.6f, %.6f) %.2e rad\n",
            kept.p.x, kept.p.y, kept.angle, fresh.p.x, fresh.p.y, fresh.angle);
    I2D_CHECK_NEAR(kept.p.x, fresh.p.x, 1e-4);
    I2D_CHECK_NEAR(kept.p.y, fresh.p.y, 1e-4);
    I2D_CHECK_NEAR(kept.angle, fresh.angle, 1e-4);
}

I2D_TEST(phys_recycling_box_sliding_off_a_ledge_matches_fresh_manifolds) {
    const Pose kept = ledge_box(true), fresh = ledge_box(false);
    fprintf(stderr, "    box off a ledge after 1.5 s: kept (%.4f, %.4f) %.3f rad, fresh (%.4f, %.4f) %.3f rad\n", kept.p.x,
            kept.p.y, kept.angle, fresh.p.x, fresh.p.y, fresh.angle);
    I2D_CHECK(fresh.p.y < -3.0f);  // it did fall off
    I2D_CHECK_NEAR(kept.p.x, fresh.p.x, 0.01);
    I2D_CHECK_NEAR(kept.p.y, fresh.p.y, 0.01);
    I2D_CHECK_NEAR(kept.angle, fresh.angle, 0.02);
}
