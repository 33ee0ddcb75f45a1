// SPDX-License-Identifier: MIT
// World: creating, changing and destroying bodies and shapes (mass, proxies, waking).
#include "dynamics/world/world.hpp"

#include <cfloat>
#include <cmath>

#include "collision/geometry.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "math/math.hpp"

namespace i2d {

World::World(const WorldDef& def)
    : settings(def),
      tasks_(def.worker_count, def.tasks),
      joints_(joints, bodies),
      contacts_(settings, bodies, shapes, joints_, events_, tasks_),
      islands_(bodies),
      solver_(SolverLinks{bodies, shapes, joints, joints_, contacts_, islands_, broad_phase_, events_, tasks_},
              def.simd_path),
      continuous_(bodies, shapes, broad_phase_, events_, tasks_),
      profiling_(def.enable_profile) {}

int32_t World::create_body(const BodyDef& def) {
    const int32_t index = bodies.allocate();
    if (index == null_index) {
        return null_index;
    }
    Body& b = bodies[index];
    b.type = def.type;
    b.transform = {def.position, def.rotation};
    b.linear_velocity = def.type == BodyType::static_body ? Vec2{} : limited_linear_velocity(def.linear_velocity);
    b.angular_velocity = def.type == BodyType::static_body ? 0.0f : limited_angular_velocity(def.angular_velocity);
    b.linear_damping = def.linear_damping;
    b.angular_damping = def.angular_damping;
    b.gravity_scale = def.gravity_scale;
    b.fixed_rotation = def.fixed_rotation;
    b.enable_sleep = def.enable_sleep;
    b.is_bullet = def.is_bullet;
    b.user_data = def.user_data;
    update_mass(index);
    if (b.type != BodyType::static_body) {
        islands_.add_body(index);
        mark_for_cover(index);
    }
    return index;
}

void World::destroy_body(int32_t body) {
    wake_body(body);  // the island it slept in loses a member
    while (bodies[body].head_joint_key != null_index) {
        destroy_joint(bodies[body].head_joint_key >> 1);
    }
    // Shapes first: each takes its contacts (and their end events) with it; a chain's
    // segments go with their chain.
    while (bodies[body].head_shape != null_index) {
        const int32_t shape = bodies[body].head_shape;
        if (shapes[shape].chain != null_index) {
            destroy_chain(shapes[shape].chain);
        } else {
            destroy_shape(shape);
        }
    }
    if (bodies[body].type != BodyType::static_body) {
        islands_.remove_body(body);
        follow_woken_bodies();
    }
    bodies.free(body);
}

void World::set_type(int32_t body, BodyType type) {
    if (bodies[body].type == type) {
        bodies[body].quarantined = false;  // a quarantined body kept static on purpose
        return;
    }
    // What touched it loses a support or meets a new obstacle.
    wake_body(body);
    contacts_.visit_contacts(body, [this](int32_t, int32_t other) { wake_body(other); });
    for (int32_t s = bodies[body].head_shape; s != null_index; s = shapes[s].next_in_body) {
        destroy_contacts_of_shape(s, false);
        broad_phase_.destroy_proxy(shapes[s].proxy_key);
    }
    unlink_joints(body);
    if (bodies[body].type != BodyType::static_body) {
        islands_.remove_body(body);
        follow_woken_bodies();
    }
    Body& b = bodies[body];
    b.type = type;
    b.quarantined = false;
    b.sleep_time = 0.0f;
    if (type == BodyType::static_body) {
        b.linear_velocity = {};
        b.angular_velocity = 0.0f;
    }
    if (type != BodyType::dynamic) {
        b.force = {};
        b.torque = 0.0f;
    }
    for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
        create_proxy(s, true);
    }
    update_mass(body);
    if (type != BodyType::static_body) {
        islands_.add_body(body);
        mark_for_cover(body);
    }
    link_joints(body);
}

void World::create_proxy(int32_t shape, bool query_now) {
    Shape& s = shapes[shape];
    const Body& body = bodies[s.body];
    const ProxyBoxes boxes = fatten(s, body, Vec2{});
    s.fat_aabb = boxes.fat;
    s.ahead_aabb = boxes.ahead;
    s.proxy_key = broad_phase_.create_proxy(s.fat_aabb, s.ahead_aabb, s.filter.category_bits, shape,
                                            proxy_kind_of(body.type), query_now);
    mark_for_cover(s.body);  // the new box is not stretched along the body's motion
}

// Links a new shape into its body and the broadphase; the caller updates the mass.
int32_t World::attach_shape(int32_t body, const ShapeDef& def, const Geometry& geometry) {
    const int32_t index = shapes.allocate();
    if (index == null_index) {
        return null_index;
    }
    Shape& s = shapes[index];
    s.body = body;
    s.geometry = geometry;
    s.aabb_margin = aabb_margin_of(geometry);
    s.density = def.density;
    s.friction = def.friction;
    s.restitution = def.restitution;
    s.rolling_resistance = def.rolling_resistance;
    s.tangent_speed = def.tangent_speed;
    s.filter = def.filter;
    s.is_sensor = def.is_sensor;
    s.enable_contact_events = def.enable_contact_events;
    s.enable_sensor_events = def.enable_sensor_events;
    s.enable_hit_events = def.enable_hit_events;
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
    return index;
}

int32_t World::create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry) {
    const int32_t index = attach_shape(body, def, geometry);
    if (index != null_index) {
        update_mass(body);
        wake_body(body);
    }
    return index;
}

void World::destroy_shape(int32_t shape) {
    const int32_t body = shapes[shape].body;
    detach_shape(shape);
    update_mass(body);
}

// Unlinks the shape from its contacts, the broadphase and its body; the caller updates
// the mass.
void World::detach_shape(int32_t shape) {
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
    shapes.free(shape);
}

// Every segment is attached first and the mass (extents) updated once: a chain of n
// segments costs O(n), not O(n^2).
int32_t World::create_chain(int32_t body, const ChainDef& def) {
    const int32_t index = chains.allocate();
    if (index == null_index) {
        return null_index;
    }
    Chain& chain = chains[index];
    chain.body = body;
    chain.is_loop = def.is_loop;
    chain.user_data = def.user_data;
    const int32_t segments = chain_segment_count(def.count, def.is_loop);
    chain.shapes.reserve(std::size_t(segments));
    for (int32_t i = 0; i < segments; ++i) {
        const SurfaceMaterial material = def.material_count == 0   ? SurfaceMaterial{}
                                         : def.material_count == 1 ? def.materials[0]
                                                                   : def.materials[i];
        ShapeDef sd;
        sd.density = 0.0f;
        sd.friction = material.friction;
        sd.restitution = material.restitution;
        sd.rolling_resistance = material.rolling_resistance;
        sd.tangent_speed = material.tangent_speed;
        sd.filter = def.filter;
        sd.enable_sensor_events = def.enable_sensor_events;
        sd.user_data = def.user_data;
        Geometry g;
        g.type = ShapeType::chain_segment;
        g.chain_segment = chain_segment_geometry(def, i);
        const int32_t shape = attach_shape(body, sd, g);
        if (shape == null_index) {
            destroy_chain(index);  // the shape pool is full: take back what was made
            return null_index;
        }
        shapes[shape].chain = index;
        chains[index].shapes.push_back(shape);
    }
    update_mass(body);
    wake_body(body);
    return index;
}

void World::destroy_chain(int32_t chain) {
    const int32_t body = chains[chain].body;
    for (const int32_t shape : chains[chain].shapes) {
        detach_shape(shape);
    }
    chains[chain].shapes.clear();
    chains.free(chain);
    update_mass(body);
}

// Mass, centre of mass and rotational inertia from the shapes. Static and kinematic
// bodies have infinite mass and inertia (inverses 0); a dynamic body with no mass gets
// 1 kg at its origin so that it still responds, rather than an infinite mass that would
// make it static in disguise. Inertia is summed about the body origin, then moved to the
// centre of mass by the parallel axis theorem.
void World::update_mass(int32_t body) {
    joints_.touch();  // a body that can no longer turn gives its joints' trees no angle rows
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
    b.min_extent = b.head_shape == null_index ? 0.0f : FLT_MAX;
    for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
        b.max_extent = max_of(b.max_extent, extent_from(shapes[s].geometry, b.local_center));
        if (!shapes[s].is_sensor) {
            b.min_extent = min_of(b.min_extent, max_of(inner_radius(shapes[s].geometry), linear_slop));
        }
    }
    b.min_extent = b.min_extent == FLT_MAX ? 0.0f : b.min_extent;
    b.center = transform_point(b.transform, b.local_center);
    contacts_.forget_manifolds(body);
}

// Before pairs are found, every moving shape's fat box must cover the step ahead, or a
// fast body could pass through a thin wall before its pair exists. The last step's
// bounds update fattened the boxes for its own time step and final velocities; only
// bodies the caller changed since (created, moved, given a velocity or an impulse)
// need checking again, unless the time step changed.
void World::cover_step_ahead(float time_step) {
    const bool same_step = time_step == last_time_step_;
    last_time_step_ = time_step;
    const auto cover = [&](int32_t body) {
        Body& b = bodies[body];
        b.needs_cover = false;
        update_shape_bounds(b, shapes, broad_phase_, time_step * b.linear_velocity, true, turn_reach(b, time_step));
    };
    if (same_step) {
        for (const int32_t body : to_cover_) {
            if (bodies.is_live(body) && bodies[body].needs_cover && is_awake(body)) {
                cover(body);
            }
        }
    } else {
        for (const int32_t body : islands_.awake_bodies()) {
            cover(body);
        }
    }
    to_cover_.clear();
    broad_phase_.commit_moves_in_place();
}

void World::mark_for_cover(int32_t body) {
    Body& b = bodies[body];
    if (b.type != BodyType::static_body && !b.needs_cover) {
        b.needs_cover = true;
        to_cover_.push_back(body);
    }
}

// Moving a body wakes it and whatever touches it (a static floor moved away from under a
// sleeping pile, say).
void World::set_transform(int32_t body, const Transform& xf) { set_transforms(&body, &xf, 1); }

// Waking was most of what a bulk write cost (each contact a cache miss, and each body it
// leads to), and it mostly changes nothing: while no island sleeps, waking a body only
// restarts its rest timer, and only a world that sleeps reads the timers. So the contacts
// are walked only when an island may wake or the timers count; either way every body
// ends as wake_body would leave it.
void World::set_transforms(const int32_t* list, const Transform* transforms, int32_t count) {
    const bool may_wake = islands_.sleeping_island_count() > 0;
    const bool timers_count = settings.enable_sleep;
    for (int32_t i = 0; i < count; ++i) {
        const int32_t body = list[i];
        if (may_wake) {
            wake_body(body);
            contacts_.visit_contacts(body, [this](int32_t, int32_t other) { wake_body(other); });
        } else {
            bodies[body].sleep_time = 0.0f;
            if (timers_count) {
                contacts_.visit_contacts(body, [this](int32_t, int32_t other) { bodies[other].sleep_time = 0.0f; });
            }
        }
        Body& b = bodies[body];
        b.transform = transforms[i];
        b.center = transform_point(transforms[i], b.local_center);
        // Proxies that must move are re-inserted before the next body moves, as when
        // set_transform is called for each body in turn: the trees, and so the pairs
        // and every later step, come out the same. (One commit at the end, in storage
        // order, was about 12 % faster when every body was teleported, but its trees
        // and later steps differed from the per-body calls'.)
        if (refit_shape_bounds(b, shapes, Vec2{}, false)) {
            move_enlarged_proxies(b, shapes, broad_phase_);
            broad_phase_.commit_moves();
        }
        mark_for_cover(body);
    }
}

// Velocities enter the world already within its limits: the solver's first use of a
// velocity (the impact speed it tracks for restitution) squares it before the substep
// clamp, and a finite 1e20 m/s squared is infinite. The length is taken in double so
// that no finite float input overflows on the way; the direction is kept.
Vec2 World::limited_linear_velocity(Vec2 v) const {
    const double x = v.x, y = v.y;
    const double speed = std::sqrt(x * x + y * y);
    const double max_speed = settings.maximum_linear_speed;
    if (speed <= max_speed) {
        return v;
    }
    const double scale = max_speed / speed;
    return Vec2{static_cast<float>(x * scale), static_cast<float>(y * scale)};
}

float World::limited_angular_velocity(float w) const {
    return w > max_angular_speed ? max_angular_speed : (w < -max_angular_speed ? -max_angular_speed : w);
}

void World::set_linear_velocity(int32_t body, Vec2 v) {
    Body& b = bodies[body];
    if (b.type == BodyType::static_body) {
        return;
    }
    if (v.x != 0.0f || v.y != 0.0f) {
        wake_body(body);
    }
    b.linear_velocity = limited_linear_velocity(v);
    mark_for_cover(body);
}

void World::set_angular_velocity(int32_t body, float w) {
    Body& b = bodies[body];
    const bool turns = b.type == BodyType::kinematic || (b.type == BodyType::dynamic && b.inv_inertia != 0.0f);
    if (!turns) {
        return;
    }
    if (w != 0.0f) {
        wake_body(body);
    }
    b.angular_velocity = limited_angular_velocity(w);
    if (b.type == BodyType::kinematic) {
        mark_for_cover(body);  // its boxes must reach as far as it now turns
    }
}

// Wakes the body if asked; a body left asleep ignores what it is given.
bool World::prepare_to_receive(int32_t body, bool wake) {
    if (bodies[body].type != BodyType::dynamic) {
        return false;
    }
    if (wake) {
        wake_body(body);
    }
    return is_awake(body);
}

bool World::accumulate(int32_t body, Vec2 force, float torque, bool wake) {
    Body& b = bodies[body];
    const Vec2 total_force = b.force + force;
    const float total_torque = b.torque + torque;
    if (!is_finite(total_force) || !std::isfinite(total_torque)) {
        return false;
    }
    if (prepare_to_receive(body, wake)) {
        b.force = total_force;
        b.torque = total_torque;
    }
    return true;
}

bool World::change_velocity(int32_t body, Vec2 dv, float dw, bool wake) {
    Body& b = bodies[body];
    const Vec2 v = b.linear_velocity + dv;
    const float w = b.angular_velocity + dw;
    if (!is_finite(v) || !std::isfinite(w)) {
        return false;
    }
    if (prepare_to_receive(body, wake)) {
        b.linear_velocity = limited_linear_velocity(v);
        b.angular_velocity = limited_angular_velocity(w);
        mark_for_cover(body);
    }
    return true;
}

bool World::apply_force(int32_t body, Vec2 force, Vec2 point, bool wake) {
    return accumulate(body, force, cross(point - bodies[body].center, force), wake);
}

bool World::apply_force_to_center(int32_t body, Vec2 force, bool wake) { return accumulate(body, force, 0.0f, wake); }

bool World::apply_torque(int32_t body, float torque, bool wake) { return accumulate(body, Vec2{}, torque, wake); }

bool World::apply_linear_impulse(int32_t body, Vec2 impulse, Vec2 point, bool wake) {
    const Body& b = bodies[body];
    return change_velocity(body, b.inv_mass * impulse, b.inv_inertia * cross(point - b.center, impulse), wake);
}

bool World::apply_angular_impulse(int32_t body, float impulse, bool wake) {
    return change_velocity(body, Vec2{}, bodies[body].inv_inertia * impulse, wake);
}

void World::wake_body(int32_t body) {
    islands_.wake_body(body);
    follow_woken_bodies();
}

void World::wake_all() {
    islands_.wake_all();
    follow_woken_bodies();
}

void World::sleep_body(int32_t body) {
    islands_.sleep_island_of(body, [this](int32_t b, FunctionRef<void(int32_t)> follow) { visit_island_links(b, follow); },
                             [this](int32_t b) { contacts_.body_slept(b); });
}

// The contacts of bodies whose island woke join the awake contact list, in the order the
// bodies joined the awake list.
void World::follow_woken_bodies() {
    for (const int32_t body : islands_.woken_bodies()) {
        contacts_.body_woke(body);
    }
    islands_.clear_woken();
}

void World::apply_link_changes() {
    islands_.apply(contacts_.link_changes());
    contacts_.clear_link_changes();
}

void World::destroy_contacts_of_shape(int32_t shape, bool only_filtered_out) {
    contacts_.destroy_contacts_of_shape(shape, only_filtered_out, [this](int32_t body) { wake_body(body); });
    apply_link_changes();
}

void World::destroy_contacts_between(int32_t body_a, int32_t body_b) {
    contacts_.destroy_contacts_between(body_a, body_b, [this](int32_t body) { wake_body(body); });
    apply_link_changes();
}

// What links a body into its island: solid contacts with points, and joints.
void World::visit_island_links(int32_t body, FunctionRef<void(int32_t other)> follow) const {
    contacts_.visit_links(body, follow);
    joints_.visit_links(body, follow);
}

// Resting bodies must feel the new gravity.
void World::set_gravity(Vec2 gravity) {
    settings.gravity = gravity;
    wake_all();
}

void World::set_friction(int32_t shape, float friction) {
    shapes[shape].friction = friction;
    contacts_.mix_materials_of_shape(shape);
}

void World::set_restitution(int32_t shape, float restitution) {
    shapes[shape].restitution = restitution;
    contacts_.mix_materials_of_shape(shape);
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

}  // namespace i2d
