// SPDX-License-Identifier: MIT
// How a joint is drawn (World::draw): lines from its bodies' origins to its anchors and
// between the anchors, and, with extras, what its limits, motor and spring hold it to.
#pragma once

#include "dynamics/debug_draw.hpp"
#include "dynamics/joint/joint.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// Draws the joint as its bodies stand (placed by xf_a and xf_b). `extra_length`: how
/// long the extras' marks are (an angle limit's line, an axis), length units.
void draw_joint(const JointDef& def, const Transform& xf_a, const Transform& xf_b, const DrawSink& sink, bool extras,
                float extra_length);

}  // namespace i2d
