// SPDX-License-Identifier: MIT
// How each kind of joint is drawn. Every kind but the mouse draws the same links (body
// origin to anchor on each side, anchor to anchor, a point at each anchor), so that a
// torn joint shows as a gap between its points; the extras add, per kind, the few
// marks that say what the joint holds its bodies to: an angle's limits and rest, an
// axis with its limits, a length's limits and rest, a motor's target. They read only
// the def and the bodies' poses: drawing needs no solver state.
#include "dynamics/joint/joint_draw.hpp"

namespace i2d {

namespace {

constexpr float anchor_point_size = 5.0f;  // pixels
constexpr float extra_point_size = 7.0f;   // pixels: a limit's or a target's point
constexpr float motor_circle_share = 0.5f;  // of the extra length: a revolute motor's circle radius
constexpr float limit_tick_share = 0.25f;   // of the extra length: half a limit tick across an axis
const Vec2 x_axis{1.0f, 0.0f};

// The joint's points in the world and where its pictures go.
struct JointPicture {
    const DrawSink& sink;
    Vec2 origin_a, origin_b, anchor_a, anchor_b;
    float extra_length;

    void segment(Vec2 p1, Vec2 p2, DrawColor color) const {
        if (sink.segment) {
            sink.segment(p1, p2, color, sink.context);
        }
    }
    void point(Vec2 p, float size, DrawColor color) const {
        if (sink.point) {
            sink.point(p, size, color, sink.context);
        }
    }
    // A short mark across `axis` at p: where a slide's limit stops it.
    void tick(Vec2 p, Vec2 axis, DrawColor color) const {
        const Vec2 across = limit_tick_share * extra_length * left_perp(axis);
        segment(p - across, p + across, color);
    }
};

void draw_links(const JointPicture& j) {
    j.segment(j.origin_a, j.anchor_a, draw_colors::joint);
    j.segment(j.anchor_a, j.anchor_b, draw_colors::joint);
    j.segment(j.origin_b, j.anchor_b, draw_colors::joint);
    j.point(j.anchor_a, anchor_point_size, draw_colors::joint_anchor);
    j.point(j.anchor_b, anchor_point_size, draw_colors::joint_anchor);
}

// Body A plays no part in a mouse joint: the picture is the pull from the target.
void draw_mouse(const JointPicture& j, const MouseSettings& s) {
    j.segment(s.target, j.anchor_b, draw_colors::joint);
    j.point(s.target, extra_point_size, draw_colors::joint_motor);
    j.point(j.anchor_b, anchor_point_size, draw_colors::joint_anchor);
}

// A line from B's anchor at the joint angle `angle` (B relative to A, less the
// reference), as A stands.
void angle_line(const JointPicture& j, const Transform& xf_a, float reference, float angle, DrawColor color) {
    const Vec2 direction = rotate(mul_rot(xf_a.q, make_rot(reference + angle)), x_axis);
    j.segment(j.anchor_b, j.anchor_b + j.extra_length * direction, color);
}

// B's own x axis, then the limits, the spring's rest angle and a circle for the motor.
void revolute_extras(const JointPicture& j, const RevoluteSettings& s, const Transform& xf_a, const Transform& xf_b) {
    j.segment(j.anchor_b, j.anchor_b + j.extra_length * rotate(xf_b.q, x_axis), draw_colors::joint);
    if (s.enable_limit) {
        angle_line(j, xf_a, s.reference_angle, s.lower_angle, draw_colors::joint_limit);
        angle_line(j, xf_a, s.reference_angle, s.upper_angle, draw_colors::joint_limit);
    }
    if (s.enable_spring) {
        angle_line(j, xf_a, s.reference_angle, s.target_angle, draw_colors::joint_spring);
    }
    if (s.enable_motor && j.sink.circle) {
        j.sink.circle(j.anchor_b, motor_circle_share * j.extra_length, draw_colors::joint_motor, j.sink.context);
    }
}

// What a prismatic and a wheel joint share: a slide along A's axis through A's anchor.
struct Slide {
    Vec2 local_axis;
    bool enable_limit;
    float lower, upper;
    bool enable_motor;
    bool enable_spring;
    float rest;  // the spring's rest translation
};

// The axis, a tick at each limit, a point at the spring's rest and one on B's anchor
// for the motor.
void slide_extras(const JointPicture& j, const Slide& s, const Transform& xf_a) {
    const Vec2 axis = normalize(rotate(xf_a.q, s.local_axis));
    j.segment(j.anchor_a - j.extra_length * axis, j.anchor_a + j.extra_length * axis, draw_colors::joint);
    if (s.enable_limit) {
        j.tick(j.anchor_a + s.lower * axis, axis, draw_colors::joint_limit);
        j.tick(j.anchor_a + s.upper * axis, axis, draw_colors::joint_limit);
    }
    if (s.enable_spring) {
        j.point(j.anchor_a + s.rest * axis, extra_point_size, draw_colors::joint_spring);
    }
    if (s.enable_motor) {
        j.point(j.anchor_b, extra_point_size, draw_colors::joint_motor);
    }
}

// Along the line between the anchors: the limits and the spring's rest length.
void distance_extras(const JointPicture& j, const DistanceSettings& s) {
    const Vec2 direction = normalize(j.anchor_b - j.anchor_a);
    if (direction == Vec2{}) {
        return;  // the anchors meet: no line to mark lengths along
    }
    if (s.enable_limit) {
        j.point(j.anchor_a + s.min_length * direction, extra_point_size, draw_colors::joint_limit);
        j.point(j.anchor_a + s.max_length * direction, extra_point_size, draw_colors::joint_limit);
    }
    if (s.enable_spring) {
        j.point(j.anchor_a + s.length * direction, extra_point_size, draw_colors::joint_spring);
    }
    if (s.enable_motor) {
        j.point(j.anchor_b, extra_point_size, draw_colors::joint_motor);
    }
}

// Where the motor drives B's origin: linear_offset in A's frame.
void motor_extras(const JointPicture& j, const MotorSettings& s, const Transform& xf_a) {
    const Vec2 target = transform_point(xf_a, s.linear_offset);
    j.segment(j.origin_b, target, draw_colors::joint_motor);
    j.point(target, extra_point_size, draw_colors::joint_motor);
}

void draw_extras(const JointPicture& j, const JointDef& def, const Transform& xf_a, const Transform& xf_b) {
    switch (def.type) {
        case JointType::revolute: revolute_extras(j, def.revolute, xf_a, xf_b); break;
        case JointType::prismatic: {
            const PrismaticSettings& s = def.prismatic;
            slide_extras(j,
                         {s.local_axis_a, s.enable_limit, s.lower_translation, s.upper_translation, s.enable_motor,
                          s.enable_spring, s.target_translation},
                         xf_a);
            break;
        }
        case JointType::wheel: {
            const WheelSettings& s = def.wheel;
            slide_extras(j,
                         {s.local_axis_a, s.enable_limit, s.lower_translation, s.upper_translation, s.enable_motor,
                          s.enable_spring, 0.0f},
                         xf_a);
            break;
        }
        case JointType::distance: distance_extras(j, def.distance); break;
        case JointType::motor: motor_extras(j, def.motor, xf_a); break;
        case JointType::filter:
        case JointType::mouse:
        case JointType::weld:
        case JointType::count: break;  // nothing beyond the links (the weld holds all)
    }
}

}  // namespace

void draw_joint(const JointDef& def, const Transform& xf_a, const Transform& xf_b, const DrawSink& sink, bool extras,
                float extra_length) {
    const JointPicture j{sink,
                         xf_a.p,
                         xf_b.p,
                         transform_point(xf_a, def.local_anchor_a),
                         transform_point(xf_b, def.local_anchor_b),
                         extra_length};
    if (def.type == JointType::mouse) {
        draw_mouse(j, def.mouse);
        return;
    }
    draw_links(j);
    if (extras) {
        draw_extras(j, def, xf_a, xf_b);
    }
}

}  // namespace i2d
