// SPDX-License-Identifier: MIT
// The world def at the C boundary: its checks, its conversion to the core's settings and
// back, and a new world's registration with the ids it hands out.
#include "world_def.hpp"

#include <cstring>
#include <type_traits>

#include "convert.hpp"
#include "limits.hpp"
#include "registry.hpp"

namespace i2d::capi {

namespace {

static_assert(I2D_MAX_WORKERS == max_worker_count, "one limit on workers");
static_assert(std::is_same<i2d_task_fn*, TaskFn>::value && std::is_same<i2d_enqueue_task_fn*, EnqueueTaskFn>::value &&
                  std::is_same<i2d_finish_task_fn*, FinishTaskFn>::value,
              "the core calls the job system as the C API declares it");

// Read as an integer: a C caller can store any int in an enum field, and loading an
// out-of-range value as the C++ enum type is undefined behaviour.
bool valid_mixing_rule(Call& call, const i2d_mixing_rule* rule, const char* field) {
    static_assert(sizeof(i2d_mixing_rule) == sizeof(int32_t), "enums are 32-bit");
    int32_t value = 0;
    std::memcpy(&value, rule, sizeof value);
    return value >= 0 && value < static_cast<int32_t>(MixingRule::count)
               ? true
               : call.fail(I2D_ERR_INVALID_ARGUMENT, "%s is %d; it must be an i2d_mixing_rule", field, value);
}

// Read as an integer, like the mixing rules; a path the CPU lacks is refused, so that a
// world never runs on kernels it cannot execute.
bool valid_simd_path(Call& call, const i2d_simd_path* path) {
    static_assert(sizeof(i2d_simd_path) == sizeof(int32_t), "enums are 32-bit");
    int32_t value = 0;
    std::memcpy(&value, path, sizeof value);
    if (value < 0 || value >= static_cast<int32_t>(SimdPath::count)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "world def: simd_path is %d; it must be an i2d_simd_path", value);
    }
    if (!simd_path_supported(SimdPath(value))) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "world def: simd_path %d is not supported by this build or CPU; check "
                         "i2d_simd_path_supported first",
                         value);
    }
    return true;
}

}  // namespace

// A worker count in range, and a job system given whole or not at all (half a job system
// could enqueue and never finish).
bool valid_job_system(Call& call, const char* def_name, int32_t worker_count, bool has_enqueue, bool has_finish) {
    if (worker_count < 1 || worker_count > I2D_MAX_WORKERS) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s: worker_count is %d; it must be in [1, %d]", def_name,
                         int(worker_count), int(I2D_MAX_WORKERS));
    }
    if (has_enqueue != has_finish) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT,
                         "%s: enqueue_task and finish_task must be given together (or both NULL for the "
                         "built-in threads); %s is NULL",
                         def_name, has_enqueue ? "finish_task" : "enqueue_task");
    }
    return true;
}

bool valid_step(Call& call, float time_step, int32_t substep_count) {
    if (!call.in_range(time_step, 0.0f, max_time_step, "time_step")) {
        return false;
    }
    if (time_step != 0.0f && time_step < min_time_step) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "time_step is %g; it must be 0 (paused) or at least %g s",
                         static_cast<double>(time_step), static_cast<double>(min_time_step));
    }
    if (substep_count < 1 || substep_count > max_substeps) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "substep_count is %d; it must be in [1, %d]", substep_count,
                         max_substeps);
    }
    return true;
}

bool validate_world_def(Call& call, const i2d_world_def* def) {
    if (!call.not_null(def, "world def") || !call.cookie(def->internal_cookie, "world_def") ||
        !call.in_range(def->length_units_per_meter, min_length_units_per_meter, max_length_units_per_meter,
                       "world def: length_units_per_meter")) {
        return false;
    }
    // Lengths and speeds are in the world's units: their limits scale with them.
    const float units = def->length_units_per_meter;
    const float speed_limit = units * max_speed_limit;
    return call.finite(def->gravity, "world def: gravity") &&
           call.in_range(def->contact_slop, 0.0f, units * max_contact_slop, "world def: contact_slop") &&
           call.in_range(def->contact_hertz, min_contact_hertz, max_setting, "world def: contact_hertz") &&
           call.in_range(def->contact_damping_ratio, 0.0f, max_setting, "world def: contact_damping_ratio") &&
           call.in_range(def->joint_hertz, min_contact_hertz, max_setting, "world def: joint_hertz") &&
           call.in_range(def->joint_damping_ratio, 0.0f, max_setting, "world def: joint_damping_ratio") &&
           call.in_range(def->contact_push_max_speed, 0.0f, speed_limit, "world def: contact_push_max_speed") &&
           call.in_range(def->restitution_threshold, 0.0f, speed_limit, "world def: restitution_threshold") &&
           call.in_range(def->maximum_linear_speed, 1.0e-6f, speed_limit, "world def: maximum_linear_speed") &&
           valid_mixing_rule(call, &def->friction_mixing, "world def: friction_mixing") &&
           valid_mixing_rule(call, &def->restitution_mixing, "world def: restitution_mixing") &&
           call.in_range(def->sleep_speed_threshold, 0.0f, speed_limit, "world def: sleep_speed_threshold") &&
           call.in_range(def->time_to_sleep, 0.0f, max_setting, "world def: time_to_sleep") &&
           call.in_range(def->hit_event_threshold, 0.0f, speed_limit, "world def: hit_event_threshold") &&
           valid_simd_path(call, &def->simd_path) &&
           valid_job_system(call, "world def", def->worker_count, def->enqueue_task != nullptr,
                            def->finish_task != nullptr);
}

namespace {

uint64_t encode_body(uint64_t world_bits, int32_t index, uint16_t generation) {
    return make_body_id(decode_id(world_bits), index, generation).bits;
}

uint64_t encode_shape(uint64_t world_bits, int32_t index, uint16_t generation) {
    return make_shape_id(decode_id(world_bits), index, generation).bits;
}

uint64_t encode_joint(uint64_t world_bits, int32_t index, uint16_t generation) {
    return make_joint_id(decode_id(world_bits), index, generation).bits;
}

}  // namespace

WorldDef to_core(const i2d_world_def& def) {
    WorldDef core;
    core.gravity = capi::to_core(def.gravity);
    core.contact_slop = def.contact_slop;
    core.contact_hertz = def.contact_hertz;
    core.contact_damping_ratio = def.contact_damping_ratio;
    core.joint_hertz = def.joint_hertz;
    core.joint_damping_ratio = def.joint_damping_ratio;
    core.contact_push_max_speed = def.contact_push_max_speed;
    core.restitution_threshold = def.restitution_threshold;
    core.maximum_linear_speed = def.maximum_linear_speed;
    core.friction_mixing = capi::to_core(def.friction_mixing);
    core.restitution_mixing = capi::to_core(def.restitution_mixing);
    core.enable_sleep = def.enable_sleep;
    core.sleep_speed_threshold = def.sleep_speed_threshold;
    core.time_to_sleep = def.time_to_sleep;
    core.simd_path = SimdPath(int(def.simd_path));
    core.enable_contact_recycling = def.enable_contact_recycling;
    core.enable_profile = def.enable_profile;
    core.worker_count = def.worker_count;
    core.tasks.enqueue = def.enqueue_task;
    core.tasks.finish = def.finish_task;
    core.tasks.user_context = def.user_task_context;
    core.enable_continuous = def.enable_continuous;
    core.enable_impact_chains = def.enable_impact_chains;
    core.hit_event_threshold = def.hit_event_threshold;
    core.length_units_per_meter = def.length_units_per_meter;
    return core;
}


i2d_world_def to_public(const WorldDef& core) {
    i2d_world_def def{};
    def.gravity = capi::to_public(core.gravity);
    def.contact_slop = core.contact_slop;
    def.contact_hertz = core.contact_hertz;
    def.contact_damping_ratio = core.contact_damping_ratio;
    def.joint_hertz = core.joint_hertz;
    def.joint_damping_ratio = core.joint_damping_ratio;
    def.contact_push_max_speed = core.contact_push_max_speed;
    def.restitution_threshold = core.restitution_threshold;
    def.maximum_linear_speed = core.maximum_linear_speed;
    def.friction_mixing = capi::to_public(core.friction_mixing);
    def.restitution_mixing = capi::to_public(core.restitution_mixing);
    def.enable_sleep = core.enable_sleep;
    def.sleep_speed_threshold = core.sleep_speed_threshold;
    def.time_to_sleep = core.time_to_sleep;
    def.simd_path = static_cast<i2d_simd_path>(core.simd_path);
    def.enable_contact_recycling = core.enable_contact_recycling;
    def.enable_profile = core.enable_profile;
    def.worker_count = core.worker_count;
    def.enqueue_task = core.tasks.enqueue;
    def.finish_task = core.tasks.finish;
    def.user_task_context = core.tasks.user_context;
    def.enable_continuous = core.enable_continuous;
    def.enable_impact_chains = core.enable_impact_chains;
    def.hit_event_threshold = core.hit_event_threshold;
    def.length_units_per_meter = core.length_units_per_meter;
    def.internal_cookie = def_cookie;
    return def;
}

i2d_world_id register_new_world(Call& call, std::unique_ptr<World> world) {
    const WorldSlotRef ref = register_world(world.get());
    if (ref.slot < 0) {
        call.fail(I2D_ERR_CAPACITY, "%d worlds are alive, the most at once; destroy one first", max_worlds);
        return I2D_NULL_WORLD_ID;
    }
    IdFields f;
    f.world_slot = ref.slot;
    f.world_generation = ref.generation;
    const i2d_world_id id = make_world_id(f);
    // Named members: the encoder's member order is the core's to change.
    IdEncoder ids;
    ids.body = encode_body;
    ids.shape = encode_shape;
    ids.joint = encode_joint;
    ids.tag = id.bits;
    world->set_id_encoder(ids);
    world.release();
    return id;
}

}  // namespace i2d::capi
