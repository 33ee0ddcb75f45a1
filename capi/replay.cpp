// SPDX-License-Identifier: MIT
#include "replay.hpp"
#include "replayed.hpp"

#include <cstring>

#include "convert.hpp"
#include "core/checksum.hpp"
#include "core/field_io.hpp"
#include "geometry_checks.hpp"
#include "dynamics/recording/recorded_fields.hpp"
#include "limits.hpp"
#include "loaded_values.hpp"

namespace i2d::capi {

// Bodies: made, destroyed, moved, pushed, woken and put to sleep, disabled and enabled.
bool Replayed::body_call(RecordedOp op) const {
    int32_t index = 0;
    switch (op) {
        case RecordedOp::create_body: {
            BodyDef def;
            body_def_fields(io, def);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!valid_recorded_body_def(call, def)) {
                return false;
            }
            return world.create_body(def) != null_index ||
                   call.fail(I2D_ERR_CAPACITY, "the world holds the most bodies it can");
        }
        case RecordedOp::destroy_body:
            io(index);
            return read_whole(in) ? passed(i2d_body_destroy(body(index))) : malformed(call);
        case RecordedOp::set_type: {
            BodyType type = BodyType::static_body;
            io(index), io(type);
            return read_whole(in) ? passed(i2d_body_set_type(body(index), i2d_body_type(type))) : malformed(call);
        }
        case RecordedOp::set_transforms: {
            const int32_t count = in.count(4 + 16, Pool<Body>::max_slots, "too many transforms");
            std::vector<int32_t> bodies(std::size_t(count > 0 ? count : 0));
            std::vector<Transform> transforms(bodies.size());
            for (std::size_t k = 0; k < bodies.size(); ++k) {
                io(bodies[k]), io(transforms[k]);
            }
            if (!read_whole(in)) {
                return malformed(call);
            }
            for (std::size_t k = 0; k < bodies.size(); ++k) {
                Rot unused;
                if (!live(call, world.bodies().is_live(bodies[k]), "body") ||
                    !call.coordinate(to_public(transforms[k].p), "transform") ||
                    !normalized_rotation(call, to_public(transforms[k].q), "transform", unused)) {
                    return false;
                }
            }
            world.set_transforms(bodies.data(), transforms.data(), count);
            return true;
        }
        case RecordedOp::set_linear_velocity:
        case RecordedOp::apply_force_to_center: {
            Vec2 v;
            bool wake = false;
            io(index), io(v);
            if (op == RecordedOp::apply_force_to_center) {
                io(wake);
            }
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.bodies().is_live(index), "body")) {
                return false;
            }
            if (op == RecordedOp::set_linear_velocity) {
                world.set_linear_velocity(index, v);
            } else {
                world.apply_force_to_center(index, v, wake);
            }
            return true;
        }
        case RecordedOp::set_angular_velocity:
        case RecordedOp::apply_torque:
        case RecordedOp::apply_angular_impulse: {
            float value = 0.0f;
            bool wake = false;
            io(index), io(value);
            if (op != RecordedOp::set_angular_velocity) {
                io(wake);
            }
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.bodies().is_live(index), "body")) {
                return false;
            }
            if (op == RecordedOp::set_angular_velocity) {
                world.set_angular_velocity(index, value);
            } else if (op == RecordedOp::apply_torque) {
                world.apply_torque(index, value, wake);
            } else {
                world.apply_angular_impulse(index, value, wake);
            }
            return true;
        }
        case RecordedOp::apply_force:
        case RecordedOp::apply_linear_impulse: {
            Vec2 value, point;
            bool wake = false;
            io(index), io(value), io(point), io(wake);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.bodies().is_live(index), "body") || !call.coordinate(to_public(point), "point")) {
                return false;
            }
            if (op == RecordedOp::apply_force) {
                world.apply_force(index, value, point, wake);
            } else {
                world.apply_linear_impulse(index, value, point, wake);
            }
            return true;
        }
        case RecordedOp::wake_body:
        case RecordedOp::sleep_body:
            io(index);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.bodies().is_live(index), "body")) {
                return false;
            }
            if (op == RecordedOp::wake_body) {
                world.wake_body(index);
            } else if (world.bodies()[index].type != BodyType::static_body) {
                world.sleep_body(index);
            } else {
                return call.fail(I2D_ERR_INVALID_SNAPSHOT, "a record puts a static body to sleep");
            }
            return true;
        case RecordedOp::wake_all:
            if (!read_whole(in)) {
                return malformed(call);
            }
            world.wake_all();
            return true;
        case RecordedOp::set_body_enabled: {
            bool enabled = false;
            io(index), io(enabled);
            if (!read_whole(in)) {
                return malformed(call);
            }
            return passed(enabled ? i2d_body_enable(body(index)) : i2d_body_disable(body(index)));
        }
        default:
            return unknown();
    }
}

// Shapes and chains: made, destroyed, their materials and filters.
bool Replayed::shape_call(RecordedOp op) const {
    int32_t index = 0;
    switch (op) {
        case RecordedOp::create_shape: {
            ShapeDef def;
            Geometry geometry;
            io(index);
            shape_def_fields(io, def);
            geometry_fields(io, geometry);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.bodies().is_live(index), "body") || !valid_recorded_shape(call, def, geometry)) {
                return false;
            }
            return world.create_shape(index, def, geometry) != null_index ||
                   call.fail(I2D_ERR_CAPACITY, "the world holds the most shapes it can");
        }
        case RecordedOp::destroy_shape:
            io(index);
            return read_whole(in) ? passed(i2d_shape_destroy(shape(index))) : malformed(call);
        case RecordedOp::set_friction:
        case RecordedOp::set_restitution: {
            float value = 0.0f;
            io(index), io(value);
            if (!read_whole(in)) {
                return malformed(call);
            }
            return passed(op == RecordedOp::set_friction ? i2d_shape_set_friction(shape(index), value)
                                                                : i2d_shape_set_restitution(shape(index), value));
        }
        case RecordedOp::set_filter: {
            Filter filter;
            io(index);
            filter_fields(io, filter);
            return read_whole(in) ? passed(i2d_shape_set_filter(shape(index), to_public(filter))) : malformed(call);
        }
        case RecordedOp::create_chain: {
            RecordedChain recorded;
            io(index);
            load_chain_def(io, recorded, max_chain_points);
            if (!read_whole(in)) {
                return malformed(call);
            }
            std::vector<i2d_vec2> points(recorded.points.size());
            for (std::size_t k = 0; k < points.size(); ++k) {
                points[k] = to_public(recorded.points[k]);
            }
            std::vector<i2d_surface_material> materials(recorded.materials.size());
            for (std::size_t k = 0; k < materials.size(); ++k) {
                const SurfaceMaterial& m = recorded.materials[k];
                materials[k] = {m.friction, m.restitution, m.rolling_resistance, m.tangent_speed};
            }
            i2d_chain_def def = i2d_default_chain_def();
            def.points = points.data();
            def.count = int32_t(points.size());
            def.is_loop = recorded.def.is_loop;
            def.materials = materials.data();
            def.material_count = int32_t(materials.size());
            def.filter = to_public(recorded.def.filter);
            def.enable_sensor_events = recorded.def.enable_sensor_events;
            def.user_data = recorded.def.user_data;
            return !I2D_IS_NULL(i2d_chain_create(body(index), &def));
        }
        case RecordedOp::destroy_chain:
            io(index);
            return read_whole(in) ? passed(i2d_chain_destroy(chain(index))) : malformed(call);
        default:
            return unknown();
    }
}

// Joints: made, changed, destroyed.
bool Replayed::joint_call(RecordedOp op) const {
    int32_t index = 0;
    switch (op) {
        case RecordedOp::create_joint: {
            JointDef def;
            joint_def_fields(io, def);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!valid_recorded_joint(call, world, def)) {
                return false;
            }
            return world.create_joint(def) != null_index ||
                   call.fail(I2D_ERR_CAPACITY, "the world holds the most joints it can");
        }
        case RecordedOp::destroy_joint:
            io(index);
            return read_whole(in) ? passed(i2d_joint_destroy(joint(index))) : malformed(call);
        case RecordedOp::set_joint_def: {
            JointDef def;
            io(index);
            joint_def_fields(io, def);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (!live(call, world.joints().is_live(index), "joint")) {
                return false;
            }
            const JointDef& now = world.joints()[index].def;
            if (def.type != now.type || def.body_a != now.body_a || def.body_b != now.body_b) {
                return call.fail(I2D_ERR_INVALID_SNAPSHOT, "a record changes a joint's kind or bodies");
            }
            if (!valid_joint_values(call, def, index)) {
                return false;
            }
            world.set_joint_def(index, def);
            return true;
        }
        default:
            return unknown();
    }
}

// User data of every kind, gravity, the static tree, the origin.
bool Replayed::world_call(RecordedOp op) const {
    int32_t index = 0;
    switch (op) {
        case RecordedOp::set_body_user_data:
        case RecordedOp::set_shape_user_data:
        case RecordedOp::set_joint_user_data: {
            void* user_data = nullptr;
            io(index), io(user_data);
            if (!read_whole(in)) {
                return malformed(call);
            }
            if (op == RecordedOp::set_body_user_data) {
                return passed(i2d_body_set_user_data(body(index), user_data));
            }
            return passed(op == RecordedOp::set_shape_user_data ? i2d_shape_set_user_data(shape(index), user_data)
                                                                : i2d_joint_set_user_data(joint(index), user_data));
        }
        case RecordedOp::set_gravity: {
            Vec2 gravity;
            io(gravity);
            return read_whole(in) ? passed(i2d_world_set_gravity(world_id, to_public(gravity))) : malformed(call);
        }
        case RecordedOp::rebuild_static_tree:
            return read_whole(in) ? passed(i2d_world_rebuild_static_tree(world_id)) : malformed(call);
        case RecordedOp::shift_origin: {
            Vec2 new_origin;
            io(new_origin);
            return read_whole(in) ? passed(i2d_world_shift_origin(world_id, to_public(new_origin))) : malformed(call);
        }
        default:
            return unknown();
    }
}

std::unique_ptr<Replay> Replay::open(Call& call, const void* data, std::size_t size, const i2d_world_def* runtime) {
    if (data == nullptr && size != 0) {
        call.fail(I2D_ERR_INVALID_ARGUMENT, "recording is NULL and size is %zu", size);
        return nullptr;
    }
    std::unique_ptr<Replay> replay(new Replay());
    const auto* bytes = static_cast<const unsigned char*>(data);
    replay->bytes_.assign(bytes, bytes + size);
    if (const char* problem = replay->read_records()) {
        call.fail(I2D_ERR_INVALID_SNAPSHOT, "recording refused: %s", problem);
        return nullptr;
    }
    const Record& first = replay->records_.front();
    const unsigned char* snapshot = replay->bytes_.data() + first.payload_at;
    replay->world_ = i2d_world_create_from_snapshot(snapshot, first.payload_size, runtime);
    if (I2D_IS_NULL(replay->world_)) {
        return nullptr;  // the status says why
    }
    return replay;
}

Replay::~Replay() {
    if (!I2D_IS_NULL(world_)) {
        i2d_world_destroy(world_);
    }
}

const char* Replay::read_records() {
    if (bytes_.size() < recording_header_size ||
        std::memcmp(bytes_.data(), recording_magic, sizeof recording_magic) != 0) {
        return "it is not a recording (no recording header)";
    }
    ByteReader header(bytes_.data() + 8, 8);
    format_version_ = header.u32();
    if (format_version_ > recording_format_version) {
        return "it is of a newer format than this library reads";
    }
    const bool size_checked = format_version_ >= 2;
    const std::size_t header_size = size_checked ? record_header_size : record_header_size_v1;
    std::size_t at = recording_header_size;
    // A record cut short at the end is one a writer did not finish: left out.
    while (bytes_.size() - at >= header_size) {
        ByteReader in(bytes_.data() + at, header_size);
        const uint32_t sum = in.u32();
        const uint8_t op = in.u8();
        const uint32_t payload = in.u32();
        if (size_checked && in.u32() != record_size_check(bytes_.data() + at)) {
            return "a record's size does not match its check (changed or corrupted)";
        }
        if (payload > bytes_.size() - at - header_size) {
            break;
        }
        const std::size_t end = at + header_size + payload;
        if (uint32_t(checksum64(bytes_.data() + at + 4, end - at - 4)) != sum) {
            return "a record's checksum does not match (changed or corrupted)";
        }
        if (op == 0 || op >= uint8_t(RecordedOp::count)) {
            return "a record is of a kind this library does not know";
        }
        if (records_.empty() && RecordedOp(op) != RecordedOp::snapshot) {
            return "it does not start with a snapshot";
        }
        if (RecordedOp(op) == RecordedOp::step) {
            step_records_.push_back(records_.size());
        }
        records_.push_back(Record{RecordedOp(op), at + header_size, payload});
        at = end;
    }
    return records_.empty() ? "it holds no whole record" : nullptr;
}

int32_t Replay::run(Call& call, int32_t count, bool stop_at_divergence) {
    int32_t ran = 0;
    while (ran < count && !broken_ && steps_done_ < step_count()) {
        const Record& record = records_[next_record_++];
        if (!(record.op == RecordedOp::step ? apply_step(call, record) : apply(call, record))) {
            broken_ = true;
            char detail[300];
            std::snprintf(detail, sizeof detail, "%s", i2d_last_error_message());
            call.fail(I2D_ERR_INVALID_SNAPSHOT, "replay stopped at record %zu (after step %d): %s", next_record_ - 1,
                      int(steps_done_), detail);
            break;
        }
        if (record.op == RecordedOp::step) {
            ++ran;
            if (stop_at_divergence && divergent_step_ == steps_done_) {
                break;
            }
        }
    }
    return ran;
}

bool Replay::seek(Call& call, int32_t step) {
    if (step < 0 || step > step_count()) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "step %d is outside the recording's 0 to %d", int(step),
                         int(step_count()));
    }
    if (broken_) {
        return call.fail(I2D_ERR_INVALID_SNAPSHOT, "the replay stopped at a record its world refused");
    }
    if (step < steps_done_) {
        const Record& first = records_.front();
        if (!passed(i2d_world_restore_snapshot(world_, bytes_.data() + first.payload_at, first.payload_size))) {
            return false;
        }
        next_record_ = 1;
        steps_done_ = 0;
    }
    run(call, step - steps_done_, false);
    return !broken_;
}

bool Replay::apply_step(Call& call, const Record& record) {
    ByteReader in(bytes_.data() + record.payload_at, record.payload_size);
    const float time_step = in.f32();
    const int32_t substeps = in.i32();
    const uint64_t hash = in.u64();
    if (!read_whole(in)) {
        return malformed(call);
    }
    if (!passed(i2d_world_step(world_, time_step, substeps))) {
        return false;
    }
    ++steps_done_;
    if (i2d_world_get_state_hash(world_) != hash && divergent_step_ < 0) {
        divergent_step_ = steps_done_;
    }
    return true;
}

bool Replay::apply(Call& call, const Record& record) {
    const unsigned char* payload = bytes_.data() + record.payload_at;
    if (record.op == RecordedOp::snapshot) {
        return passed(i2d_world_restore_snapshot(world_, payload, record.payload_size));
    }
    WorldRef w;
    if (!call.world(world_, w) || !call.unlocked(*w.world)) {
        return false;
    }
    ByteReader in(payload, record.payload_size);
    LoadIo io(in, format_version_);
    const Replayed r{call, *w.world, w.id, world_, in, io};
    switch (record.op) {
        case RecordedOp::create_shape:
        case RecordedOp::destroy_shape:
        case RecordedOp::set_friction:
        case RecordedOp::set_restitution:
        case RecordedOp::set_filter:
        case RecordedOp::create_chain:
        case RecordedOp::destroy_chain:
            return r.shape_call(record.op);
        case RecordedOp::create_joint:
        case RecordedOp::destroy_joint:
        case RecordedOp::set_joint_def:
            return r.joint_call(record.op);
        case RecordedOp::set_body_user_data:
        case RecordedOp::set_shape_user_data:
        case RecordedOp::set_joint_user_data:
        case RecordedOp::set_gravity:
        case RecordedOp::rebuild_static_tree:
        case RecordedOp::shift_origin:
            return r.world_call(record.op);
        case RecordedOp::set_mass_data:
        case RecordedOp::set_body_setting:
        case RecordedOp::set_body_flag:
        case RecordedOp::set_shape_geometry:
        case RecordedOp::set_shape_density:
        case RecordedOp::set_shape_material:
        case RecordedOp::set_shape_flag:
        case RecordedOp::set_world_settings:
            return r.settings_call(record.op);
        default:
            return r.body_call(record.op);
    }
}

}  // namespace i2d::capi
