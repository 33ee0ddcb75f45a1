// SPDX-License-Identifier: MIT
// World lifecycle (bodies, shapes, mass, proxies) and the step.
#include "dynamics/world.hpp"

#include <cfloat>
#include <cmath>

#include "collision/geometry.hpp"
#include "core/timer.hpp"
#include "math/math.hpp"
#include "dynamics/constants.hpp"

namespace i2d {

namespace {

ProxyKind proxy_kind_of(BodyType type) {
    switch (type) {
        case BodyType::static_body: return ProxyKind::static_proxy;
        case BodyType::kinematic: return ProxyKind::kinematic_proxy;
        default: return ProxyKind::dynamic_proxy;
    }
}

// Static shapes never move, so their fat box is their tight box. A moving shape's box
// grows by the margin and stretches along the displacement expected over one step, so
// that a falling body is re-inserted about once a step rather than every substep.
AABB fatten(const AABB& box, BodyType type, Vec2 displacement) {
    if (type == BodyType::static_body) {
        return box;
    }
    const Vec2 margin{aabb_margin, aabb_margin};
    return {min(box.lower, box.lower + displacement) - margin, max(box.upper, box.upper + displacement) + margin};
}

}  // namespace

World::World(const WorldDef& def) : settings(def) {}

uint64_t World::shape_id(int32_t shape) const {
    const uint16_t generation = shapes.generation(shape);
    return id_encoder.shape ? id_encoder.shape(id_encoder.tag, shape, generation)
                            : (uint64_t(generation) << 32) | uint32_t(shape);
}

uint64_t World::body_id(int32_t body) const {
    const uint16_t generation = bodies.generation(body);
    return id_encoder.body ? id_encoder.body(id_encoder.tag, body, generation)
                           : (uint64_t(generation) << 32) | uint32_t(body);
}

int32_t World::create_body(const BodyDef& def) {
    // Room in the awake set for every body slot first, so that waking never allocates.
    awake_bodies_.reserve(std::size_t(bodies.capacity()) + 1);
    const int32_t index = bodies.allocate();
    if (index == null_index) {
        return null_index;
    }
    Body& b = bodies[index];
    b.type = def.type;
    b.transform = {def.position, def.rotation};
    b.linear_velocity = def.type == BodyType::static_body ? Vec2{} : def.linear_velocity;
    b.angular_velocity = def.type == BodyType::static_body ? 0.0f : def.angular_velocity;
    b.linear_damping = def.linear_damping;
    b.angular_damping = def.angular_damping;
    b.gravity_scale = def.gravity_scale;
    b.fixed_rotation = def.fixed_rotation;
    b.enable_sleep = def.enable_sleep;
    b.is_bullet = def.is_bullet;
    b.user_data = def.user_data;
    update_mass(index);
    if (b.type != BodyType::static_body) {
        add_awake_body(index);
    }
    return index;
}

void World::destroy_body(int32_t body) {
    wake_body(body);  // the island it slept in loses a member
    // Shapes first: each takes its contacts (and their end events) with it.
    while (bodies[body].head_shape != null_index) {
        destroy_shape(bodies[body].head_shape);
    }
    if (bodies[body].awake_index != null_index) {
        remove_awake_body(body);
    }
    bodies.free(body);
}

void World::create_proxy(int32_t shape, bool query_now) {
    Shape& s = shapes[shape];
    const BodyType type = bodies[s.body].type;
    s.proxy_key = broad_phase_.create_proxy(fatten(s.aabb, type, Vec2{}), s.filter.category_bits, shape,
                                            proxy_kind_of(type), query_now);
}

int32_t World::create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry) {
    const int32_t index = shapes.allocate();
    if (index == null_index) {
        return null_index;
    }
    Shape& s = shapes[index];
    s.body = body;
    s.geometry = geometry;
    s.density = def.density;
    s.friction = def.friction;
    s.restitution = def.restitution;
    s.rolling_resistance = def.rolling_resistance;
    s.tangent_speed = def.tangent_speed;
    s.filter = def.filter;
    s.is_sensor = def.is_sensor;
    s.enable_contact_events = def.enable_contact_events;
    s.enable_sensor_events = def.enable_sensor_events;
    s.user_data = def.user_data;

    Body& b = bodies[body];
    s.next_in_body = b.head_shape;
    if (b.head_shape != null_index) {
        shapes[b.head_shape].prev_in_body = index;
    }
    b.head_shape = index;
    ++b.shape_count;
    s.aabb = compute_aabb(geometry, b.transform);
    // A new static shape may land on resting bodies: let it look for pairs too.
    create_proxy(index, true);
    update_mass(body);
    wake_body(body);
    return index;
}

void World::destroy_shape(int32_t shape) {
    wake_body(shapes[shape].body);
    destroy_contacts_of_shape(shape, false);
    const Shape& s = shapes[shape];
    broad_phase_.destroy_proxy(s.proxy_key);
    Body& b = bodies[s.body];
    if (s.prev_in_body != null_index) {
        shapes[s.prev_in_body].next_in_body = s.next_in_body;
    } else {
        b.head_shape = s.next_in_body;
    }
    if (s.next_in_body != null_index) {
        shapes[s.next_in_body].prev_in_body = s.prev_in_body;
    }
    --b.shape_count;
    const int32_t body = s.body;
    shapes.free(shape);
    update_mass(body);
}

// Mass, centre of mass and rotational inertia from the shapes. Static and kinematic
// bodies have infinite mass and inertia (inverses 0); a dynamic body with no mass gets
// 1 kg at its origin so that it still responds, rather than an infinite mass that would
// make it static in disguise. Inertia is summed about the body origin, then moved to the
// centre of mass by the parallel axis theorem.
void World::update_mass(int32_t body) {
    Body& b = bodies[body];
    b.mass = b.inv_mass = b.inertia = b.inv_inertia = 0.0f;
    b.max_extent = 0.0f;
    b.local_center = {};
    if (b.type == BodyType::dynamic) {
        float mass = 0.0f, inertia_about_origin = 0.0f;
        Vec2 moment;
        for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
            const MassData md = compute_mass(shapes[s].geometry, shapes[s].density);
            mass += md.mass;
            moment += md.mass * md.center;
            inertia_about_origin += md.rotational_inertia + md.mass * length_squared(md.center);
        }
        // Below FLT_MIN the inverse would overflow; such a body counts as massless.
        if (mass >= FLT_MIN) {
            b.mass = mass;
            b.local_center = (1.0f / mass) * moment;
            b.inertia = inertia_about_origin - mass * length_squared(b.local_center);
        } else {
            b.mass = 1.0f;
        }
        b.inv_mass = 1.0f / b.mass;
        if (b.fixed_rotation) {
            b.inertia = 0.0f;  // it never turns
            b.angular_velocity = 0.0f;
        } else if (b.inertia >= FLT_MIN) {
            b.inv_inertia = 1.0f / b.inertia;
        } else {
            b.inertia = 0.0f;  // no shapes yet, or a point mass: torque cannot turn it
        }
    }
    // How fast the body's farthest point moves when it spins: a spinning kinematic
    // drum is not resting.
    for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
        b.max_extent = max_of(b.max_extent, extent_from(shapes[s].geometry, b.local_center));
    }
    b.center = transform_point(b.transform, b.local_center);
}

// Tight boxes follow the body; a shape whose tight box left its fat box is re-inserted
// with a new fat box and queued for pair finding.
void World::sync_proxies(int32_t body) {
    const Body& b = bodies[body];
    const Vec2 displacement = last_time_step_ * b.linear_velocity;
    for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
        Shape& shape = shapes[s];
        shape.aabb = compute_aabb(shape.geometry, b.transform);
        if (!contains(broad_phase_.fat_aabb(shape.proxy_key), shape.aabb)) {
            broad_phase_.move_proxy(shape.proxy_key, fatten(shape.aabb, b.type, displacement));
        }
    }
}

// Before pairs are found: a body whose velocity changed since its box was fattened (a
// new body, a velocity or impulse set by the caller) must have a box that covers the
// step ahead, or a fast body could pass through a thin wall in the first step.
void World::cover_step_ahead(float time_step) {
    for (const int32_t body : awake_bodies_) {
        const Body& b = bodies[body];
        const Vec2 displacement = time_step * b.linear_velocity;
        for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
            const Shape& shape = shapes[s];
            const AABB ahead{shape.aabb.lower + displacement, shape.aabb.upper + displacement};
            if (!contains(broad_phase_.fat_aabb(shape.proxy_key), union_of(shape.aabb, ahead))) {
                broad_phase_.move_proxy(shape.proxy_key, fatten(shape.aabb, b.type, displacement));
            }
        }
    }
    broad_phase_.commit_moves();
}

// Moving a body wakes it and whatever touches it (a static floor moved away from under a
// sleeping pile, say).
void World::set_transform(int32_t body, const Transform& xf) {
    wake_body(body);
    visit_contacts(body, [this](int32_t, int32_t other) { wake_body(other); });
    Body& b = bodies[body];
    b.transform = xf;
    b.center = transform_point(xf, b.local_center);
    sync_proxies(body);
    broad_phase_.commit_moves();
}

// The proxy is re-created because the trees keep category bits for query masks; its
// new pairs are found at the next step (known pairs are skipped).
void World::set_filter(int32_t shape, const Filter& filter) {
    wake_body(shapes[shape].body);
    shapes[shape].filter = filter;
    destroy_contacts_of_shape(shape, true);
    broad_phase_.destroy_proxy(shapes[shape].proxy_key);
    create_proxy(shape, true);
}

// Box2D v3's pipeline: pairs from the last step's moves, one narrowphase, the soft step
// with its substeps, bounds, sleep. Events are gathered along the way.
void World::step(float time_step, int32_t substep_count) {
    Timer total, timer;
    profile_ = StepProfile{};
    events_.clear();
    events_.contact_end.swap(pending_contact_ends_);
    events_.sensor_end.swap(pending_sensor_ends_);
    if (time_step == 0.0f) {
        return;  // a paused world: nothing moves, nothing is tested (Box2D's rule)
    }
    last_time_step_ = time_step;
    for (const int32_t body : awake_bodies_) {
        bodies[body].step_start = bodies[body].transform;
    }
    begin_contact_step();
    profile_.events += timer.lap_ms();
    cover_step_ahead(time_step);
    find_new_contacts();
    profile_.pairs += timer.lap_ms();
    update_contacts();
    profile_.collide += timer.lap_ms();
    solve(time_step, substep_count);
    profile_.solve += timer.lap_ms();
    for (const int32_t body : awake_bodies_) {
        sync_proxies(body);
    }
    broad_phase_.commit_moves();
    profile_.update_bounds += timer.lap_ms();
    update_sleep_timers(time_step);
    find_islands_to_sleep();
    profile_.sleep += timer.lap_ms();
    update_touching();
    end_contact_step();
    report_body_moves();
    profile_.events += timer.lap_ms();
    put_marked_islands_to_sleep();
    profile_.sleep += timer.lap_ms();
    validate();
    profile_.step = total.lap_ms();
}

// Only awake bodies can have moved; a body falling asleep reports even if it did not.
void World::report_body_moves() {
    for (int32_t k = 0; k < int32_t(awake_bodies_.size()); ++k) {
        const int32_t i = awake_bodies_[k];
        Body& b = bodies[i];
        const Transform& start = b.step_start;
        const bool moved = !(b.transform.p == start.p && b.transform.q.c == start.q.c && b.transform.q.s == start.q.s);
        const bool falls_asleep = falls_asleep_[k] != 0;
        if (moved || falls_asleep) {
            events_.body_moves.push_back({b.transform, body_id(i), b.user_data, falls_asleep});
        }
        b.force = {};
        b.torque = 0.0f;
    }
}

WorldCounters World::counters() const {
    WorldCounters c;
    c.body_count = bodies.count();
    c.shape_count = shapes.count();
    c.pair_count = contacts.count();
    for (int32_t i = 0; i < contacts.capacity(); ++i) {
        if (contacts.is_live(i) && (contacts[i].flags & (contact_touching | contact_sensor)) == contact_touching) {
            ++c.contact_count;
        }
    }
    for (int32_t k = 0; k < int32_t(ProxyKind::count); ++k) {
        c.tree_heights[k] = broad_phase_.tree(ProxyKind(k)).height();
    }
    c.awake_body_count = int32_t(awake_bodies_.size());
    c.sleeping_island_count = sleeping_islands_.count();
    return c;
}

}  // namespace i2d
