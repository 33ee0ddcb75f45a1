// SPDX-License-Identifier: MIT
// Contact points from a fresh manifold, with impulse carry-over by feature id.
#include "dynamics/contact.hpp"

namespace i2d {

void update_points(Contact& contact, const Manifold& m, Vec2 center_a, Vec2 center_b) {
    ContactPoint points[2];
    for (int32_t i = 0; i < m.point_count; ++i) {
        const ManifoldPoint& mp = m.points[i];
        ContactPoint& p = points[i];
        p.anchor_a = mp.point - center_a;
        p.anchor_b = mp.point - center_b;
        p.separation = -mp.penetration;
        p.id = mp.id;
        for (int32_t k = 0; k < contact.point_count; ++k) {
            if (contact.points[k].id == mp.id) {
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
}

}  // namespace i2d
