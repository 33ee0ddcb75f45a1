// SPDX-License-Identifier: MIT
// i2d_default_debug_draw, i2d_world_draw: the world drawn through the caller's callbacks.
//
// The core draws into its own sink (src/dynamics/debug_draw.hpp); each of the caller's
// callbacks that is set gets a trampoline there, which converts the core's value types
// to the public ones (layout-identical) and calls it. A callback left NULL leaves the
// sink's slot null, so the core skips that kind of picture altogether.
#include <cstddef>

#include "boundary.hpp"
#include "convert.hpp"
#include "dynamics/debug_draw.hpp"
#include "geometry_checks.hpp"
#include "limits.hpp"

using namespace i2d;
using namespace i2d::capi;

static_assert(sizeof(Vec2) == sizeof(i2d_vec2) && offsetof(Vec2, y) == offsetof(i2d_vec2, y),
              "polygon vertices are handed over in place");
static_assert(I2D_COLOR_STATIC == draw_colors::static_body && I2D_COLOR_KINEMATIC == draw_colors::kinematic &&
                  I2D_COLOR_AWAKE == draw_colors::awake && I2D_COLOR_ASLEEP == draw_colors::asleep &&
                  I2D_COLOR_BULLET == draw_colors::bullet && I2D_COLOR_SENSOR == draw_colors::sensor &&
                  I2D_COLOR_DISABLED == draw_colors::disabled && I2D_COLOR_QUARANTINED == draw_colors::quarantined,
              "the shape colours the header documents");
static_assert(I2D_COLOR_JOINT == draw_colors::joint && I2D_COLOR_JOINT_ANCHOR == draw_colors::joint_anchor &&
                  I2D_COLOR_JOINT_LIMIT == draw_colors::joint_limit &&
                  I2D_COLOR_JOINT_MOTOR == draw_colors::joint_motor &&
                  I2D_COLOR_JOINT_SPRING == draw_colors::joint_spring,
              "the joint colours the header documents");
static_assert(I2D_COLOR_BOUNDS == draw_colors::shape_bounds && I2D_COLOR_ISLAND == draw_colors::island &&
                  I2D_COLOR_MASS == draw_colors::mass && I2D_COLOR_CONTACT == draw_colors::contact_point &&
                  I2D_COLOR_SPECULATIVE == draw_colors::speculative_point &&
                  I2D_COLOR_CONTACT_NORMAL == draw_colors::contact_normal &&
                  I2D_COLOR_CONTACT_IMPULSE == draw_colors::contact_impulse &&
                  I2D_COLOR_FRICTION_IMPULSE == draw_colors::friction_impulse &&
                  I2D_COLOR_GRAPH_OVERFLOW == draw_colors::graph_overflow &&
                  I2D_GRAPH_COLOR_COUNT == draw_colors::graph_palette_size,
              "the other colours the header documents");

namespace {

constexpr i2d_color graph_palette[] = I2D_GRAPH_COLORS;
static_assert(sizeof(graph_palette) == sizeof(draw_colors::graph_palette), "the graph palette the header documents");

constexpr bool same_palette(int32_t k = 0) {
    return k == I2D_GRAPH_COLOR_COUNT || (graph_palette[k] == draw_colors::graph_palette[k] && same_palette(k + 1));
}
static_assert(same_palette(), "the graph palette the header documents");

/// One trampoline per callback; context is the caller's i2d_debug_draw (a copy the call
/// keeps, so that a callback editing the caller's struct cannot change the pass).
struct DrawTrampolines {
    static const i2d_debug_draw& user(void* context) { return *static_cast<const i2d_debug_draw*>(context); }
    static const i2d_vec2* vertices(const Vec2* v) { return reinterpret_cast<const i2d_vec2*>(v); }

    static void polygon(const Vec2* v, int32_t count, DrawColor color, void* context) {
        user(context).draw_polygon(vertices(v), count, color, user(context).context);
    }
    static void solid_polygon(const Transform& xf, const Vec2* v, int32_t count, float radius, DrawColor color,
                              void* context) {
        user(context).draw_solid_polygon(to_public(xf), vertices(v), count, radius, color, user(context).context);
    }
    static void circle(Vec2 center, float radius, DrawColor color, void* context) {
        user(context).draw_circle(to_public(center), radius, color, user(context).context);
    }
    static void solid_circle(const Transform& xf, float radius, DrawColor color, void* context) {
        user(context).draw_solid_circle(to_public(xf), radius, color, user(context).context);
    }
    static void solid_capsule(Vec2 p1, Vec2 p2, float radius, DrawColor color, void* context) {
        user(context).draw_solid_capsule(to_public(p1), to_public(p2), radius, color, user(context).context);
    }
    static void segment(Vec2 p1, Vec2 p2, DrawColor color, void* context) {
        user(context).draw_segment(to_public(p1), to_public(p2), color, user(context).context);
    }
    static void transform(const Transform& xf, void* context) {
        user(context).draw_transform(to_public(xf), user(context).context);
    }
    static void point(Vec2 p, float size, DrawColor color, void* context) {
        user(context).draw_point(to_public(p), size, color, user(context).context);
    }
    static void string(Vec2 p, const char* text, DrawColor color, void* context) {
        user(context).draw_string(to_public(p), text, color, user(context).context);
    }
};

// The slot's trampoline when the caller set the callback, else null.
template <class Callback, class Trampoline>
Trampoline* when_set(Callback* callback, Trampoline* trampoline) {
    return callback != nullptr ? trampoline : nullptr;
}

DrawSink to_sink(const i2d_debug_draw& d) {
    DrawSink sink;
    sink.polygon = when_set(d.draw_polygon, &DrawTrampolines::polygon);
    sink.solid_polygon = when_set(d.draw_solid_polygon, &DrawTrampolines::solid_polygon);
    sink.circle = when_set(d.draw_circle, &DrawTrampolines::circle);
    sink.solid_circle = when_set(d.draw_solid_circle, &DrawTrampolines::solid_circle);
    sink.solid_capsule = when_set(d.draw_solid_capsule, &DrawTrampolines::solid_capsule);
    sink.segment = when_set(d.draw_segment, &DrawTrampolines::segment);
    sink.transform = when_set(d.draw_transform, &DrawTrampolines::transform);
    sink.point = when_set(d.draw_point, &DrawTrampolines::point);
    sink.string = when_set(d.draw_string, &DrawTrampolines::string);
    sink.context = const_cast<i2d_debug_draw*>(&d);
    return sink;
}

DrawOptions to_options(const i2d_debug_draw& d) {
    DrawOptions o;
    o.bounds = capi::to_core(d.drawing_bounds);
    o.use_bounds = d.use_drawing_bounds;
    o.shapes = d.draw_shapes;
    o.joints = d.draw_joints;
    o.joint_extras = d.draw_joint_extras;
    o.shape_bounds = d.draw_bounds;
    o.mass = d.draw_mass;
    o.contacts = d.draw_contacts;
    o.contact_normals = d.draw_contact_normals;
    o.contact_impulses = d.draw_contact_impulses;
    o.friction_impulses = d.draw_friction_impulses;
    o.graph_colors = d.draw_graph_colors;
    o.islands = d.draw_islands;
    return o;
}

}  // namespace

// The culling box is a wide one until the caller sets it: a def with use_drawing_bounds
// turned on and nothing else changed still draws the world.
I2D_API i2d_debug_draw i2d_default_debug_draw(void) {
    set_ok();
    const DrawOptions core;
    i2d_debug_draw d{};
    d.drawing_bounds = i2d_aabb{{-max_coordinate, -max_coordinate}, {max_coordinate, max_coordinate}};
    d.use_drawing_bounds = core.use_bounds;
    d.draw_shapes = core.shapes;
    d.draw_joints = core.joints;
    d.draw_joint_extras = core.joint_extras;
    d.draw_bounds = core.shape_bounds;
    d.draw_mass = core.mass;
    d.draw_contacts = core.contacts;
    d.draw_contact_normals = core.contact_normals;
    d.draw_contact_impulses = core.contact_impulses;
    d.draw_friction_impulses = core.friction_impulses;
    d.draw_graph_colors = core.graph_colors;
    d.draw_islands = core.islands;
    d.internal_cookie = def_cookie;
    return d;
}

// Reading, not changing: allowed in a locked world (from a query's or another draw's
// callback), refused only inside a step, as every getter is.
I2D_API i2d_status i2d_world_draw(i2d_world_id world, const i2d_debug_draw* draw) {
    return guarded("i2d_world_draw", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.not_null(draw, "draw") ||
            !call.cookie(draw->internal_cookie, "debug_draw")) {
            return last_status();
        }
        if (draw->use_drawing_bounds && !valid_aabb(call, draw->drawing_bounds, "drawing_bounds")) {
            return last_status();
        }
        const i2d_debug_draw user = *draw;
        w.world->draw(DebugDraw{to_sink(user), to_options(user)});
        set_ok();  // the callbacks may have made calls of their own
        return I2D_OK;
    });
}
