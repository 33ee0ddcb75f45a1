// SPDX-License-Identifier: MIT
// DebugDraw: what a drawing pass over the world (World::draw, world_draw.cpp) hands its
// pictures to, what it is asked to draw, and the colours it draws them in.
//
// Design note: the core never sees the public header, so the sink is the core's own: a
// function pointer per kind of picture, taking the core's value types, and one context
// for them all; the C boundary points each at a trampoline that converts to the public
// types and calls the user's callback (capi/debug_draw_api.cpp). A null pointer means
// the kind is not drawn, and the pass then skips the work of making it (a polygon's
// placed vertices, a contact's points). Plain function pointers rather than a virtual
// interface: the pass calls them once per shape, and a binding's callbacks are C
// function pointers anyway. The colours are 0xRRGGBB, the values the public header
// lists (the boundary checks that they agree).
#pragma once

#include <cstdint>

#include "math/vec2.hpp"

namespace i2d {

using DrawColor = uint32_t;

/// Where the pictures go; any member may be null (that kind is then not drawn).
struct DrawSink {
    /// A closed outline, world vertices (bounds come here, four vertices).
    void (*polygon)(const Vec2* vertices, int32_t count, DrawColor color, void* context) = nullptr;
    /// A filled polygon: local vertices placed by xf, grown by radius.
    void (*solid_polygon)(const Transform& xf, const Vec2* vertices, int32_t count, float radius, DrawColor color,
                          void* context) = nullptr;
    void (*circle)(Vec2 center, float radius, DrawColor color, void* context) = nullptr;
    /// A filled circle; xf.p is its centre, xf.q its body's rotation.
    void (*solid_circle)(const Transform& xf, float radius, DrawColor color, void* context) = nullptr;
    void (*solid_capsule)(Vec2 p1, Vec2 p2, float radius, DrawColor color, void* context) = nullptr;
    void (*segment)(Vec2 p1, Vec2 p2, DrawColor color, void* context) = nullptr;
    void (*transform)(const Transform& xf, void* context) = nullptr;
    /// size: a hint in pixels, whatever the view's scale.
    void (*point)(Vec2 p, float size, DrawColor color, void* context) = nullptr;
    void (*string)(Vec2 p, const char* text, DrawColor color, void* context) = nullptr;
    void* context = nullptr;
};

/// What a pass draws.
struct DrawOptions {
    AABB bounds;              // the box culled to when use_bounds is set; valid (lower <= upper)
    bool use_bounds = false;
    bool shapes = true;
    bool joints = true;
    bool joint_extras = false;      // limits, motors, springs
    bool shape_bounds = false;      // shapes' fat boxes
    bool mass = false;              // dynamic bodies' centres of mass
    bool contacts = false;          // contact points
    bool contact_normals = false;
    bool contact_impulses = false;
    bool friction_impulses = false;
    bool graph_colors = false;      // contact points in their constraint colour
    bool islands = false;           // awake islands' bounds
};

struct DebugDraw {
    DrawSink sink;
    DrawOptions options;
};

/// The colours of the pictures (the public header's I2D_COLOR_* values, which it
/// documents; capi/debug_draw_api.cpp checks that the two lists agree).
namespace draw_colors {

// A shape's colour says its body's state (shape_color in world_draw.cpp gives the order
// in which they win).
constexpr DrawColor static_body = 0x80E680u;
constexpr DrawColor kinematic = 0x8080E6u;
constexpr DrawColor awake = 0xE6B380u;
constexpr DrawColor asleep = 0x999999u;
constexpr DrawColor bullet = 0xE6E64Du;
constexpr DrawColor sensor = 0x33CCFFu;
constexpr DrawColor disabled = 0x666666u;
constexpr DrawColor quarantined = 0xFF3333u;
// Joints.
constexpr DrawColor joint = 0x7FB89Au;         // the lines between the anchors and the body origins
constexpr DrawColor joint_anchor = 0x2E8B57u;  // the anchors' points
constexpr DrawColor joint_limit = 0xE05050u;   // extras: limits
constexpr DrawColor joint_motor = 0xB050E0u;   // extras: motors and motor targets
constexpr DrawColor joint_spring = 0x50A0E0u;  // extras: springs' rest positions
// Boxes and bodies.
constexpr DrawColor shape_bounds = 0xFFD700u;
constexpr DrawColor island = 0xFF4500u;
constexpr DrawColor mass = 0xF5F5F5u;
// Contacts.
constexpr DrawColor contact_point = 0x3366FFu;        // a point within the contact slop
constexpr DrawColor speculative_point = 0xC8C8C8u;    // a point still apart by more than the slop
constexpr DrawColor contact_normal = 0x696969u;
constexpr DrawColor contact_impulse = 0xFF00FFu;
constexpr DrawColor friction_impulse = 0xFFFF00u;
// The constraint graph's colours, taken in turn (colour k draws as palette[k % size]);
// the overflow colour, solved last and in sequence, has its own.
constexpr DrawColor graph_palette[] = {0xFF0000u, 0xFF8000u, 0xFFFF00u, 0x80FF00u, 0x00FF00u, 0x00FF80u,
                                       0x00FFFFu, 0x0080FFu, 0x0000FFu, 0x8000FFu, 0xFF00FFu, 0xFF0080u};
constexpr int32_t graph_palette_size = int32_t(sizeof(graph_palette) / sizeof(graph_palette[0]));
constexpr DrawColor graph_overflow = 0xFFFFFFu;

}  // namespace draw_colors

}  // namespace i2d
