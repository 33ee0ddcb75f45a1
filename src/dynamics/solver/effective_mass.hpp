// SPDX-License-Identifier: MIT
// effective_mass: how heavy two bodies' relative motion along a direction is at two
// anchors, for the contact solver's rows and the continuous stage's impacts alike.
#pragma once

#include "math/vec2.hpp"

namespace i2d {

/// 1 / (invMassA + invMassB + (rA x d)^2 invIA + (rB x d)^2 invIB), or 0 when nothing
/// moves. Motion is any type with inv_mass and inv_inertia (BodyMotion, ImpactBody).
template <class Motion>
inline float effective_mass(const Motion& a, const Motion& b, Vec2 r_a, Vec2 r_b, Vec2 direction) {
    const float ra = cross(r_a, direction), rb = cross(r_b, direction);
    const float k = a.inv_mass + b.inv_mass + a.inv_inertia * ra * ra + b.inv_inertia * rb * rb;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

}  // namespace i2d
