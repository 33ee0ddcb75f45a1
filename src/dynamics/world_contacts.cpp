// SPDX-License-Identifier: MIT
// Contact bookkeeping: creation from broadphase pairs, the narrowphase update with
// begin/end events, and destruction with the body contact lists kept consistent.
#include <cmath>

#include "collision/collision_constants.hpp"
#include "collision/geometry.hpp"

#include "collision/manifold.hpp"
#include "dynamics/awake_set.hpp"
#include "dynamics/world.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

int32_t contact_of(int32_t key) { return key >> 1; }
int32_t edge_of(int32_t key) { return key & 1; }

// A sensor reports overlap only: its gaps (speculative points) do not count.
Manifold without_speculative_points(Manifold m) {
    int32_t kept = 0;
    for (int32_t i = 0; i < m.point_count; ++i) {
        if (m.points[i].penetration >= 0.0f) {
            m.points[kept++] = m.points[i];
        }
    }
    m.point_count = kept;
    return m;
}

// How far apart the two shapes may be and still meet within the step: the fixed
// speculative distance plus how far their surfaces can approach in one step (relative
// speed, and spin times extent). Contacts within it get points the solver can stop at.
float speculative_margin(const Body& a, const Body& b, float time_step) {
    const float approach = length(b.linear_velocity - a.linear_velocity) +
                           std::fabs(a.angular_velocity) * a.max_extent + std::fabs(b.angular_velocity) * b.max_extent;
    return speculative_distance + time_step * approach;
}

bool is_moving(const Body& b) {
    return b.awake_index != null_index && (b.linear_velocity.x != 0.0f || b.linear_velocity.y != 0.0f || b.angular_velocity != 0.0f);
}

}  // namespace

void World::add_awake_contact(int32_t contact) { add_to_awake_set(awake_contacts_, contacts, contact); }

void World::remove_awake_contact(int32_t contact) { remove_from_awake_set(awake_contacts_, contacts, contact); }

void World::create_contact(int32_t shape_a, int32_t shape_b) {
    if (!pair_set_.insert(pair_key(shape_a, shape_b))) {
        return;  // the pair has a contact already
    }
    // Room in the awake set for every contact slot first, so that waking never allocates.
    awake_contacts_.reserve(std::size_t(contacts.capacity()) + 1);
    const int32_t index = contacts.allocate();
    if (index == null_index) {
        pair_set_.remove(pair_key(shape_a, shape_b));
        return;  // 16.7 million contacts: the pair goes without one
    }
    const Shape& a = shapes[shape_a];
    const Shape& b = shapes[shape_b];
    Contact& c = contacts[index];
    c.shape_a = shape_a;
    c.shape_b = shape_b;
    if (a.is_sensor || b.is_sensor) {
        const Shape& visitor = a.is_sensor ? b : a;
        c.flags = contact_sensor | (visitor.enable_sensor_events ? contact_report_events : 0u);
    } else if (a.enable_contact_events && b.enable_contact_events) {
        c.flags = contact_report_events;
    }
    const int32_t body_of[2] = {a.body, b.body};
    for (int32_t e = 0; e < 2; ++e) {
        Body& body = bodies[body_of[e]];
        ContactEdge& edge = c.edges[e];
        edge.body = body_of[e];
        edge.next_key = body.head_contact_key;
        if (body.head_contact_key != null_index) {
            contacts[contact_of(body.head_contact_key)].edges[edge_of(body.head_contact_key)].prev_key = (index << 1) | e;
        }
        body.head_contact_key = (index << 1) | e;
        ++body.contact_count;
    }
    // A pair found while both bodies rest (a shape created or refiltered beside them)
    // wakes them, or nothing would ever update it.
    if (!is_awake(a.body) && !is_awake(b.body)) {
        wake_body(a.body);
        wake_body(b.body);
    }
    if (contacts[index].awake_index == null_index) {
        add_awake_contact(index);
    }
}

// Contact events name the pair in shape order; sensor events name the sensor first.
ShapePairEvent World::event_of(const Contact& c) const {
    const bool sensor_is_b = (c.flags & contact_sensor) != 0 && !shapes[c.shape_a].is_sensor;
    return sensor_is_b ? ShapePairEvent{shape_id(c.shape_b), shape_id(c.shape_a)}
                       : ShapePairEvent{shape_id(c.shape_a), shape_id(c.shape_b)};
}

// Events compare the end of the step with its start, so that applying a step's begin
// events and then its end events always gives the true final state.
void World::report_touch_changes(const Contact& c, bool touching_now) {
    if ((c.flags & contact_report_events) == 0) {
        return;
    }
    const bool at_start = (c.flags & contact_touching_at_start) != 0;
    const bool began = !at_start && touching_now;
    const bool ended = at_start && !touching_now;
    const bool sensor = (c.flags & contact_sensor) != 0;
    if (began) {
        (sensor ? events_.sensor_begin : events_.contact_begin).push_back(event_of(c));
    }
    if (ended) {
        (sensor ? events_.sensor_end : events_.contact_end).push_back(event_of(c));
    }
}

void World::destroy_contact(int32_t index, bool during_step) {
    Contact& c = contacts[index];
    if (!during_step) {
        // The caller took something away from under or beside these bodies.
        wake_body(c.edges[0].body);
        wake_body(c.edges[1].body);
    }
    if (c.awake_index != null_index) {
        remove_awake_contact(index);
    }
    if (during_step) {
        report_touch_changes(c, false);
    } else if ((c.flags & contact_touching) && (c.flags & contact_report_events)) {
        // Between steps the last step reported the pair as touching: it ends now, and
        // the end waits for the next step's arrays so that the current ones stay valid.
        const bool sensor = (c.flags & contact_sensor) != 0;
        (sensor ? pending_sensor_ends_ : pending_contact_ends_).push_back(event_of(c));
    }
    for (int32_t e = 0; e < 2; ++e) {
        const ContactEdge& edge = c.edges[e];
        Body& body = bodies[edge.body];
        if (edge.prev_key != null_index) {
            contacts[contact_of(edge.prev_key)].edges[edge_of(edge.prev_key)].next_key = edge.next_key;
        } else {
            body.head_contact_key = edge.next_key;
        }
        if (edge.next_key != null_index) {
            contacts[contact_of(edge.next_key)].edges[edge_of(edge.next_key)].prev_key = edge.prev_key;
        }
        --body.contact_count;
    }
    pair_set_.remove(pair_key(c.shape_a, c.shape_b));
    contacts.free(index);
}

// Called between steps: destroying a shape (all its contacts go), changing its filter
// (only the contacts the new filter forbids go; the others keep touching, no events).
void World::destroy_contacts_of_shape(int32_t shape, bool only_filtered_out) {
    const Body& body = bodies[shapes[shape].body];
    int32_t key = body.head_contact_key;
    while (key != null_index) {
        const Contact& c = contacts[contact_of(key)];
        const int32_t next = c.edges[edge_of(key)].next_key;
        const bool involved = c.shape_a == shape || c.shape_b == shape;
        if (involved && (!only_filtered_out || !should_collide(shapes[c.shape_a].filter, shapes[c.shape_b].filter))) {
            destroy_contact(contact_of(key), false);
        }
        key = next;
    }
}

// Pairs of shapes on one body, of bodies that cannot move each other, of two sensors
// and of filtered shapes never get a contact.
void World::find_new_contacts() {
    new_pairs_.clear();
    broad_phase_.update_pairs(
        [this](int32_t shape_a, int32_t shape_b) {
            const Shape& a = shapes[shape_a];
            const Shape& b = shapes[shape_b];
            if (a.body == b.body || (a.is_sensor && b.is_sensor)) {
                return false;
            }
            if (bodies[a.body].type != BodyType::dynamic && bodies[b.body].type != BodyType::dynamic) {
                return false;
            }
            return should_collide(a.filter, b.filter) && !pair_set_.contains(pair_key(shape_a, shape_b));
        },
        new_pairs_);
    for (const ShapePairCandidate& pair : new_pairs_) {
        create_contact(pair.shape_a, pair.shape_b);
    }
}

// The narrowphase, once per step, over the awake contacts. A contact whose fat boxes
// stopped overlapping stops touching and is destroyed at the end of the step, so that a
// pair never has two contacts (and two event histories) in one step. A contact that
// gains or loses points against a sleeping body wakes it (something arrived or left),
// as does one whose other body moves (a kinematic platform set going).
void World::update_contacts() {
    islands_to_wake_.clear();
    for (const int32_t index : awake_contacts_) {
        Contact& c = contacts[index];
        const Shape& a = shapes[c.shape_a];
        const Shape& b = shapes[c.shape_b];
        const bool had_points = c.manifold.point_count > 0;
        if (!overlaps(broad_phase_.fat_aabb(a.proxy_key), broad_phase_.fat_aabb(b.proxy_key))) {
            c.flags = (c.flags & ~uint32_t(contact_touching)) | contact_disjoint;
            c.manifold.point_count = 0;
        } else {
            update_contact(c, a, b);
        }
        const bool has_points = c.manifold.point_count > 0;
        if ((c.flags & contact_sensor) == 0 && (had_points || has_points)) {
            for (int32_t e = 0; e < 2; ++e) {
                const Body& body = bodies[c.edges[e].body];
                const Body& other = bodies[c.edges[e ^ 1].body];
                if (body.sleeping_island != null_index && (had_points != has_points || is_moving(other))) {
                    islands_to_wake_.push_back(body.sleeping_island);
                }
            }
        }
    }
    // Waking adds to the awake contacts, so it waits until the loop is done; the woken
    // contacts' manifolds are current, since sleeping bodies did not move.
    for (const int32_t island : islands_to_wake_) {
        wake_island(island);
    }
}

// Points within the contact slop count as touching (for events): a resting contact sits
// about there, and a bounce stopped by a speculative point touches without overlap.
void World::update_contact(Contact& c, const Shape& a, const Shape& b) {
    const Body& body_a = bodies[a.body];
    const Body& body_b = bodies[b.body];
    c.friction = mix(settings.friction_mixing, a.friction, b.friction);
    c.restitution = mix(settings.restitution_mixing, a.restitution, b.restitution);
    c.rolling_resistance = a.rolling_resistance == 0.0f && b.rolling_resistance == 0.0f
                               ? 0.0f
                               : max_of(a.rolling_resistance * rounding_radius(a.geometry),
                                        b.rolling_resistance * rounding_radius(b.geometry));
    // Each surface moves counter-clockwise around its own shape: along +left_perp(n)
    // for A, whose outward normal is n, and along -left_perp(n) for B. No slip between
    // the moving surfaces means dot(vB - vA, left_perp(n)) = speed A + speed B.
    c.tangent_speed = a.tangent_speed + b.tangent_speed;
    const bool sensor = (c.flags & contact_sensor) != 0;
    const Manifold fresh = collide_shapes(a.geometry, body_a.transform, b.geometry, body_b.transform,
                                          speculative_margin(body_a, body_b, last_time_step_));
    update_manifold(c, sensor ? without_speculative_points(fresh) : fresh);
}

// Touching describes where the step left the bodies, so that events arrive in the step
// that made the touch. A solid contact touches when a point ends within the contact
// slop: its separation follows from the substeps' motion, with no second narrowphase
// (its speculative points cover the whole step). A sensor overlap is tested afresh.
void World::update_touching() {
    for (const int32_t index : awake_contacts_) {
        Contact& c = contacts[index];
        c.flags &= ~uint32_t(contact_touching);
        if ((c.flags & contact_sensor) != 0 && (c.flags & contact_disjoint) == 0) {
            const Shape& a = shapes[c.shape_a];
            const Shape& b = shapes[c.shape_b];
            const Manifold m = without_speculative_points(
                collide_shapes(a.geometry, bodies[a.body].transform, b.geometry, bodies[b.body].transform));
            c.flags |= m.point_count > 0 ? uint32_t(contact_touching) : 0u;
        }
    }
    for (const ContactConstraint& constraint : constraints_) {
        Contact& c = contacts[constraint.contact];
        for (int32_t i = 0; i < constraint.point_count; ++i) {
            if (separation_of(constraint, constraint.points[i], states_) <= settings.contact_slop) {
                c.flags |= contact_touching;
            }
        }
    }
}

void World::begin_contact_step() {
    for (const int32_t index : awake_contacts_) {
        Contact& c = contacts[index];
        c.flags &= ~uint32_t(contact_touching_at_start);
        if (c.flags & contact_touching) {
            c.flags |= contact_touching_at_start;
        }
    }
}

// Backwards, because destroying a contact moves the last awake contact into its place.
void World::end_contact_step() {
    for (int32_t k = int32_t(awake_contacts_.size()) - 1; k >= 0; --k) {
        const int32_t index = awake_contacts_[k];
        const Contact& c = contacts[index];
        if (c.flags & contact_disjoint) {
            destroy_contact(index, true);
        } else {
            report_touch_changes(c, (c.flags & contact_touching) != 0);
        }
    }
}

}  // namespace i2d
