// SPDX-License-Identifier: MIT
// Islands and sleep: the awake set, rest timers, falling asleep together, waking.
//
// Design note: islands are found afresh each step by union-find over the awake bodies
// and the contacts that hold points (cost linear in what is awake), rather than kept
// persistent and split on contact removal as Box2D v3 does: simpler, and the step
// already touches every awake contact. Only a sleeping island is stored: a list of its
// bodies, so that waking it is linear in its size. Kinematic bodies do not join
// islands (they would chain everything they touch into one), but a moving one keeps
// the islands it touches awake.
#include "dynamics/awake_set.hpp"
#include "dynamics/world.hpp"
#include "math/math.hpp"

namespace i2d {

void World::add_awake_body(int32_t body) { add_to_awake_set(awake_bodies_, bodies, body); }

void World::remove_awake_body(int32_t body) { remove_from_awake_set(awake_bodies_, bodies, body); }

void World::wake_body(int32_t body) {
    Body& b = bodies[body];
    b.sleep_time = 0.0f;
    if (b.sleeping_island != null_index) {
        wake_island(b.sleeping_island);
    }
}

void World::wake_island(int32_t island) {
    if (!sleeping_islands_.is_live(island)) {
        return;  // woken already
    }
    int32_t body = sleeping_islands_[island].head_body;
    while (body != null_index) {
        Body& b = bodies[body];
        const int32_t next = b.next_in_island;
        b.next_in_island = null_index;
        b.sleeping_island = null_index;
        b.sleep_time = 0.0f;
        add_awake_body(body);
        visit_contacts(body, [this](int32_t contact, int32_t) {
            if (contacts[contact].awake_index == null_index) {
                add_awake_contact(contact);
            }
        });
        body = next;
    }
    sleeping_islands_.free(island);
}

void World::wake_all() {
    for (int32_t i = 0; i < sleeping_islands_.capacity(); ++i) {
        if (sleeping_islands_.is_live(i)) {
            wake_island(i);
        }
    }
}

// A body rests while its fastest point (spin x extent) and its centre stay slow.
void World::update_sleep_timers(float time_step) {
    const float threshold = settings.sleep_speed_threshold;
    for (const int32_t index : awake_bodies_) {
        Body& b = bodies[index];
        const bool resting = settings.enable_sleep && b.enable_sleep && length(b.linear_velocity) <= threshold &&
                             std::fabs(b.angular_velocity) * b.max_extent <= threshold;
        b.sleep_time = resting ? b.sleep_time + time_step : 0.0f;
    }
}

int32_t World::island_root(int32_t k) {
    while (island_parent_[k] != k) {
        island_parent_[k] = island_parent_[island_parent_[k]];  // path halving
        k = island_parent_[k];
    }
    return k;
}

namespace {

bool links_island(const Contact& c) {
    return (c.flags & contact_sensor) == 0 && c.manifold.point_count > 0;
}

}  // namespace

// Marks in falls_asleep_ the awake bodies whose whole island has rested long enough.
void World::find_islands_to_sleep() {
    const int32_t count = int32_t(awake_bodies_.size());
    falls_asleep_.assign(std::size_t(count), 0);
    if (!settings.enable_sleep) {
        return;
    }
    island_parent_.resize(std::size_t(count));
    island_rest_.resize(std::size_t(count));
    for (int32_t k = 0; k < count; ++k) {
        island_parent_[k] = k;
        island_rest_[k] = bodies[awake_bodies_[k]].sleep_time;
    }
    for (const int32_t index : awake_contacts_) {
        const Contact& c = contacts[index];
        const Body& a = bodies[c.edges[0].body];
        const Body& b = bodies[c.edges[1].body];
        if (!links_island(c) || a.awake_index == null_index || b.awake_index == null_index) {
            continue;
        }
        if (a.type == BodyType::dynamic && b.type == BodyType::dynamic) {
            const int32_t root_a = island_root(a.awake_index), root_b = island_root(b.awake_index);
            // The smaller index becomes the root: the same scene gives the same islands.
            island_parent_[max_of(root_a, root_b)] = min_of(root_a, root_b);
        } else if ((a.type == BodyType::kinematic) != (b.type == BodyType::kinematic)) {
            // A kinematic body shares its rest time with the island it touches.
            const Body& mover = a.type == BodyType::kinematic ? a : b;
            const Body& other = a.type == BodyType::kinematic ? b : a;
            island_rest_[other.awake_index] = min_of(island_rest_[other.awake_index], mover.sleep_time);
        }
    }
    for (int32_t k = 0; k < count; ++k) {
        const int32_t root = island_root(k);
        island_rest_[root] = min_of(island_rest_[root], island_rest_[k]);
    }
    for (int32_t k = 0; k < count; ++k) {
        falls_asleep_[k] = island_rest_[island_root(k)] >= settings.time_to_sleep ? 1 : 0;
    }
}

// Groups the marked bodies by island root (lists threaded through island_next_, in
// awake order), then puts each group to sleep.
void World::put_marked_islands_to_sleep() {
    const int32_t count = int32_t(falls_asleep_.size());
    island_head_.assign(std::size_t(count), null_index);
    island_next_.assign(std::size_t(count), null_index);
    bool any = false;
    for (int32_t k = count - 1; k >= 0; --k) {
        if (falls_asleep_[k]) {
            const int32_t root = island_root(k);
            island_next_[k] = island_head_[root];
            island_head_[root] = k;
            any = true;
        }
    }
    if (!any) {
        return;
    }
    // Awake indices change as bodies leave the set: collect body indices first, one
    // group per island, each group ended by null_index.
    std::vector<int32_t>& members = island_members_;
    members.clear();
    for (int32_t root = 0; root < count; ++root) {
        if (island_head_[root] != null_index) {
            for (int32_t k = island_head_[root]; k != null_index; k = island_next_[k]) {
                members.push_back(awake_bodies_[k]);
            }
            members.push_back(null_index);
        }
    }
    std::size_t start = 0;
    for (std::size_t i = 0; i < members.size(); ++i) {
        if (members[i] == null_index) {
            put_to_sleep(members.data() + start, int32_t(i - start));
            start = i + 1;
        }
    }
    drop_sleeping_contacts();
}

void World::put_to_sleep(const int32_t* members, int32_t count) {
    const int32_t island = sleeping_islands_.allocate();
    if (island == null_index) {
        return;  // no room for another island: the bodies stay awake
    }
    SleepingIsland& record = sleeping_islands_[island];
    for (int32_t i = 0; i < count; ++i) {
        Body& b = bodies[members[i]];
        b.linear_velocity = {};
        b.angular_velocity = 0.0f;
        b.force = {};
        b.torque = 0.0f;
        b.sleeping_island = island;
        b.next_in_island = record.head_body;
        record.head_body = members[i];
        ++record.body_count;
        remove_awake_body(members[i]);
    }
}

// Contacts with no awake body left leave the awake set (backwards: removal moves the
// last one into the hole).
void World::drop_sleeping_contacts() {
    for (int32_t k = int32_t(awake_contacts_.size()) - 1; k >= 0; --k) {
        const Contact& c = contacts[awake_contacts_[k]];
        if (!is_awake(c.edges[0].body) && !is_awake(c.edges[1].body)) {
            remove_awake_contact(awake_contacts_[k]);
        }
    }
}

// The API's sleep: the island is found by walking touching contacts from the body.
void World::sleep_body(int32_t body) {
    if (!is_awake(body)) {
        return;
    }
    std::vector<int32_t>& members = island_members_;
    members.assign(1, body);
    bodies[body].sleep_time = -1.0f;  // marks a member while walking
    for (std::size_t i = 0; i < members.size(); ++i) {
        const Body& b = bodies[members[i]];
        if (b.type != BodyType::dynamic) {
            continue;  // islands do not pass through kinematic bodies
        }
        visit_contacts(members[i], [this, &members](int32_t contact, int32_t other) {
            Body& o = bodies[other];
            if (links_island(contacts[contact]) && o.type == BodyType::dynamic && is_awake(other) &&
                o.sleep_time >= 0.0f) {
                o.sleep_time = -1.0f;
                members.push_back(other);
            }
        });
    }
    for (const int32_t member : members) {
        bodies[member].sleep_time = 0.0f;
    }
    put_to_sleep(members.data(), int32_t(members.size()));
    drop_sleeping_contacts();
}

}  // namespace i2d
