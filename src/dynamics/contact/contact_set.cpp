// SPDX-License-Identifier: MIT
// ContactSet: creating and destroying contacts with the body contact lists kept
// consistent, the awake contact list, materials.
#include <cmath>

#include "collision/geometry.hpp"
#include "core/assert.hpp"
#include "core/dense_list.hpp"
#include "core/reserve.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "math/math.hpp"

namespace i2d {

void ContactSet::add_awake(int32_t contact) {
    dense_list_add(awake_, contact, [this](int32_t c) -> int32_t& { return pool_[c].awake_index; });
    ++layout_version_;
}

void ContactSet::remove_awake(int32_t contact) {
    dense_list_remove(awake_, contact, [this](int32_t c) -> int32_t& { return pool_[c].awake_index; });
    ++layout_version_;
}

void ContactSet::create_contact(int32_t shape_a, int32_t shape_b, WakeBody wake) {
    if (!pair_set_.insert(pair_key(shape_a, shape_b))) {
        return;  // the pair has a contact already
    }
    // Room in the awake list for every contact slot first, so that waking never allocates.
    reserve_room(awake_, std::size_t(pool_.capacity()) + 1);
    const int32_t index = pool_.allocate();
    if (index == null_index) {
        pair_set_.remove(pair_key(shape_a, shape_b));
        return;  // 16.7 million contacts: the pair goes without one
    }
    const Shape& a = shapes_[shape_a];
    const Shape& b = shapes_[shape_b];
    Contact& c = pool_[index];
    c.shape_a = shape_a;
    c.shape_b = shape_b;
    if (a.is_sensor || b.is_sensor) {
        const Shape& visitor = a.is_sensor ? b : a;
        c.flags = contact_sensor | (visitor.enable_sensor_events ? contact_report_events : 0u);
    } else {
        c.flags = (a.enable_contact_events && b.enable_contact_events ? uint32_t(contact_report_events) : 0u) |
                  (a.enable_hit_events || b.enable_hit_events ? uint32_t(contact_hit_events) : 0u) |
                  (a.enable_pre_solve_events || b.enable_pre_solve_events ? uint32_t(contact_pre_solve) : 0u);
    }
    mix_material(c, a, b);
    const int32_t body_of[2] = {a.body, b.body};
    for (int32_t e = 0; e < 2; ++e) {
        Body& body = bodies_[body_of[e]];
        ContactEdge& edge = c.edges[e];
        edge.body = body_of[e];
        edge.next_key = body.head_contact_key;
        if (body.head_contact_key != null_index) {
            pool_[contact_of_key(body.head_contact_key)].edges[edge_of_key(body.head_contact_key)].prev_key =
                (index << 1) | e;
        }
        body.head_contact_key = (index << 1) | e;
        ++body.contact_count;
    }
    // A pair found while both bodies rest (a shape created or refiltered beside them)
    // wakes them, or nothing would ever update it.
    if (!is_awake(a.body) && !is_awake(b.body)) {
        wake(a.body);
        wake(b.body);
    }
    if (pool_[index].awake_index == null_index) {
        add_awake(index);
    }
}

// Between steps the caller woke both bodies first.
void ContactSet::destroy_contact(int32_t index, bool during_step) {
    Contact& c = pool_[index];
    if (c.flags & contact_island_link) {
        link_changes_.push_back({c.edges[0].body, c.edges[1].body, false});
    }
    if (c.awake_index != null_index) {
        remove_awake(index);
    }
    if (during_step) {
        report_touch_changes(c, false);
    } else if ((c.flags & contact_touching) && (c.flags & contact_report_events)) {
        // Between steps the last step reported the pair as touching: it ends now, and
        // the end waits for the next step's arrays so that the current ones stay valid.
        const bool sensor = (c.flags & contact_sensor) != 0;
        (sensor ? events_.pending_sensor_ends : events_.pending_contact_ends).push_back(pair_of(c));
    }
    for (int32_t e = 0; e < 2; ++e) {
        const ContactEdge& edge = c.edges[e];
        Body& body = bodies_[edge.body];
        if (edge.prev_key != null_index) {
            pool_[contact_of_key(edge.prev_key)].edges[edge_of_key(edge.prev_key)].next_key = edge.next_key;
        } else {
            body.head_contact_key = edge.next_key;
        }
        if (edge.next_key != null_index) {
            pool_[contact_of_key(edge.next_key)].edges[edge_of_key(edge.next_key)].prev_key = edge.prev_key;
        }
        --body.contact_count;
    }
    pair_set_.remove(pair_key(c.shape_a, c.shape_b));
    pool_.free(index);
}

// Called between steps: destroying a shape (all its contacts go), changing its filter
// (only the contacts the new filter forbids go; the others keep touching, no events).
// The caller took something away from under or beside each contact's bodies: both wake
// before it goes.
void ContactSet::destroy_contacts_of_shape(int32_t shape, bool only_filtered_out, WakeBody wake) {
    int32_t key = bodies_[shapes_[shape].body].head_contact_key;
    while (key != null_index) {
        const Contact& c = pool_[contact_of_key(key)];
        const int32_t next = c.edges[edge_of_key(key)].next_key;
        const bool involved = c.shape_a == shape || c.shape_b == shape;
        if (involved && (!only_filtered_out || !should_collide(shapes_[c.shape_a].filter, shapes_[c.shape_b].filter))) {
            wake(c.edges[0].body);
            wake(c.edges[1].body);
            destroy_contact(contact_of_key(key), false);
        }
        key = next;
    }
}

void ContactSet::destroy_contacts_between(int32_t body_a, int32_t body_b, WakeBody wake) {
    int32_t key = bodies_[body_a].head_contact_key;
    while (key != null_index) {
        const Contact& c = pool_[contact_of_key(key)];
        const int32_t next = c.edges[edge_of_key(key)].next_key;
        if (c.edges[edge_of_key(key) ^ 1].body == body_b) {
            wake(c.edges[0].body);
            wake(c.edges[1].body);
            destroy_contact(contact_of_key(key), false);
        }
        key = next;
    }
}

// A shape's material, outline (its rounding radius), hit-event or pre-solve flag changed: its
// contacts take the new values. Contact and sensor event flags stay as the contact was
// made, so that every begin event reported keeps its end.
void ContactSet::refresh_contacts_of_shape(int32_t shape) {
    ++layout_version_;  // the colouring notes whether any contact is elastic
    visit_contacts(shapes_[shape].body, [&](int32_t contact, int32_t) {
        Contact& c = pool_[contact];
        if (c.shape_a == shape || c.shape_b == shape) {
            const Shape& a = shapes_[c.shape_a];
            const Shape& b = shapes_[c.shape_b];
            mix_material(c, a, b);
            if ((c.flags & contact_sensor) == 0) {
                const bool hits = a.enable_hit_events || b.enable_hit_events;
                const bool pre_solve = a.enable_pre_solve_events || b.enable_pre_solve_events;
                c.flags = hits ? c.flags | contact_hit_events : c.flags & ~uint32_t(contact_hit_events);
                c.flags = pre_solve ? c.flags | contact_pre_solve : c.flags & ~uint32_t(contact_pre_solve);
            }
        }
    });
}

// Material is mixed when the contact is made and whenever a shape's material changes,
// not every step: the geometric mean costs two square roots.
void ContactSet::mix_material(Contact& c, const Shape& a, const Shape& b) const {
    c.friction = mix(settings_.friction_mixing, a.friction, b.friction);
    c.restitution = mix(settings_.restitution_mixing, a.restitution, b.restitution);
    c.rolling_resistance = a.rolling_resistance == 0.0f && b.rolling_resistance == 0.0f
                               ? 0.0f
                               : max_of(a.rolling_resistance * rounding_radius(a.geometry),
                                        b.rolling_resistance * rounding_radius(b.geometry));
    // Each surface moves counter-clockwise around its own shape: along +left_perp(n)
    // for A, whose outward normal is n, and along -left_perp(n) for B. No slip between
    // the moving surfaces means dot(vB - vA, left_perp(n)) = speed A + speed B.
    c.tangent_speed = a.tangent_speed + b.tangent_speed;
}

void ContactSet::body_woke(int32_t body) {
    visit_contacts(body, [&](int32_t contact, int32_t) {
        Contact& c = pool_[contact];
        if (c.awake_index == null_index) {
            add_awake(contact);
            if (is_solvable(c)) {
                solvable_.push_back(contact);
            }
        }
        const int32_t edge = c.edges[0].body == body ? 0 : 1;
        layout_version_ += set_solver_state(c, edge, bodies_[body]) ? 1u : 0u;
    });
}

void ContactSet::body_slept(int32_t body) {
    visit_contacts(body, [&](int32_t contact, int32_t other) {
        if (pool_[contact].awake_index != null_index && !is_awake(other)) {
            remove_awake(contact);
        }
    });
}

void ContactSet::forget_manifolds(int32_t body) {
    visit_contacts(body, [&](int32_t contact, int32_t) { pool_[contact].flags &= ~uint32_t(contact_recyclable); });
}

int32_t ContactSet::touching_count() const {
    int32_t count = 0;
    for (int32_t i = 0; i < pool_.capacity(); ++i) {
        if (pool_.is_live(i) && (pool_[i].flags & (contact_touching | contact_sensor)) == contact_touching) {
            ++count;
        }
    }
    return count;
}

void ContactSet::validate() const {
#if defined(I2D_VALIDATE)
    for (int32_t k = 0; k < int32_t(awake_.size()); ++k) {
        I2D_ASSERT(pool_.is_live(awake_[k]) && pool_[awake_[k]].awake_index == k);
    }
    I2D_ASSERT(pair_set_.count() == pool_.count());
    for (int32_t i = 0; i < pool_.capacity(); ++i) {
        if (!pool_.is_live(i)) {
            continue;
        }
        const Contact& c = pool_[i];
        I2D_ASSERT(c.shape_a < c.shape_b && shapes_.is_live(c.shape_a) && shapes_.is_live(c.shape_b));
        I2D_ASSERT(pair_set_.contains(pair_key(c.shape_a, c.shape_b)));
        // Exactly the contacts with an awake body are updated each step.
        const bool has_awake_body = is_awake(c.edges[0].body) || is_awake(c.edges[1].body);
        I2D_ASSERT(has_awake_body == (c.awake_index != null_index));
        // A link joins two bodies of one island.
        if (c.flags & contact_island_link) {
            I2D_ASSERT(bodies_[c.edges[0].body].island == bodies_[c.edges[1].body].island);
        }
    }
#endif
}

}  // namespace i2d
