// SPDX-License-Identifier: MIT
// Contact manifold updates with impulse carry-over by feature id.
#include "dynamics/contact.hpp"

namespace i2d {

void update_manifold(Contact& contact, const Manifold& fresh) {
    ContactImpulse carried[2];
    for (int32_t i = 0; i < fresh.point_count; ++i) {
        for (int32_t k = 0; k < contact.manifold.point_count; ++k) {
            if (contact.manifold.points[k].id == fresh.points[i].id) {
                carried[i] = contact.impulses[k];
                break;
            }
        }
    }
    contact.manifold = fresh;
    contact.impulses[0] = carried[0];
    contact.impulses[1] = carried[1];
}

}  // namespace i2d
