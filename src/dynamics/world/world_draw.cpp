// SPDX-License-Identifier: MIT
// World: the drawing pass, which hands the world to a DebugDraw's sink (debug_draw.hpp):
// shapes coloured by their body's state and their fat boxes, then, for the bodies whose
// shapes were drawn, centres of mass, joints, contacts and awake islands.
//
// The shapes come first. Culled, they are found through the broadphase trees, so that
// shapes far from the box cost nothing; disabled bodies, whose shapes are in no tree,
// are looked for only when some shape lacks a proxy. Not culled, the shape pool is read
// in order. Each shape drawn marks its body visible; everything else hangs off the
// visible bodies, walked in index order through their own lists, each joint, contact and
// island once (a bit marks what was drawn). The marks belong to the pass, made per call,
// not kept in the world: a callback may draw the world again from inside its own call,
// and two passes must not share them. The world is locked throughout, as for a query.
#include <cstdio>
#include <vector>

#include "collision/geometry.hpp"
#include "core/bit_set.hpp"
#include "dynamics/debug_draw.hpp"
#include "dynamics/joint/joint_draw.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

namespace {

constexpr float contact_point_size = 5.0f;   // pixels
constexpr float overflow_point_size = 8.0f;  // pixels: a contact of the graph's overflow colour
constexpr float contact_normal_length = 0.3f;  // m, scaled to the world's length unit
constexpr float impulse_length_per_newton_second = 10.0f;  // m per N s, scaled likewise
constexpr float joint_extra_length = 0.5f;  // m, scaled likewise: limit lines, axes
constexpr int32_t mass_text_size = 32;

/// The colour that says the state of a shape's body: the first of quarantined, disabled,
/// sensor (the shape's own), static, kinematic, bullet (awake), awake and asleep.
DrawColor shape_color(const Body& b, const Shape& s) {
    if (b.quarantined) {
        return draw_colors::quarantined;
    }
    if (!b.enabled) {
        return draw_colors::disabled;
    }
    if (s.is_sensor) {
        return draw_colors::sensor;
    }
    if (b.type == BodyType::static_body) {
        return draw_colors::static_body;
    }
    if (b.type == BodyType::kinematic) {
        return draw_colors::kinematic;
    }
    if (b.awake_index == null_index) {
        return draw_colors::asleep;
    }
    return b.is_bullet ? draw_colors::bullet : draw_colors::awake;
}

/// What the pass reads of the world, all of it const.
struct DrawnWorld {
    const Pool<Body>& bodies;
    const Pool<Shape>& shapes;
    const BroadPhase& broad_phase;
    const Pool<Joint>& joints;
    const Pool<Contact>& contacts;
    const Pool<Island>& islands;
    const ConstraintGraph& graph;
    float linear_slop;   // length units
    float length_unit;   // length units per metre
};

class WorldDrawer {
public:
    WorldDrawer(const DebugDraw& draw, const DrawnWorld& world)
        : sink_(draw.sink), options_(draw.options), world_(world) {}

    void run() {
        if (options_.use_bounds) {
            visit_culled_shapes();
        } else {
            visit_all_shapes();
        }
        if (options_.mass || options_.joints || wants_contacts() || options_.islands) {
            if (wants_contacts() && options_.graph_colors) {
                gather_graph_colors();
            }
            visible_.visit([this](int32_t body) { draw_body(body); });
        }
    }

private:
    bool wants_contact_points() const { return options_.contacts || options_.graph_colors; }
    bool wants_contacts() const {
        return wants_contact_points() || options_.contact_normals || options_.contact_impulses ||
               options_.friction_impulses;
    }

    // ---- Shapes ----

    // Every tree's shapes whose fat box meets the box, those whose tight box does too;
    // then those of disabled bodies, if any shape lacks a proxy.
    void visit_culled_shapes() {
        const AABB& box = options_.bounds;
        int32_t proxies = 0;
        for (int32_t k = 0; k < int32_t(ProxyKind::count); ++k) {
            const DynamicTree& tree = world_.broad_phase.tree(ProxyKind(k));
            proxies += tree.proxy_count();
            tree.query(box, [&](int32_t, int32_t shape) {
                if (overlaps(world_.shapes[shape].aabb, box)) {
                    visit_shape(shape);
                }
                return true;
            });
        }
        if (proxies < world_.shapes.count()) {
            visit_disabled_shapes();
        }
    }

    // A disabled body's boxes are not kept up to date (it is out of the step): its
    // shapes are placed afresh.
    void visit_disabled_shapes() {
        for (int32_t body = 0; body < world_.bodies.capacity(); ++body) {
            if (!world_.bodies.is_live(body) || world_.bodies[body].enabled) {
                continue;
            }
            const Body& b = world_.bodies[body];
            for (int32_t s = b.head_shape; s != null_index; s = world_.shapes[s].next_in_body) {
                if (overlaps(compute_aabb(world_.shapes[s].geometry, b.transform), options_.bounds)) {
                    visit_shape(s);
                }
            }
        }
    }

    // Unculled, every body is visible, shapes or not (a mouse joint's body may have none).
    void visit_all_shapes() {
        for (int32_t shape = 0; shape < world_.shapes.capacity(); ++shape) {
            if (world_.shapes.is_live(shape)) {
                visit_shape(shape);
            }
        }
        for (int32_t body = 0; body < world_.bodies.capacity(); ++body) {
            visible_.insert(body);
        }
    }

    void visit_shape(int32_t shape) {
        const Shape& s = world_.shapes[shape];
        const Body& b = world_.bodies[s.body];
        visible_.insert(s.body);
        if (options_.shapes) {
            draw_geometry(s.geometry, b.transform, shape_color(b, s));
        }
        // A shape without a proxy (a disabled body's) has no fat box in the broadphase.
        if (options_.shape_bounds && s.proxy_key != null_index) {
            draw_box(s.fat_aabb, draw_colors::shape_bounds);
        }
    }

    void draw_geometry(const Geometry& g, const Transform& xf, DrawColor color) const {
        switch (g.type) {
            case ShapeType::circle:
                if (sink_.solid_circle) {
                    sink_.solid_circle({transform_point(xf, g.circle.center), xf.q}, g.circle.radius, color,
                                       sink_.context);
                }
                break;
            case ShapeType::capsule:
                if (sink_.solid_capsule) {
                    sink_.solid_capsule(transform_point(xf, g.capsule.center1), transform_point(xf, g.capsule.center2),
                                        g.capsule.radius, color, sink_.context);
                }
                break;
            case ShapeType::polygon:
                if (sink_.solid_polygon) {
                    sink_.solid_polygon(xf, g.polygon.vertices, g.polygon.count, g.polygon.radius, color,
                                        sink_.context);
                }
                break;
            case ShapeType::segment: draw_segment(xf, g.segment.point1, g.segment.point2, color); break;
            case ShapeType::chain_segment:
                draw_segment(xf, g.chain_segment.point1, g.chain_segment.point2, color);
                break;
            case ShapeType::count: break;
        }
    }

    void draw_segment(const Transform& xf, Vec2 p1, Vec2 p2, DrawColor color) const {
        if (sink_.segment) {
            sink_.segment(transform_point(xf, p1), transform_point(xf, p2), color, sink_.context);
        }
    }

    // A box as a closed outline of four vertices, counter-clockwise from its lower left.
    void draw_box(const AABB& box, DrawColor color) const {
        if (sink_.polygon) {
            const Vec2 corners[4] = {box.lower, {box.upper.x, box.lower.y}, box.upper, {box.lower.x, box.upper.y}};
            sink_.polygon(corners, 4, color, sink_.context);
        }
    }

    // ---- What hangs off a visible body ----

    void draw_body(int32_t body) {
        if (!world_.bodies.is_live(body)) {
            return;  // unculled, every slot is visible, free ones too
        }
        const Body& b = world_.bodies[body];
        if (options_.mass && b.type == BodyType::dynamic) {
            draw_mass(b);
        }
        if (options_.joints) {
            draw_joints_of(b);
        }
        // Every contact has a body that moves: static bodies' lists add nothing but
        // the contacts of bodies culled away.
        if (wants_contacts() && b.type != BodyType::static_body) {
            draw_contacts_of(b);
        }
        if (options_.islands && b.island != null_index) {
            draw_island(b.island);
        }
    }

    void draw_mass(const Body& b) const {
        const Transform frame{b.center, b.transform.q};
        if (sink_.transform) {
            sink_.transform(frame, sink_.context);
        }
        if (sink_.string) {
            char text[mass_text_size];
            std::snprintf(text, sizeof text, "%.2f kg", double(b.mass));
            sink_.string(b.center, text, draw_colors::mass, sink_.context);
        }
    }

    // A joint with a disabled body is out of the world, as its body is: not drawn.
    void draw_joints_of(const Body& b) {
        for (int32_t key = b.head_joint_key; key != null_index;) {
            const int32_t joint = key >> 1;
            const Joint& j = world_.joints[joint];
            key = j.edges[key & 1].next_key;
            const Body& a = world_.bodies[j.def.body_a];
            const Body& other = world_.bodies[j.def.body_b];
            if (drawn_joints_.insert(joint) && a.enabled && other.enabled) {
                draw_joint(j.def, a.transform, other.transform, sink_, options_.joint_extras,
                           joint_extra_length * world_.length_unit);
            }
        }
    }

    void draw_contacts_of(const Body& b) {
        for (int32_t key = b.head_contact_key; key != null_index;) {
            const int32_t contact = contact_of_key(key);
            const Contact& c = world_.contacts[contact];
            key = c.edges[edge_of_key(key)].next_key;
            if (drawn_contacts_.insert(contact) && is_solvable(c)) {
                draw_contact(contact, c);
            }
        }
    }

    // Each point where the begin event puts it: A's centre plus its anchor.
    void draw_contact(int32_t index, const Contact& c) const {
        const Vec2 center_a = world_.bodies[c.edges[0].body].center;
        const float impulse_length = impulse_length_per_newton_second * world_.length_unit;
        for (int32_t i = 0; i < c.point_count; ++i) {
            const ContactPoint& point = c.points[i];
            const Vec2 p = center_a + point.anchor_a;
            if (wants_contact_points() && sink_.point) {
                draw_contact_point(index, p, point.separation);
            }
            if (sink_.segment && options_.contact_normals) {
                sink_.segment(p, p + contact_normal_length * world_.length_unit * c.normal,
                              draw_colors::contact_normal, sink_.context);
            }
            if (sink_.segment && options_.contact_impulses) {
                sink_.segment(p, p + impulse_length * point.normal_impulse * c.normal, draw_colors::contact_impulse,
                              sink_.context);
            }
            if (sink_.segment && options_.friction_impulses) {
                sink_.segment(p, p + impulse_length * point.tangent_impulse * left_perp(c.normal),
                              draw_colors::friction_impulse, sink_.context);
            }
        }
    }

    void draw_contact_point(int32_t index, Vec2 p, float separation) const {
        const int32_t color = graph_colors_.empty() ? -1 : graph_colors_[std::size_t(index)];
        if (color == ConstraintColors::overflow) {
            sink_.point(p, overflow_point_size, draw_colors::graph_overflow, sink_.context);
        } else if (color >= 0) {
            sink_.point(p, contact_point_size, draw_colors::graph_palette[color % draw_colors::graph_palette_size],
                        sink_.context);
        } else {
            const DrawColor plain =
                separation > world_.linear_slop ? draw_colors::speculative_point : draw_colors::contact_point;
            sink_.point(p, contact_point_size, plain, sink_.context);
        }
    }

    // Each contact's colour in the solver's last colouring, -1 for none. The colouring
    // may name contacts destroyed since (between steps): only live ones take a colour,
    // and none is created before the next colouring. After a restore it names none.
    void gather_graph_colors() {
        const ConstraintGraph& graph = world_.graph;
        graph_colors_.assign(std::size_t(world_.contacts.capacity()), int8_t(-1));
        if (!graph.is_colored()) {
            return;
        }
        const std::vector<int32_t>& starts = graph.color_starts();
        const std::vector<int32_t>& ordered = graph.ordered_contacts();
        for (int32_t color = 0; color + 1 < int32_t(starts.size()); ++color) {
            for (int32_t k = starts[std::size_t(color)]; k < starts[std::size_t(color) + 1]; ++k) {
                const int32_t contact = ordered[std::size_t(k)];
                if (world_.contacts.is_live(contact)) {
                    graph_colors_[std::size_t(contact)] = int8_t(color);
                }
            }
        }
    }

    // An awake island's bounds: the union of its bodies' fat boxes.
    void draw_island(int32_t island) {
        const Island& isl = world_.islands[island];
        if (isl.awake_index == null_index || !drawn_islands_.insert(island)) {
            return;
        }
        AABB box;
        bool any = false;
        for (int32_t body = isl.head_body; body != null_index; body = world_.bodies[body].island_next) {
            for (int32_t s = world_.bodies[body].head_shape; s != null_index; s = world_.shapes[s].next_in_body) {
                const AABB& fat = world_.shapes[s].fat_aabb;
                box = any ? union_of(box, fat) : fat;
                any = true;
            }
        }
        if (any) {
            draw_box(box, draw_colors::island);
        }
    }

    const DrawSink& sink_;
    const DrawOptions& options_;
    const DrawnWorld& world_;
    BitSet visible_;  // bodies
    BitSet drawn_joints_;
    BitSet drawn_contacts_;
    BitSet drawn_islands_;
    std::vector<int8_t> graph_colors_;  // per contact, when asked for
};

}  // namespace

void World::draw(const DebugDraw& draw) const {
    QueryLock lock(*this);
    const DrawnWorld drawn{bodies_,
                           shapes_,
                           stages_->broad_phase,
                           stages_->joints.pool(),
                           stages_->contacts.pool(),
                           stages_->islands.pool(),
                           stages_->solver.graph(),
                           tolerances().linear_slop,
                           settings_.length_units_per_meter};
    WorldDrawer(draw, drawn).run();
}

}  // namespace i2d
