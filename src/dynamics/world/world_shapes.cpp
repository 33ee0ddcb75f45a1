// SPDX-License-Identifier: MIT
// World: creating and destroying shapes and chains, their proxies, materials and filters.
#include "collision/geometry.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

void World::create_proxy(int32_t shape, bool query_now) {
    Shape& s = shapes_[shape];
    const Body& body = bodies_[s.body];
    const ProxyBoxes boxes = fatten(s, body, Vec2{});
    s.fat_aabb = boxes.fat;
    s.ahead_aabb = boxes.ahead;
    s.proxy_key = stages_->broad_phase.create_proxy(s.fat_aabb, s.ahead_aabb, s.filter.category_bits, shape,
                                            proxy_kind_of(body.type), query_now);
    mark_for_cover(s.body);  // the new box is not stretched along the body's motion
}

// Links a new shape into its body and the broadphase; the caller updates the mass.
int32_t World::attach_shape(int32_t body, const ShapeDef& def, const Geometry& geometry) {
    const int32_t index = shapes_.allocate();
    if (index == null_index) {
        return null_index;
    }
    Shape& s = shapes_[index];
    s.body = body;
    s.geometry = geometry;
    s.aabb_margin = aabb_margin_of(geometry, tolerances().max_aabb_margin);
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
    s.enable_custom_filtering = def.enable_custom_filtering;
    s.enable_pre_solve_events = def.enable_pre_solve_events;
    s.user_data = def.user_data;

    Body& b = bodies_[body];
    s.next_in_body = b.head_shape;
    if (b.head_shape != null_index) {
        shapes_[b.head_shape].prev_in_body = index;
    }
    b.head_shape = index;
    ++b.shape_count;
    s.aabb = compute_aabb(geometry, b.transform);
    // A new static shape may land on resting bodies: let it look for pairs too. A disabled
    // body's shape gets its proxy when the body is enabled.
    if (b.enabled) {
        create_proxy(index, true);
    }
    return index;
}

int32_t World::create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry) {
    RecordScope record(recorder_.get(), RecordedOp::create_shape);
    record.write(body, def, geometry);
    ++structure_version_;
    const int32_t index = attach_shape(body, def, geometry);
    if (index != null_index) {
        update_mass(body);
        wake_body(body);
    }
    return index;
}

void World::destroy_shape(int32_t shape) {
    RecordScope record(recorder_.get(), RecordedOp::destroy_shape);
    record.write(shape);
    ++structure_version_;
    const int32_t body = shapes_[shape].body;
    detach_shape(shape);
    update_mass(body);
}

// Unlinks the shape from its contacts, the broadphase and its body; the caller updates
// the mass.
void World::detach_shape(int32_t shape) {
    wake_body(shapes_[shape].body);
    destroy_contacts_of_shape(shape, false);
    const Shape& s = shapes_[shape];
    Body& b = bodies_[s.body];
    if (b.enabled) {
        stages_->broad_phase.destroy_proxy(s.proxy_key);
    }
    if (s.prev_in_body != null_index) {
        shapes_[s.prev_in_body].next_in_body = s.next_in_body;
    } else {
        b.head_shape = s.next_in_body;
    }
    if (s.next_in_body != null_index) {
        shapes_[s.next_in_body].prev_in_body = s.prev_in_body;
    }
    --b.shape_count;
    shapes_.free(shape);
}

// Every segment is attached first and the mass (extents) updated once: a chain of n
// segments costs O(n), not O(n^2).
int32_t World::create_chain(int32_t body, const ChainDef& def) {
    RecordScope record(recorder_.get(), RecordedOp::create_chain);
    record.write(body, def);
    ++structure_version_;
    const int32_t index = chains_.allocate();
    if (index == null_index) {
        return null_index;
    }
    Chain& chain = chains_[index];
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
        shapes_[shape].chain = index;
        chains_[index].shapes.push_back(shape);
    }
    update_mass(body);
    wake_body(body);
    return index;
}

void World::destroy_chain(int32_t chain) {
    RecordScope record(recorder_.get(), RecordedOp::destroy_chain);
    record.write(chain);
    ++structure_version_;
    const int32_t body = chains_[chain].body;
    for (const int32_t shape : chains_[chain].shapes) {
        detach_shape(shape);
    }
    chains_[chain].shapes.clear();
    chains_.free(chain);
    update_mass(body);
}

void World::set_friction(int32_t shape, float friction) {
    RecordScope record(recorder_.get(), RecordedOp::set_friction);
    record.write(shape, friction);
    ++structure_version_;
    shapes_[shape].friction = friction;
    stages_->contacts.refresh_contacts_of_shape(shape);
}

void World::set_restitution(int32_t shape, float restitution) {
    RecordScope record(recorder_.get(), RecordedOp::set_restitution);
    record.write(shape, restitution);
    ++structure_version_;
    shapes_[shape].restitution = restitution;
    stages_->contacts.refresh_contacts_of_shape(shape);
}

// The proxy is re-created because the trees keep category bits for query masks; its
// new pairs are found at the next step (known pairs are skipped). A disabled body's
// shape has none: it gets one, with the new bits, when the body is enabled.
void World::set_filter(int32_t shape, const Filter& filter) {
    RecordScope record(recorder_.get(), RecordedOp::set_filter);
    record.write(shape, filter);
    ++structure_version_;
    wake_body(shapes_[shape].body);
    shapes_[shape].filter = filter;
    destroy_contacts_of_shape(shape, true);
    if (bodies_[shapes_[shape].body].enabled) {
        stages_->broad_phase.destroy_proxy(shapes_[shape].proxy_key);
        create_proxy(shape, true);
    }
}

void World::set_shape_user_data(int32_t shape, void* user_data) {
    RecordScope record(recorder_.get(), RecordedOp::set_shape_user_data);
    record.write(shape, user_data);
    shapes_[shape].user_data = user_data;
}

}  // namespace i2d
