// SPDX-License-Identifier: MIT
// Contact bookkeeping: creation from broadphase pairs, the narrowphase update with
// begin/end events, and destruction with the body contact lists kept consistent.
#include <cmath>

#include "collision/manifold.hpp"
#include "dynamics/world.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

int32_t contact_of(int32_t key) { return key >> 1; }
int32_t edge_of(int32_t key) { return key & 1; }

// Speculative points (penetration < 0: a gap within the speculative distance) are dropped
// until the soft-step solver lands: it handles them, while the seed's solver would treat
// a gap as contact and hold the shapes apart.
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

}  // namespace

void World::create_contact(int32_t shape_a, int32_t shape_b) {
    if (!pair_set_.insert(pair_key(shape_a, shape_b))) {
        return;  // the pair has a contact already
    }
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
    // Geometric-mean friction, written so that the product of two huge values cannot
    // overflow; the seed's minimum for restitution.
    c.friction = std::sqrt(a.friction) * std::sqrt(b.friction);
    c.restitution = min_of(a.restitution, b.restitution);
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
}

// Contact events name the pair in shape order; sensor events name the sensor first.
ShapePairEvent World::event_of(const Contact& c) const {
    const bool sensor_is_b = (c.flags & contact_sensor) != 0 && !shapes[c.shape_a].is_sensor;
    return sensor_is_b ? ShapePairEvent{shape_id(c.shape_b), shape_id(c.shape_a)}
                       : ShapePairEvent{shape_id(c.shape_a), shape_id(c.shape_b)};
}

// Events are net per step, so that applying a step's begin events and then its end
// events always gives the true final state: begin when a pair touches at the end of the
// step but did not at its start, end for the reverse, both for a touch that came and
// went within the step, none for a gap that came and went. (The narrowphase runs every
// substep, so a pair can change more than once in a step.)
void World::report_touch_changes(const Contact& c, bool touching_now) {
    if ((c.flags & contact_report_events) == 0) {
        return;
    }
    const bool at_start = (c.flags & contact_touching_at_start) != 0;
    const bool began = !at_start && (touching_now || (c.flags & contact_touched_in_step));
    const bool ended = at_start ? !touching_now : (began && !touching_now);
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

// The narrowphase: every contact in index order (a fixed order) updates its manifold.
// A contact whose fat boxes stopped overlapping stops touching but lives until the end
// of the step, so that a pair never has two contacts (and two event histories) in one
// step.
void World::update_contacts() {
    for (int32_t i = 0; i < contacts.capacity(); ++i) {
        if (!contacts.is_live(i)) {
            continue;
        }
        Contact& c = contacts[i];
        const Shape& a = shapes[c.shape_a];
        const Shape& b = shapes[c.shape_b];
        if (!overlaps(broad_phase_.fat_aabb(a.proxy_key), broad_phase_.fat_aabb(b.proxy_key))) {
            c.flags &= ~uint32_t(contact_touching);
            c.manifold.point_count = 0;
            continue;
        }
        update_manifold(c, without_speculative_points(
                               collide_shapes(a.geometry, bodies[a.body].transform, b.geometry, bodies[b.body].transform)));
        if (c.manifold.point_count > 0) {
            c.flags |= contact_touching | contact_touched_in_step;
        } else {
            c.flags &= ~uint32_t(contact_touching);
        }
    }
}

void World::begin_contact_step() {
    for (int32_t i = 0; i < contacts.capacity(); ++i) {
        if (contacts.is_live(i)) {
            Contact& c = contacts[i];
            c.flags &= ~uint32_t(contact_touching_at_start | contact_touched_in_step);
            if (c.flags & contact_touching) {
                c.flags |= contact_touching_at_start;
            }
        }
    }
}

void World::end_contact_step() {
    for (int32_t i = 0; i < contacts.capacity(); ++i) {
        if (!contacts.is_live(i)) {
            continue;
        }
        const Contact& c = contacts[i];
        if (!overlaps(broad_phase_.fat_aabb(shapes[c.shape_a].proxy_key), broad_phase_.fat_aabb(shapes[c.shape_b].proxy_key))) {
            destroy_contact(i, true);
        } else {
            report_touch_changes(c, (c.flags & contact_touching) != 0);
        }
    }
}

}  // namespace i2d
