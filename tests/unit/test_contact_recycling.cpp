// SPDX-License-Identifier: MIT
// Contact recycling (dynamics/contact.hpp): a kept manifold's separations follow the
// bodies' motion exactly as a fresh narrowphase would for small moves, and a move or
// turn beyond the limits asks for a fresh manifold.
#include <cmath>

#include "check.h"
#include "collision/hull.hpp"
#include "collision/manifold.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/contact/contact.hpp"

using namespace i2d;

namespace {

const RecycleLimits limits{recycle_touching_distance, recycle_apart_distance, recycle_min_cos};

// A unit box resting on a wide box: B (above) at height y, A (the floor) fixed at the origin.
struct RestingBox {
    Polygon floor = make_box(5.0f, 0.5f);
    Polygon box = make_box(0.5f, 0.5f);
    Transform floor_xf{{0.0f, 0.0f}, Rot{}};

    Manifold collide(const Transform& box_xf) const { return collide_polygons(floor, floor_xf, box, box_xf); }

    Contact made_at(const Transform& box_xf) const {
        Contact c;
        update_points(c, collide(box_xf), floor_xf.p, box_xf.p);
        remember_poses(c, floor_xf, floor_xf.p, box_xf, box_xf.p);
        c.flags |= contact_touching_at_start;
        return c;
    }
};

}  // namespace

I2D_TEST(unit_recycle_unmoved_bodies_keep_their_separations_exactly) {
    const RestingBox scene;
    const Transform box_xf{{0.3f, 0.999f}, make_rot(0.0f)};
    Contact c = scene.made_at(box_xf);
    I2D_REQUIRE(c.point_count == 2);
    const float before[2] = {c.points[0].separation, c.points[1].separation};
    I2D_CHECK(recycle_manifold(c, scene.floor_xf, scene.floor_xf.p, box_xf, box_xf.p, 0.71f, limits));
    I2D_CHECK(c.points[0].separation == before[0] && c.points[1].separation == before[1]);
}

I2D_TEST(unit_recycle_separations_follow_a_small_move_like_the_narrowphase) {
    // The box rises 0.3 mm and slides 0.4 mm: kept separations must match a fresh
    // manifold's to well under a micron.
    const RestingBox scene;
    Contact c = scene.made_at(Transform{{0.3f, 0.999f}, Rot{}});
    const Transform moved{{0.3004f, 0.9993f}, Rot{}};
    I2D_REQUIRE(recycle_manifold(c, scene.floor_xf, scene.floor_xf.p, moved, moved.p, 0.71f, limits));
    const Manifold fresh = scene.collide(moved);
    I2D_REQUIRE(fresh.point_count == 2);
    for (int32_t i = 0; i < 2; ++i) {
        I2D_CHECK_NEAR(c.points[i].separation, -fresh.points[i].penetration, 1e-6);
    }
}

I2D_TEST(unit_recycle_refuses_moves_and_turns_beyond_the_limits) {
    const RestingBox scene;
    const Transform start{{0.3f, 0.999f}, Rot{}};
    // Farther than the touching distance.
    Contact c = scene.made_at(start);
    const Transform far{{0.3f + 2.0f * recycle_touching_distance, 0.999f}, Rot{}};
    I2D_CHECK(!recycle_manifold(c, scene.floor_xf, scene.floor_xf.p, far, far.p, 0.71f, limits));
    // A turn whose swing at the box's corner (extent 0.71 m) exceeds the distance.
    c = scene.made_at(start);
    const Transform turned{start.p, make_rot(2.0f * recycle_touching_distance / 0.71f)};
    I2D_CHECK(!recycle_manifold(c, scene.floor_xf, scene.floor_xf.p, turned, turned.p, 0.71f, limits));
    // Both bodies turning together past the angle limit, even with no relative motion.
    c = scene.made_at(start);
    const float angle = 2.0f * std::acos(recycle_min_cos);
    const Transform floor_turned{scene.floor_xf.p, make_rot(angle)};
    const Transform box_turned{transform_point(floor_turned, start.p), make_rot(angle)};
    I2D_CHECK(!recycle_manifold(c, floor_turned, floor_turned.p, box_turned, box_turned.p, 0.71f, limits));
    // A contact that was apart uses the smaller distance.
    c = scene.made_at(start);
    c.flags &= ~uint32_t(contact_touching_at_start);
    const float between = 0.5f * (recycle_apart_distance + recycle_touching_distance);
    const Transform nudged{{0.3f + between, 0.999f}, Rot{}};
    I2D_CHECK(!recycle_manifold(c, scene.floor_xf, scene.floor_xf.p, nudged, nudged.p, 0.71f, limits));
    c.flags |= contact_touching_at_start;
    I2D_CHECK(recycle_manifold(c, scene.floor_xf, scene.floor_xf.p, nudged, nudged.p, 0.71f, limits));
    // A contact never made (no remembered poses) is never kept.
    Contact blank;
    I2D_CHECK(!recycle_manifold(blank, scene.floor_xf, scene.floor_xf.p, start, start.p, 0.71f, limits));
}
