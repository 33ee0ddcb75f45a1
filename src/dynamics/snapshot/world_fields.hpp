// SPDX-License-Identifier: MIT
// The fields of everything a world holds, in the order a snapshot stores them: one list
// per struct, for saving and loading alike (field_io.hpp).
//
// Design note: a `Part` says what is saved. A full snapshot (whole) has every field; a
// rollback state (state) only what a step can change, for a world whose structure (its
// bodies, shapes, joints, chains and settings) is the one it was saved from. Fields that
// only a structural change moves (a body's mass, a shape's geometry, a joint's settings)
// are in the whole part alone. Structs whose every field a step may change (contacts,
// islands, tree nodes) are whole in both, less what the rest gives again as they load (a
// contact's bodies and material come from its shapes, its unused points are fresh).
#pragma once

#include <algorithm>
#include <vector>

#include "broadphase/dynamic_tree.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/chain.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/contact/contact.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint.hpp"
#include "core/field_io.hpp"
#include "core/force_inline.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/world/world_def.hpp"

namespace i2d {

enum class SnapshotPart : uint8_t { whole, state };

/// The format versions that added settings fields, in the numbering of the format that
/// holds them: snapshots and recordings count their versions apart.
struct SettingsVersions {
    uint32_t length_unit;
    uint32_t impact_chains;
};
constexpr SettingsVersions snapshot_settings_versions{2, 4};
constexpr SettingsVersions recording_settings_versions{2, 3};

/// The simulation's settings; not the host's wiring (workers, task callbacks, SIMD path,
/// profiling), which a world keeps as its own.
template <class Io, class Def>
void settings_fields(Io& io, Def& s, const SettingsVersions& added) {
    io(s.gravity);
    io(s.contact_slop);
    io(s.contact_hertz);
    io(s.contact_damping_ratio);
    io(s.contact_push_max_speed);
    io(s.joint_hertz);
    io(s.joint_damping_ratio);
    io(s.restitution_threshold);
    io(s.maximum_linear_speed);
    io(s.friction_mixing);
    io(s.restitution_mixing);
    io(s.enable_sleep);
    io(s.sleep_speed_threshold);
    io(s.time_to_sleep);
    io(s.enable_contact_recycling);
    io(s.enable_continuous);
    io(s.hit_event_threshold);
    if (io.has_version(added.length_unit)) {
        io(s.length_units_per_meter);
    } else if constexpr (Io::loading) {
        s.length_units_per_meter = 1.0f;
    }
    if (io.has_version(added.impact_chains)) {
        io(s.enable_impact_chains);
    } else if constexpr (Io::loading) {
        s.enable_impact_chains = true;
    }
}

template <class Io, class B>
void body_fields(Io& io, B& b, SnapshotPart part) {
    io(b.transform);
    io(b.center);
    io(b.linear_velocity);
    io(b.angular_velocity);
    io(b.awake_index);
    io(b.force);
    io(b.torque);
    io(b.sleep_time);
    io(b.island);
    io(b.island_prev);
    io(b.island_next);
    io(b.needs_cover);
    io(b.head_contact_key);
    io(b.contact_count);
    io(b.center0);
    io(b.rotation0);
    if (part == SnapshotPart::state) {
        return;
    }
    io(b.type);
    io(b.quarantined);
    io(b.max_extent);
    io(b.min_extent);
    if constexpr (Io::loading) {
        if (!io.has_version(5) && b.type == BodyType::static_body) {
            b.max_extent = b.min_extent = 0.0f;  // format 5 made them 0
        }
    }
    io(b.inv_mass);
    io(b.inv_inertia);
    io(b.mass);
    io(b.inertia);
    io(b.local_center);
    io(b.fixed_rotation);
    io(b.enable_sleep);
    io(b.is_bullet);
    io(b.gravity_scale);
    io(b.linear_damping);
    io(b.angular_damping);
    io(b.head_shape);
    io(b.shape_count);
    io(b.head_joint_key);
    io(b.joint_count);
    io(b.user_data);
    if (io.has_version(2)) {
        io(b.sleep_threshold);
        io(b.enabled);
        io(b.mass_overridden);
        io(b.override_inertia);
    } else if constexpr (Io::loading) {
        b.enabled = true;  // the sleep threshold is the world's (World::transfer)
        b.mass_overridden = false;
    }
}

template <class Io, class G>
void geometry_fields(Io& io, G& g) {
    io(g.type);
    switch (g.type) {
        case ShapeType::circle:
            io(g.circle.center);
            io(g.circle.radius);
            break;
        case ShapeType::capsule:
            io(g.capsule.center1);
            io(g.capsule.center2);
            io(g.capsule.radius);
            break;
        case ShapeType::segment:
            io(g.segment.point1);
            io(g.segment.point2);
            break;
        case ShapeType::polygon:
            io(g.polygon.count);
            io.check(g.polygon.count >= 1 && g.polygon.count <= max_polygon_vertices,
                     "a polygon's vertex count is out of range");
            for (int32_t i = 0; i < max_polygon_vertices; ++i) {
                io(g.polygon.vertices[i]);
                io(g.polygon.normals[i]);
            }
            io(g.polygon.centroid);
            io(g.polygon.radius);
            break;
        case ShapeType::chain_segment:
            io(g.chain_segment.ghost1);
            io(g.chain_segment.point1);
            io(g.chain_segment.point2);
            io(g.chain_segment.ghost2);
            break;
        case ShapeType::count: break;
    }
}

template <class Io, class F>
void filter_fields(Io& io, F& f) {
    io(f.category_bits);
    io(f.mask_bits);
    io(f.group_index);
}

template <class Io, class S>
void shape_fields(Io& io, S& s, SnapshotPart part) {
    io(s.proxy_key);
    io(s.aabb);
    io(s.fat_aabb);
    io(s.ahead_aabb);
    io(s.enlarged);
    if (part == SnapshotPart::state) {
        return;
    }
    io(s.body);
    io(s.is_sensor);
    io(s.enable_contact_events);
    io(s.enable_sensor_events);
    io(s.enable_hit_events);
    if (io.has_version(3)) {
        io(s.enable_custom_filtering);
        io(s.enable_pre_solve_events);
    }
    io(s.aabb_margin);
    io(s.friction);
    io(s.restitution);
    io(s.rolling_resistance);
    io(s.tangent_speed);
    io(s.prev_in_body);
    io(s.next_in_body);
    io(s.chain);
    io(s.density);
    filter_fields(io, s.filter);
    io(s.user_data);
    geometry_fields(io, s.geometry);
}

template <class Io, class C>
void chain_fields(Io& io, C& c) {
    io(c.body);
    list_fields(io, c.shapes, Pool<Shape>::max_slots, "a chain lists more segments than the bytes left could hold");
    io(c.is_loop);
    io(c.user_data);
}

template <class Io, class D>
void joint_def_fields(Io& io, D& d) {
    io(d.type);
    io(d.body_a);
    io(d.body_b);
    io(d.local_anchor_a);
    io(d.local_anchor_b);
    io(d.collide_connected);
    io(d.force_threshold);
    io(d.torque_threshold);
    io(d.user_data);
    // Every kind's settings, not only the one read: a joint comes back exactly as it was.
    auto& r = d.revolute;
    io(r.reference_angle), io(r.enable_limit), io(r.lower_angle), io(r.upper_angle), io(r.enable_motor);
    io(r.motor_speed), io(r.max_motor_torque), io(r.enable_spring), io(r.hertz), io(r.damping_ratio);
    io(r.target_angle);
    auto& p = d.prismatic;
    io(p.local_axis_a), io(p.reference_angle), io(p.enable_limit), io(p.lower_translation);
    io(p.upper_translation), io(p.enable_motor), io(p.motor_speed), io(p.max_motor_force), io(p.enable_spring);
    io(p.hertz), io(p.damping_ratio), io(p.target_translation);
    auto& l = d.distance;
    io(l.length), io(l.enable_limit), io(l.min_length), io(l.max_length), io(l.enable_spring), io(l.hertz);
    io(l.damping_ratio), io(l.enable_motor), io(l.motor_speed), io(l.max_motor_force);
    auto& w = d.weld;
    io(w.reference_angle), io(w.linear_hertz), io(w.angular_hertz), io(w.linear_damping_ratio);
    io(w.angular_damping_ratio);
    auto& h = d.wheel;
    io(h.local_axis_a), io(h.enable_spring), io(h.hertz), io(h.damping_ratio), io(h.enable_limit);
    io(h.lower_translation), io(h.upper_translation), io(h.enable_motor), io(h.motor_speed), io(h.max_motor_torque);
    auto& m = d.motor;
    io(m.linear_offset), io(m.angular_offset), io(m.max_force), io(m.max_torque), io(m.correction_factor);
    auto& u = d.mouse;
    io(u.target), io(u.hertz), io(u.damping_ratio), io(u.max_force);
}

template <class Io, class J>
void joint_fields(Io& io, J& j, SnapshotPart part) {
    io(j.impulses.linear);
    io(j.impulses.angular);
    io(j.impulses.axial);
    io(j.impulses.spring);
    io(j.impulses.motor);
    io(j.impulses.lower);
    io(j.impulses.upper);
    io(j.reaction_force);
    io(j.reaction_torque);
    io(j.motor_output);
    io(j.solver_index);
    io(j.island_link);
    if (part == SnapshotPart::state) {
        return;
    }
    joint_def_fields(io, j.def);
    for (auto& edge : j.edges) {
        io(edge.body);
        io(edge.prev_key);
        io(edge.next_key);
    }
}

// Inlined so that a save stages it (save_staged, field_io.hpp) with the stage's size in
// a register: called, each field reloaded it (326 against 142 us for pile_1k's state).
template <class Io, class C>
I2D_FORCE_INLINE void contact_fields(Io& io, C& c) {
    io(c.normal);
    io(c.point_count);
    io.check(c.point_count >= 0 && c.point_count <= 2, "a contact has more than two points");
    io(c.flags);
    io(c.state_a);
    io(c.state_b);
    io(c.rolling_impulse);
    // Format 6 mixes the material again from the shapes as it loads (ContactSet::load),
    // as the contact did when it was made and whenever a shape's material changed since.
    if (!io.has_version(6)) {
        io(c.friction);
        io(c.restitution);
        io(c.rolling_resistance);
        io(c.tangent_speed);
    }
    io(c.awake_index);
    io(c.hit_speed);
    io(c.hit_point);
    io.check(c.hit_point >= 0 && c.hit_point < 2, "a contact's hit point is out of range");
    // Format 6 keeps only the points a contact has: the rest are never read (the points,
    // their ids and base separations past point_count), and load as a fresh contact's.
    const int32_t kept_points = io.has_version(6) ? std::clamp(c.point_count, 0, 2) : 2;
    for (int32_t i = 0; i < kept_points; ++i) {
        auto& point = c.points[i];
        io(point.anchor_a);
        io(point.anchor_b);
        io(point.separation);
        io(point.normal_impulse);
        io(point.tangent_impulse);
    }
    io(c.shape_a);
    io(c.shape_b);
    for (auto& edge : c.edges) {
        if (!io.has_version(6)) {
            io(edge.body);  // format 6: the body of the edge's shape, set as the contact loads
        }
        io(edge.prev_key);
        io(edge.next_key);
    }
    for (int32_t i = 0; i < kept_points; ++i) {
        io(c.point_ids[i]);
    }
    for (int32_t i = 0; i < kept_points; ++i) {
        io(c.base_separations[i]);
    }
    if constexpr (Io::loading) {
        for (int32_t i = kept_points; i < 2; ++i) {
            c.points[i] = ContactPoint{};
            c.point_ids[i] = 0u;
            c.base_separations[i] = 0.0f;
        }
    }
    io(c.made_rotation_a);
    io(c.made_rotation_b);
    io(c.made_relative_pose);
}

template <class Io, class E>
void pending_end_fields(Io& io, E& e) {
    io(e.shape_a);
    io(e.shape_b);
    io(e.generation_a);
    io(e.generation_b);
}

/// A list of structs: its length, then each through fields(io, item).
template <class Io, class List, class Fields>
void struct_list_fields(Io& io, List& list, std::size_t min_item_bytes, int32_t limit, const char* too_long,
                        Fields&& fields) {
    if constexpr (!Io::loading) {
        io.count(int32_t(list.size()));
    } else {
        list.resize(std::size_t(io.count(min_item_bytes, limit, too_long)));
    }
    for (auto& item : list) {
        fields(io, item);
    }
}

template <class Io, class I>
void island_fields(Io& io, I& island) {
    io(island.head_body);
    io(island.tail_body);
    io(island.body_count);
    io(island.link_count);
    io(island.removed_links);
    io(island.awake_index);
}

}  // namespace i2d
