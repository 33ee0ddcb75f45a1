// SPDX-License-Identifier: MIT
// World lifecycle (bodies, shapes, mass) and the step.
#include "dynamics/world.hpp"

#include <cfloat>
#include <cmath>

#include "collision/geometry.hpp"
#include "collision/manifold.hpp"

namespace i2d {

World::World(const WorldDef& def) : settings(def) {}

int32_t World::create_body(const BodyDef& def) {
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
    validate();
    return index;
}

void World::destroy_body(int32_t body) {
    while (bodies[body].head_shape != null_index) {
        destroy_shape(bodies[body].head_shape);
    }
    bodies.free(body);
    validate();
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
    s.filter = def.filter;
    s.is_sensor = def.is_sensor;
    s.enable_contact_events = def.enable_contact_events;
    s.user_data = def.user_data;

    Body& b = bodies[body];
    s.next_in_body = b.head_shape;
    if (b.head_shape != null_index) {
        shapes[b.head_shape].prev_in_body = index;
    }
    b.head_shape = index;
    ++b.shape_count;
    s.aabb = compute_aabb(geometry, b.transform);
    update_mass(body);
    validate();
    return index;
}

void World::destroy_shape(int32_t shape) {
    const Shape& s = shapes[shape];
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

// Mass and centre of mass from the shapes. Static and kinematic bodies have infinite
// mass (inverse 0); a dynamic body with no mass gets 1 kg at its origin so that it
// still responds, rather than an infinite mass that would make it static in disguise.
void World::update_mass(int32_t body) {
    Body& b = bodies[body];
    b.mass = 0.0f;
    b.inv_mass = 0.0f;
    b.local_center = {};
    if (b.type == BodyType::dynamic) {
        float mass = 0.0f;
        Vec2 moment;
        for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
            const MassData md = compute_mass(shapes[s].geometry, shapes[s].density);
            mass += md.mass;
            moment += md.mass * md.center;
        }
        // Below FLT_MIN the inverse would overflow; such a body counts as massless.
        if (mass >= FLT_MIN) {
            b.mass = mass;
            b.local_center = (1.0f / mass) * moment;
        } else {
            b.mass = 1.0f;
        }
        b.inv_mass = 1.0f / b.mass;
    }
    b.center = transform_point(b.transform, b.local_center);
}

void World::update_shape_bounds(int32_t body) {
    const Body& b = bodies[body];
    for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
        shapes[s].aabb = compute_aabb(shapes[s].geometry, b.transform);
    }
}

void World::set_transform(int32_t body, const Transform& xf) {
    Body& b = bodies[body];
    b.transform = xf;
    b.center = transform_point(xf, b.local_center);
    update_shape_bounds(body);
}

void World::step(float time_step, int32_t substep_count) {
    if (time_step > 0.0f) {
        const float h = time_step / static_cast<float>(substep_count);
        for (int32_t i = 0; i < substep_count; ++i) {
            substep(h);
        }
    }
    for (int32_t i = 0; i < bodies.capacity(); ++i) {
        if (bodies.is_live(i)) {
            bodies[i].force = {};
            bodies[i].torque = 0.0f;
        }
    }
    validate();
}

// One substep of the seed's pipeline: forces, contacts, impulses, positions, correction.
void World::substep(float h) {
    integrate_velocities(h);
    find_contacts();
    const SolverSettings solver{settings.restitution_threshold, settings.contact_slop,
                                settings.contact_correction_percent, settings.velocity_iterations};
    prepare_contacts(contacts_, bodies, solver);
    warm_start_contacts(contacts_, bodies);
    solve_contact_velocities(contacts_, bodies, solver);
    integrate_positions(h);
    correct_contact_positions(contacts_, bodies, solver);
    for (int32_t i = 0; i < bodies.capacity(); ++i) {
        if (bodies.is_live(i) && bodies[i].type != BodyType::static_body) {
            update_shape_bounds(i);
        }
    }
}

void World::integrate_velocities(float h) {
    const float max_speed_sq = settings.maximum_linear_speed * settings.maximum_linear_speed;
    for (int32_t i = 0; i < bodies.capacity(); ++i) {
        if (!bodies.is_live(i) || bodies[i].type != BodyType::dynamic) {
            continue;
        }
        Body& b = bodies[i];
        Vec2 v = b.linear_velocity + h * (b.gravity_scale * settings.gravity + b.inv_mass * b.force);
        // Implicit damping: stable for any damping and step, v -> v / (1 + h c).
        v = (1.0f / (1.0f + h * b.linear_damping)) * v;
        const float speed_sq = length_squared(v);
        if (speed_sq > max_speed_sq) {
            v = (settings.maximum_linear_speed / std::sqrt(speed_sq)) * v;
        }
        b.linear_velocity = v;
    }
}

void World::integrate_positions(float h) {
    const float max_speed_sq = settings.maximum_linear_speed * settings.maximum_linear_speed;
    for (int32_t i = 0; i < bodies.capacity(); ++i) {
        if (!bodies.is_live(i) || bodies[i].type == BodyType::static_body) {
            continue;
        }
        Body& b = bodies[i];
        // Kinematic bodies skip integrate_velocities, so clamp here too.
        const float speed_sq = length_squared(b.linear_velocity);
        if (speed_sq > max_speed_sq) {
            b.linear_velocity = (settings.maximum_linear_speed / std::sqrt(speed_sq)) * b.linear_velocity;
        }
        const Vec2 delta = h * b.linear_velocity;
        b.center += delta;
        b.transform.p += delta;
    }
}

// Broadphase over every shape's bounds, then a manifold per candidate pair. Pairs of
// shapes on one body, of two bodies that cannot move each other, of sensors and of
// filtered shapes never reach the narrowphase.
void World::find_contacts() {
    proxy_bounds_.clear();
    proxy_shapes_.clear();
    for (int32_t i = 0; i < shapes.capacity(); ++i) {
        if (shapes.is_live(i) && !shapes[i].is_sensor) {
            proxy_bounds_.push_back(shapes[i].aabb);
            proxy_shapes_.push_back(i);
        }
    }
    pairs_.clear();
    broadphase_.find_pairs(
        proxy_bounds_,
        [this](int32_t pa, int32_t pb) {
            const Shape& a = shapes[proxy_shapes_[pa]];
            const Shape& b = shapes[proxy_shapes_[pb]];
            if (a.body == b.body) {
                return false;
            }
            const BodyType ta = bodies[a.body].type, tb = bodies[b.body].type;
            if (ta != BodyType::dynamic && tb != BodyType::dynamic) {
                return false;
            }
            return should_collide(a.filter, b.filter);
        },
        pairs_);
    last_pair_count_ = static_cast<int32_t>(pairs_.size());

    contacts_.swap(previous_contacts_);
    contacts_.clear();
    for (const BroadphasePair& pair : pairs_) {
        const int32_t shape_a = proxy_shapes_[pair.a], shape_b = proxy_shapes_[pair.b];
        const Shape& a = shapes[shape_a];
        const Shape& b = shapes[shape_b];
        const Manifold m = collide_shapes(a.geometry, bodies[a.body].transform, b.geometry, bodies[b.body].transform);
        if (m.point_count == 0) {
            continue;
        }
        ContactConstraint c;
        c.key_a = (uint64_t(shapes.generation(shape_a)) << 32) | uint32_t(shape_a);
        c.key_b = (uint64_t(shapes.generation(shape_b)) << 32) | uint32_t(shape_b);
        c.body_a = a.body;
        c.body_b = b.body;
        c.normal = m.normal;
        c.friction = std::sqrt(a.friction * b.friction);
        c.restitution = std::fmin(a.restitution, b.restitution);
        c.point_count = 0;
        for (int32_t i = 0; i < m.point_count; ++i) {
            // Speculative points (penetration < 0) are dropped until the soft-step
            // solver issue lands: it handles them; this solver would pull them together.
            if (m.points[i].penetration < 0.0f) {
                continue;
            }
            c.points[c.point_count].id = m.points[i].id;
            c.points[c.point_count].penetration = m.points[i].penetration;
            ++c.point_count;
        }
        if (c.point_count == 0) {
            continue;
        }
        contacts_.push_back(c);
    }
    sort_contacts(contacts_);
    carry_impulses(contacts_, previous_contacts_);
}

WorldCounters World::counters() const {
    WorldCounters c;
    c.body_count = bodies.count();
    c.shape_count = shapes.count();
    c.contact_count = static_cast<int32_t>(contacts_.size());
    c.pair_count = last_pair_count_;
    return c;
}

}  // namespace i2d
