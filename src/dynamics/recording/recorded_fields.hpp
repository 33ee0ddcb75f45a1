// SPDX-License-Identifier: MIT
// The arguments a recording stores for each recorded call, in the same field-list style
// as a snapshot's (snapshot/world_fields.hpp, whose geometry, filter and joint lists it
// shares), for writing while recording and reading while replaying.
#pragma once

#include <vector>

#include "dynamics/body/body.hpp"
#include "dynamics/body/chain.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/snapshot/world_fields.hpp"

namespace i2d {

template <class Io, class D>
void body_def_fields(Io& io, D& d) {
    io(d.type);
    io(d.position);
    io(d.rotation);
    io(d.linear_velocity);
    io(d.angular_velocity);
    io(d.linear_damping);
    io(d.angular_damping);
    io(d.gravity_scale);
    io(d.fixed_rotation);
    io(d.enable_sleep);
    io(d.is_bullet);
    io(d.user_data);
}

template <class Io, class D>
void shape_def_fields(Io& io, D& d) {
    io(d.density);
    io(d.friction);
    io(d.restitution);
    io(d.rolling_resistance);
    io(d.tangent_speed);
    io(d.is_sensor);
    io(d.enable_contact_events);
    io(d.enable_sensor_events);
    io(d.enable_hit_events);
    if (io.has_version(2)) {
        io(d.enable_custom_filtering);
        io(d.enable_pre_solve_events);
    }
    filter_fields(io, d.filter);
    io(d.user_data);
}

template <class Io, class M>
void surface_material_fields(Io& io, M& m) {
    io(m.friction);
    io(m.restitution);
    io(m.rolling_resistance);
    io(m.tangent_speed);
}

/// A chain def with the points and materials it points at, as a replay reads it.
struct RecordedChain {
    ChainDef def;
    std::vector<Vec2> points;
    std::vector<SurfaceMaterial> materials;
};

inline void save_chain_def(SaveIo& io, const ChainDef& d) {
    io.count(d.count);
    for (int32_t i = 0; i < d.count; ++i) {
        io(d.points[i]);
    }
    io.count(d.material_count);
    for (int32_t i = 0; i < d.material_count; ++i) {
        surface_material_fields(io, d.materials[i]);
    }
    io(d.is_loop);
    filter_fields(io, d.filter);
    io(d.enable_sensor_events);
    io(d.user_data);
}

/// `limit`: the most points (and materials) a chain may have.
inline void load_chain_def(LoadIo& io, RecordedChain& chain, int32_t limit) {
    chain.points.resize(std::size_t(io.count(8, limit, "a chain has too many points")));
    for (Vec2& p : chain.points) {
        io(p);
    }
    chain.materials.resize(std::size_t(io.count(16, limit, "a chain has too many materials")));
    for (SurfaceMaterial& m : chain.materials) {
        surface_material_fields(io, m);
    }
    ChainDef& d = chain.def;
    d.points = chain.points.data();
    d.count = int32_t(chain.points.size());
    d.materials = chain.materials.data();
    d.material_count = int32_t(chain.materials.size());
    io(d.is_loop);
    filter_fields(io, d.filter);
    io(d.enable_sensor_events);
    io(d.user_data);
}

// What RecordScope::write does with each kind of argument.
template <class T>
void save_recorded(SaveIo& io, const T& value) {
    io(value);
}
inline void save_recorded(SaveIo& io, const BodyDef& d) { body_def_fields(io, d); }
inline void save_recorded(SaveIo& io, const ShapeDef& d) { shape_def_fields(io, d); }
inline void save_recorded(SaveIo& io, const Geometry& g) { geometry_fields(io, g); }
inline void save_recorded(SaveIo& io, const Filter& f) { filter_fields(io, f); }
inline void save_recorded(SaveIo& io, const ChainDef& d) { save_chain_def(io, d); }
inline void save_recorded(SaveIo& io, const JointDef& d) { joint_def_fields(io, d); }
inline void save_recorded(SaveIo& io, const SurfaceMaterial& m) { surface_material_fields(io, m); }
inline void save_recorded(SaveIo& io, const WorldDef& s) { settings_fields(io, s, recording_settings_versions); }

}  // namespace i2d
