// SPDX-License-Identifier: MIT
// Checks of a world read from a snapshot against the rules the C API holds callers to.
//
// Design note: a snapshot's checksum says its bytes are the ones saved, not that a world
// saved them: any caller can hand bytes with a matching checksum. The core checks what
// links its stages (World::check_loaded); these check each value a body, shape or joint
// brings in against the same rule its create call or setter applies, kept beside that
// rule, so a restored world holds nothing a caller could not have put there. Each fails
// through call.fail, naming the object and the field.
#pragma once

#include <cstdint>
#include <cstdio>

#include "boundary.hpp"

namespace i2d::capi {

/// How far past the world's maximum_linear_speed a saved speed may be: the solver clamps
/// in float, so a speed at the limit can read an ulp or two above it.
constexpr double loaded_speed_tolerance = 1.0e-5;
/// How far a body's centre of mass may be from where its origin and rotation put it, as a
/// share of the distance from the world origin (at least 1 m): the step moves the centre
/// and derives the origin, so the two agree to rounding only.
constexpr float loaded_center_tolerance = 1.0e-5f;

/// A field's name in a message: "body 12: position", or "shape def: density" for no index.
struct FieldName {
    char text[96];
    FieldName(const char* object, int32_t index, const char* field) {
        if (index < 0) {
            std::snprintf(text, sizeof text, "%s: %s", object, field);
        } else {
            std::snprintf(text, sizeof text, "%s %d: %s", object, static_cast<int>(index), field);
        }
    }
    operator const char*() const { return text; }
};

/// Runs check(name), where name(field) spells a field for the messages, with plain field
/// names, then, only when it fails, once more with names that carry the object and its
/// index, for the message: formatting a name for every field of every object cost more
/// than the checks themselves.
template <class Check>
bool checked_with_names(const char* object, int32_t index, Check&& check) {
    return check([](const char* field) { return field; }) ||
           check([object, index](const char* field) { return FieldName(object, index, field); });
}

bool valid_loaded_body(Call& call, const World& world, int32_t body);
bool valid_loaded_shape(Call& call, const World& world, int32_t shape);
bool valid_loaded_joint(Call& call, const World& world, int32_t joint);

// The same rules for the arguments of a recorded call, which a replay passes to the core
// as they were recorded (calls that would change them on the way, normalising a rotation
// again, say, could change a bit).
bool valid_recorded_body_def(Call& call, const BodyDef& def);
/// A shape's def and geometry (not a chain segment's: chains are made whole).
bool valid_recorded_shape(Call& call, const ShapeDef& def, const Geometry& geometry);
/// Bodies live and distinct, one of them dynamic (body_b for a mouse joint), then the
/// anchors, thresholds and settings.
bool valid_recorded_joint(Call& call, const World& world, const JointDef& def);
/// The anchors, thresholds and settings of a joint def; `index` names it (-1: none).
bool valid_joint_values(Call& call, const JointDef& def, int32_t index);

}  // namespace i2d::capi
