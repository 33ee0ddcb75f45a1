// SPDX-License-Identifier: MIT
// World: a shape's settings changed after creation: its geometry, density, material and
// event flags.
//
// Each is a structural change (rollback states saved before are refused) and is recorded.
// A geometry change keeps the shape's contacts, whose manifolds are made afresh at the
// next step from the new outline: a shape that still touches what it touched reports no
// end and begin in between.
#include "collision/geometry.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

// The proxy is made again: its box (and the tree it sits in) must fit the new outline,
// and its new pairs are found at once (known pairs are skipped). A disabled body's shape
// has none until the body is enabled.
void World::set_geometry(int32_t shape, const Geometry& geometry) {
    RecordScope record(recorder_.get(), RecordedOp::set_shape_geometry);
    record.write(shape, geometry);
    ++structure_version_;
    const int32_t body = shapes_[shape].body;
    wake_body(body);
    Shape& s = shapes_[shape];
    s.geometry = geometry;
    s.aabb_margin = aabb_margin_of(geometry, tolerances().max_aabb_margin);
    s.aabb = compute_aabb(geometry, bodies_[body].transform);
    if (bodies_[body].enabled) {
        stages_->broad_phase.destroy_proxy(s.proxy_key);
        create_proxy(shape, true);
    }
    update_mass(body);  // also forgets the body's manifolds, anchored on the old outline
    stages_->contacts.refresh_contacts_of_shape(shape);  // rolling resistance reads the radius
}

void World::set_density(int32_t shape, float density, bool update_body_mass) {
    RecordScope record(recorder_.get(), RecordedOp::set_shape_density);
    record.write(shape, density, update_body_mass);
    ++structure_version_;
    shapes_[shape].density = density;
    if (update_body_mass) {
        const int32_t body = shapes_[shape].body;
        update_mass(body);
        wake_body(body);
    }
}

void World::set_material(int32_t shape, const SurfaceMaterial& material) {
    RecordScope record(recorder_.get(), RecordedOp::set_shape_material);
    record.write(shape, material);
    ++structure_version_;
    Shape& s = shapes_[shape];
    s.friction = material.friction;
    s.restitution = material.restitution;
    s.rolling_resistance = material.rolling_resistance;
    s.tangent_speed = material.tangent_speed;
    stages_->contacts.refresh_contacts_of_shape(shape);
    wake_body(s.body);  // a conveyor started or a surface turned to ice moves what rests on it
}

// Contact and sensor event flags apply to contacts and visits that begin afterwards (so
// every begin reported keeps its end); hit and pre-solve events to every contact from the
// next step.
void World::set_shape_flag(int32_t shape, ShapeFlag flag, bool value) {
    RecordScope record(recorder_.get(), RecordedOp::set_shape_flag);
    record.write(shape, flag, value);
    ++structure_version_;
    Shape& s = shapes_[shape];
    switch (flag) {
        case ShapeFlag::contact_events: s.enable_contact_events = value; break;
        case ShapeFlag::sensor_events: s.enable_sensor_events = value; break;
        case ShapeFlag::hit_events:
            s.enable_hit_events = value;
            stages_->contacts.refresh_contacts_of_shape(shape);
            break;
        case ShapeFlag::pre_solve_events:
            s.enable_pre_solve_events = value;
            stages_->contacts.refresh_contacts_of_shape(shape);
            break;
        case ShapeFlag::count: break;
    }
}

void World::set_custom_filter(const ContactHooks::CustomFilter& filter) { stages_->hooks.custom_filter = filter; }

void World::set_pre_solve(const ContactHooks::PreSolve& pre_solve) { stages_->hooks.pre_solve = pre_solve; }

}  // namespace i2d
