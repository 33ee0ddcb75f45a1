// SPDX-License-Identifier: MIT
// Contact points from a fresh manifold, with impulse carry-over by feature id.
#include "dynamics/contact/contact.hpp"

#include <cmath>

namespace i2d {

void update_points(Contact& contact, const Manifold& m, Vec2 center_a, Vec2 center_b) {
    ContactPoint points[2];
    for (int32_t i = 0; i < m.point_count; ++i) {
        const ManifoldPoint& mp = m.points[i];
        ContactPoint& p = points[i];
        p.anchor_a = mp.point - center_a;
        p.anchor_b = mp.point - center_b;
        p.separation = -mp.penetration;
        for (int32_t k = 0; k < contact.point_count; ++k) {
            if (contact.point_ids[k] == mp.id) {
                p.normal_impulse = contact.points[k].normal_impulse;
                p.tangent_impulse = contact.points[k].tangent_impulse;
                break;
            }
        }
    }
    contact.normal = m.normal;
    contact.point_count = m.point_count;
    contact.points[0] = points[0];
    contact.points[1] = points[1];
    contact.point_ids[0] = m.point_count > 0 ? m.points[0].id : 0u;
    contact.point_ids[1] = m.point_count > 1 ? m.points[1].id : 0u;
}

// The base separation makes recycle_manifold's formula give the separation back exactly
// at the poses the manifold was made at.
void remember_poses(Contact& contact, const Transform& xf_a, Vec2 center_a, const Transform& xf_b, Vec2 center_b) {
    contact.made_rotation_a = xf_a.q;
    contact.made_rotation_b = xf_b.q;
    contact.made_relative_pose = inv_mul_transforms(xf_a, xf_b);
    contact.flags |= contact_recyclable;
    const Vec2 centers = center_b - center_a;
    for (int32_t i = 0; i < contact.point_count; ++i) {
        const ContactPoint& p = contact.points[i];
        contact.base_separations[i] = p.separation - dot(centers + (p.anchor_b - p.anchor_a), contact.normal);
    }
}

// Conservative advancement's bound: a body turning by angle t about its centre moves its
// farthest point by at most extent |sin t| (for the small turns allowed here).
bool recycle_manifold(Contact& c, const Transform& xf_a, Vec2 center_a, const Transform& xf_b, Vec2 center_b,
                      float extent, const RecycleLimits& limits) {
    if ((c.flags & contact_recyclable) == 0) {
        return false;
    }
    const Rot turn_a = inv_mul_rot(c.made_rotation_a, xf_a.q), turn_b = inv_mul_rot(c.made_rotation_b, xf_b.q);
    if (!(turn_a.c > limits.min_cos && turn_b.c > limits.min_cos)) {
        return false;
    }
    const Transform pose = inv_mul_transforms(xf_a, xf_b);
    const float travel = length(pose.p - c.made_relative_pose.p);
    const float relative_turn = std::fabs(inv_mul_rot(c.made_relative_pose.q, pose.q).s);
    const bool touching = (c.flags & contact_touching_at_start) != 0;
    const float limit = touching ? limits.touching_distance : limits.apart_distance;
    if (!(travel + extent * relative_turn < limit)) {
        return false;
    }
    const Vec2 centers = center_b - center_a;
    for (int32_t i = 0; i < c.point_count; ++i) {
        ContactPoint& p = c.points[i];
        const Vec2 moved = centers + (rotate(turn_b, p.anchor_b) - rotate(turn_a, p.anchor_a));
        p.separation = c.base_separations[i] + dot(moved, c.normal);
    }
    return true;
}

}  // namespace i2d
