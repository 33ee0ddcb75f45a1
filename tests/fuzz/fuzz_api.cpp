// SPDX-License-Identifier: MIT
// libFuzzer harness: reads its input as a program of C API calls and runs it.
//
// Each instruction is one opcode byte followed by the operands it reads (ids chosen from
// what the program holds, floats from a table of hostile values or raw bits, sizes and
// counts of any sign). Ids are kept after their objects die, so stale, foreign (a body's
// bits passed as a shape) and null ids are used on purpose. Query and ray callbacks call
// back into the library and try to destroy things, as the debug draw's callbacks do, which
// also check that every float they are handed is finite. Joints are made between any held
// bodies (of any world, live or dead) with hostile settings, then changed, read and
// broken. The library must never crash, leak or trip a sanitizer, and a world (into
// which the API accepts only finite values) must never report a non-finite position,
// velocity or joint measure; a cast's normal is unit and a translation longer than 1e9 m
// is refused; a joint's angles read back in (-pi, pi]; the character mover's answers are
// finite (fuzz_mover_calls.inl). A breach aborts with a message.
//
// Only the public header is used: the harness is a hostile C API caller.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "../api/any_joint_def.h"
#include "fuzz_input.hpp"
#include "raw_enum_calls.h"

namespace {

constexpr int max_worlds_held = 4;
constexpr int max_bodies_held = 48;
constexpr int max_shapes_held = 96;
constexpr int max_joints_held = 32;

// What the program holds: live ids and, on purpose, dead ones.
struct Held {
    i2d_world_id worlds[max_worlds_held] = {};
    i2d_body_id bodies[max_bodies_held] = {};
    i2d_shape_id shapes[max_shapes_held] = {};
    i2d_joint_id joints[max_joints_held] = {};
    int world_count = 0, body_count = 0, shape_count = 0, joint_count = 0;
    // Every world this input created, to free them all at its end (at most 256 can live).
    i2d_world_id created[256] = {};
    int created_count = 0;
};

Held* g_held = nullptr;
// FUZZ_TRACE=1 prints each instruction and the bodies before each step: how a finding
// is read back into a regression test.
const bool g_trace = std::getenv("FUZZ_TRACE") != nullptr;

void trace_bodies() {
    for (int i = 0; g_trace && i < g_held->body_count; ++i) {
        const i2d_body_id b = g_held->bodies[i];
        if (i2d_body_is_valid(b)) {
            const i2d_transform xf = i2d_body_get_transform(b);
            const i2d_vec2 v = i2d_body_get_linear_velocity(b);
            const i2d_vec2 c = i2d_body_get_world_center_of_mass(b);
            std::fprintf(stderr,
                         "  body %d type %d p (%g, %g) q (%g, %g) v (%g, %g) w %g mass %g inertia %g centre (%g, %g) "
                         "shapes %d\n",
                         i, int(i2d_body_get_type(b)), xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y,
                         i2d_body_get_angular_velocity(b), i2d_body_get_mass(b), i2d_body_get_rotational_inertia(b),
                         c.x, c.y, i2d_body_get_shape_count(b));
            i2d_shape_id shapes[8];
            const int32_t n = i2d_body_get_shapes(b, shapes, 8);
            for (int32_t k = 0; k < n && k < 8; ++k) {
                const i2d_aabb box = i2d_shape_get_aabb(shapes[k]);
                const i2d_filter f = i2d_shape_get_filter(shapes[k]);
                std::fprintf(stderr, "    shape type %d sensor %d aabb (%g, %g)-(%g, %g) filter %llx %llx %d\n",
                             int(i2d_shape_get_type(shapes[k])), int(i2d_shape_is_sensor(shapes[k])), box.min.x,
                             box.min.y, box.max.x, box.max.y, (unsigned long long)f.category_bits,
                             (unsigned long long)f.mask_bits, f.group_index);
                if (i2d_shape_get_type(shapes[k]) == I2D_SHAPE_POLYGON) {
                    const i2d_polygon p = i2d_shape_get_polygon(shapes[k]);
                    std::fprintf(stderr, "      radius %.9g vertices", p.radius);
                    for (int32_t v = 0; v < p.count && v < I2D_MAX_POLYGON_VERTICES; ++v) {
                        std::fprintf(stderr, " (%.9g, %.9g)", p.vertices[v].x, p.vertices[v].y);
                    }
                    std::fprintf(stderr, "\n");
                } else if (i2d_shape_get_type(shapes[k]) == I2D_SHAPE_CIRCLE) {
                    const i2d_circle c = i2d_shape_get_circle(shapes[k]);
                    std::fprintf(stderr, "      centre (%.9g, %.9g) radius %.9g\n", c.center.x, c.center.y, c.radius);
                }
            }
        }
    }
}

void fail(const char* what, double a, double b) {
    std::fprintf(stderr, "fuzz_api: %s (%g, %g)\n", what, a, b);
    std::abort();
}

// ---- Picking ids: held ones (live or stale), null, random bits, or another kind's ----

// One byte decides: below held_below a held id, below 230 the null id, below 245 the bits
// of a held id of another kind (foreign), else random bits.
template <class Id, class Foreign>
Id pick_id(FuzzInput& in, const Id* held, int held_count, int held_below, const Foreign* foreign, int foreign_count) {
    const uint8_t k = in.byte();
    if (k < held_below && held_count > 0) {
        return held[k % held_count];
    }
    if (k < 230) {
        return Id{0};
    }
    if (k < 245 && foreign_count > 0) {
        return Id{foreign[k % foreign_count].bits};
    }
    return Id{in.u64()};
}

i2d_world_id pick_world(FuzzInput& in) {
    return pick_id(in, g_held->worlds, g_held->world_count, 200, g_held->bodies, g_held->body_count);
}

i2d_body_id pick_body(FuzzInput& in) {
    return pick_id(in, g_held->bodies, g_held->body_count, 210, g_held->shapes, g_held->shape_count);
}

i2d_shape_id pick_shape(FuzzInput& in) {
    return pick_id(in, g_held->shapes, g_held->shape_count, 210, g_held->worlds, g_held->world_count);
}

// New ids replace old ones round robin once the table is full: the old stays stale.
template <class Id>
void keep(Id* table, int& count, int capacity, Id id, uint8_t where) {
    if (I2D_IS_NULL(id)) {
        return;
    }
    if (count < capacity) {
        table[count++] = id;
    } else {
        table[where % capacity] = id;
    }
}

// ---- The finiteness check ------------------------------------------------------------

bool finite2(i2d_vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

void check_body_finite(i2d_body_id b) {
    if (!i2d_body_is_valid(b)) {
        return;
    }
    const i2d_transform xf = i2d_body_get_transform(b);
    const i2d_vec2 v = i2d_body_get_linear_velocity(b);
    const float w = i2d_body_get_angular_velocity(b);
    if (!finite2(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s)) {
        fail("non-finite body position", xf.p.x, xf.p.y);
    }
    if (!finite2(v) || !std::isfinite(w)) {
        fail("non-finite body velocity", v.x, w);
    }
}

void check_all_finite() {
    for (int i = 0; i < g_held->body_count; ++i) {
        check_body_finite(g_held->bodies[i]);
    }
}

// ---- What the API promises of casts ---------------------------------------------------

// A hit's normal is unit, also for a shape cast that starts overlapping (issue 44: it was
// (0, 0) for a translation of 1e-30 m).
constexpr double unit_normal_tolerance = 1e-3;

void check_unit_normal(i2d_vec2 normal, const char* what) {
    const double length = std::hypot(double(normal.x), double(normal.y));
    if (!(std::fabs(length - 1.0) <= unit_normal_tolerance)) {
        fail(what, normal.x, normal.y);
    }
}

// A translation longer than 1e9 m is refused, however it is split between x and y (issue
// 44: each component was bounded instead).
constexpr double max_cast_length_m = 1e9;

void check_cast_length(i2d_vec2 translation, i2d_status status) {
    const double length = std::hypot(double(translation.x), double(translation.y));
    if (std::isfinite(length) && length > max_cast_length_m && status == I2D_OK) {
        fail("a cast longer than 1e9 m was accepted", translation.x, translation.y);
    }
}

// ---- A job system of the harness's own, for worlds with workers ----------------------
// Single threaded, so that a finding replays: it runs each of the engine's tasks as soon
// as it is enqueued, or holds it until finish_task (tasks then run late, in order or the
// newest first), or first calls back into the library from inside the step. The fuzz
// build shares the work of worlds this small (constants.hpp), so the stages run in
// blocks, with the workers' take-over of tasks that start late.

enum class JobOrder : uint8_t { inline_now, at_finish, newest_first, intruding };

struct HeldTask {
    i2d_task_fn* task;
    int32_t item_count;
    void* context;
    bool done;
};

struct FuzzJobs {
    JobOrder order;
    // A stack: steps nest (an intruding task steps another world) and each finishes its
    // own tasks before its caller's.
    HeldTask held[2 * I2D_MAX_WORKERS];
    int held_count;
};

FuzzJobs g_jobs[] = {{JobOrder::inline_now, {}, 0}, {JobOrder::at_finish, {}, 0},
                     {JobOrder::newest_first, {}, 0}, {JobOrder::intruding, {}, 0}};
FuzzInput* g_in = nullptr;  // the program, for the intruding job system's choices

// The worlds inside i2d_world_step on this thread, innermost last.
constexpr int max_nested_steps = 8;
i2d_world_id g_stepping[max_nested_steps];
int g_stepping_count = 0;

bool is_stepping(i2d_world_id w) {
    for (int i = 0; i < g_stepping_count; ++i) {
        if (g_stepping[i].bits == w.bits) {
            return true;
        }
    }
    return false;
}

i2d_status step_world(i2d_world_id w, float dt, int32_t substeps) {
    if (g_stepping_count == max_nested_steps) {
        return I2D_ERR_WORLD_LOCKED;  // deep enough: the harness declines, not the library
    }
    g_stepping[g_stepping_count++] = w;
    const i2d_status status = i2d_world_step(w, dt, substeps);
    --g_stepping_count;
    return status;
}

// Calls from inside a step's task: every one naming a stepping world, or a body of one,
// must be refused as such.
void intrude(FuzzInput& in) {
    const i2d_world_id w = pick_world(in);
    const i2d_body_id b = pick_body(in);
    i2d_body_get_world(b);
    const bool body_locked = i2d_last_status() == I2D_ERR_WORLD_LOCKED;
    bool on_body = false;
    i2d_status status = I2D_OK;
    switch (in.byte() % 6) {
        case 0: status = step_world(w, 1.0f / 60.0f, 1 + in.byte() % 4); break;
        case 1: status = i2d_world_destroy(w); break;
        case 2: {
            const i2d_body_def def = i2d_default_body_def();
            status = I2D_IS_NULL(i2d_body_create(w, &def)) ? i2d_last_status() : I2D_OK;
            break;
        }
        case 3: i2d_world_get_counters(w); status = i2d_last_status(); break;
        case 4: status = i2d_body_set_linear_velocity(b, in.vec2()); on_body = true; break;
        default: status = i2d_body_destroy(b); on_body = true; break;
    }
    const bool locked = on_body ? body_locked : is_stepping(w);
    if (g_trace) {
        std::fprintf(stderr, "  from a task: %s on a %sstepping world: %s\n", on_body ? "body call" : "world call",
                     locked ? "" : "not ", i2d_status_string(status));
    }
    if (locked && status != I2D_ERR_WORLD_LOCKED) {
        fail("a call naming a world inside its step was accepted from its job system", double(status), 0.0);
    }
}

void run_held(HeldTask& t) {
    if (!t.done) {
        t.done = true;
        t.task(0, t.item_count, 0, t.context);
    }
}

void* enqueue_job(i2d_task_fn* task, int32_t item_count, int32_t, void* task_context, void* user_context) {
    FuzzJobs& jobs = *static_cast<FuzzJobs*>(user_context);
    if (jobs.order == JobOrder::intruding && g_in != nullptr) {
        intrude(*g_in);
    }
    if (jobs.order == JobOrder::inline_now || jobs.order == JobOrder::intruding ||
        jobs.held_count == 2 * I2D_MAX_WORKERS) {
        task(0, item_count, 0, task_context);
        return nullptr;
    }
    HeldTask& t = jobs.held[jobs.held_count++];
    t = {task, item_count, task_context, false};
    return &t;
}

void finish_job(void* handle, void* user_context) {
    FuzzJobs& jobs = *static_cast<FuzzJobs*>(user_context);
    HeldTask* t = static_cast<HeldTask*>(handle);
    if (jobs.order == JobOrder::newest_first) {
        for (HeldTask* newer = jobs.held + jobs.held_count - 1; newer > t; --newer) {
            run_held(*newer);
        }
    }
    run_held(*t);
    while (jobs.held_count > 0 && jobs.held[jobs.held_count - 1].done) {
        --jobs.held_count;
    }
}

// A worker count (mostly 1 to 8, sometimes any int) and who runs the work: a job system
// above, half of one (refused), or the built-in threads (2 workers at most, as threads
// that spin between tasks would starve the fuzzer). For a world def or a batch def.
template <class Def>
void worker_settings(FuzzInput& in, Def& def) {
    const uint8_t k = in.byte();
    def.worker_count = k < 240 ? 1 + k % 8 : static_cast<int32_t>(in.u32());
    const uint8_t who = in.byte() % 7;
    if (who < 4) {
        def.enqueue_task = &enqueue_job;
        def.finish_task = &finish_job;
        def.user_task_context = &g_jobs[who];
    } else if (who == 4) {
        def.enqueue_task = &enqueue_job;  // half a job system
    } else if (who == 5) {
        def.finish_task = &finish_job;
    } else if (def.worker_count > 2) {
        def.worker_count = 2;
    }
}

// ---- Definitions: from the default function, then edited; sometimes not initialised ----

// Edit bytes from this one on set the workers; the ones below keep the meaning they had
// before workers existed, so that older inputs still build the same worlds.
constexpr uint8_t worker_edit_first = 248;

i2d_world_def world_def(FuzzInput& in) {
    i2d_world_def def = i2d_default_world_def();
    const uint8_t edits = in.byte() % 6;
    for (uint8_t e = 0; e < edits; ++e) {
        const uint8_t edit = in.byte();
        switch (edit >= worker_edit_first ? 12 : edit % 12) {
            case 0: def.gravity = in.vec2(); break;
            case 1: def.contact_slop = in.real(); break;
            case 2: def.contact_hertz = in.real(); break;
            case 3: def.contact_damping_ratio = in.real(); break;
            case 4: def.contact_push_max_speed = in.real(); break;
            case 5: def.restitution_threshold = in.real(); break;
            case 6: def.maximum_linear_speed = in.real(); break;
            case 7: in.raw_enum(&def.friction_mixing); in.raw_enum(&def.restitution_mixing); break;
            case 8: def.enable_sleep = in.flag(); def.sleep_speed_threshold = in.real(); break;
            case 9: def.time_to_sleep = in.real(); def.enable_contact_recycling = in.flag(); break;
            case 10: in.raw_enum(&def.simd_path); break;
            case 11: def.internal_cookie = in.u32(); break;  // an uninitialised def
            default: worker_settings(in, def); break;
        }
    }
    return def;
}

i2d_body_def body_def(FuzzInput& in) {
    i2d_body_def def = i2d_default_body_def();
    def.type = static_cast<i2d_body_type>(in.byte() % 3);
    def.position = in.vec2();
    const uint8_t edits = in.byte() % 6;
    for (uint8_t e = 0; e < edits; ++e) {
        switch (in.byte() % 9) {
            case 0: def.rotation = i2d_make_rot(in.real()); break;
            case 1: def.rotation = i2d_rot{in.real(), in.real()}; break;
            case 2: def.linear_velocity = in.vec2(); break;
            case 3: def.angular_velocity = in.real(); break;
            case 4: def.linear_damping = in.real(); def.angular_damping = in.real(); break;
            case 5: def.gravity_scale = in.real(); break;
            case 6: def.fixed_rotation = in.flag(); def.is_bullet = in.flag(); def.enable_sleep = in.flag(); break;
            case 7: in.raw_enum(&def.type); break;
            default: def.internal_cookie = in.u32(); break;
        }
    }
    return def;
}

i2d_filter filter(FuzzInput& in) {
    i2d_filter f = i2d_default_filter();
    if (in.flag()) {
        f.category_bits = in.u64();
        f.mask_bits = in.u64();
        f.group_index = static_cast<int32_t>(in.u32());
    }
    return f;
}

i2d_shape_def shape_def(FuzzInput& in) {
    i2d_shape_def def = i2d_default_shape_def();
    const uint8_t edits = in.byte() % 5;
    for (uint8_t e = 0; e < edits; ++e) {
        switch (in.byte() % 7) {
            case 0: def.density = in.real(); break;
            case 1: def.friction = in.real(); def.restitution = in.real(); break;
            case 2: def.rolling_resistance = in.real(); def.tangent_speed = in.real(); break;
            case 3: def.is_sensor = in.flag(); def.enable_sensor_events = in.flag(); break;
            case 4:
                def.enable_contact_events = in.flag();
                def.enable_custom_filtering = in.flag();
                def.enable_pre_solve_events = in.flag();
                break;
            case 5: def.filter = filter(in); break;
            default: def.internal_cookie = in.u32(); break;
        }
    }
    return def;
}

// A def pointer: usually the def, sometimes NULL.
template <class Def>
const Def* maybe_null(FuzzInput& in, const Def& def) {
    return in.byte() < 245 ? &def : nullptr;
}

i2d_polygon polygon(FuzzInput& in) {
    i2d_vec2 points[10];
    const int32_t count = in.count(10);
    for (int32_t i = 0; i < 10; ++i) {
        points[i] = in.small_vec2();
    }
    i2d_polygon p{};
    if (i2d_make_polygon(points, count, in.small_real(), &p) != I2D_OK || in.byte() > 240) {
        p = i2d_make_box(in.small_real(), in.small_real());
    }
    if (in.byte() > 235) {  // hand-edited: any field may now be wrong
        p.vertices[in.byte() % I2D_MAX_POLYGON_VERTICES] = in.vec2();
        p.count = static_cast<int32_t>(in.u32());
    }
    return p;
}

i2d_transform transform(FuzzInput& in) {
    i2d_transform xf;
    xf.p = in.vec2();
    xf.q = in.flag() ? i2d_make_rot(in.real()) : i2d_rot{in.real(), in.real()};
    return xf;
}

i2d_joint_id pick_joint(FuzzInput& in) {
    return pick_id(in, g_held->joints, g_held->joint_count, 210, g_held->bodies, g_held->body_count);
}

// ---- Callbacks that call back in -----------------------------------------------------

struct CallbackContext {
    FuzzInput* in;
    int calls;
};

// Inside a query the world is locked: whatever the callback tries must be refused
// cleanly or answered (getters); it then continues or stops as the input says.
void call_back_in(CallbackContext& c, i2d_shape_id shape) {
    FuzzInput& in = *c.in;
    const i2d_body_id body = i2d_shape_get_body(shape);
    switch (in.byte() % 8) {
        case 0: i2d_body_destroy(body); break;
        case 1: i2d_shape_destroy(shape); break;
        case 2: i2d_world_destroy(i2d_body_get_world(body)); break;
        case 3: i2d_world_step(i2d_body_get_world(body), 1.0f / 60.0f, 4); break;
        case 4: i2d_body_set_linear_velocity(body, in.vec2()); break;
        case 5: i2d_shape_set_user_data(shape, &c); break;
        case 6: {
            i2d_shape_id out[4];
            i2d_world_overlap_aabb_ids(i2d_body_get_world(body), i2d_shape_get_aabb(shape), i2d_default_query_filter(),
                                       out, 4);
            break;
        }
        default:
            check_body_finite(body);
            if (g_held->joint_count > 0) {  // refused inside the query: the world is locked
                const i2d_joint_id j = g_held->joints[c.calls % g_held->joint_count];
                i2d_joint_set_collide_connected(j, true);
                i2d_joint_destroy(j);
                i2d_joint_set_user_data(j, &c);
            }
            break;
    }
}

bool overlap_callback(i2d_shape_id shape, void* context) {
    auto& c = *static_cast<CallbackContext*>(context);
    ++c.calls;
    call_back_in(c, shape);
    return c.in->byte() < 200;
}

float ray_callback(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    auto& c = *static_cast<CallbackContext*>(context);
    ++c.calls;
    if (!finite2(point) || !finite2(normal) || !(fraction >= 0.0f && fraction <= 1.0f)) {
        fail("ray callback got a non-finite hit", point.x, fraction);
    }
    check_unit_normal(normal, "a cast callback got a normal that is not unit");
    call_back_in(c, shape);
    switch (c.in->byte() % 6) {
        case 0: return -1.0f;
        case 1: return 0.0f;
        case 2: return fraction;
        case 3: return 1.0f;
        default: return c.in->real();  // NaN, inf, 7, -3: whatever a buggy binding returns
    }
}

// ---- Events: every pointer read, every id asked about ---------------------------------

void read_events(i2d_world_id w) {
    const i2d_contact_events contacts = i2d_world_get_contact_events(w);
    for (int32_t i = 0; i < contacts.begin_count; ++i) {
        i2d_shape_is_valid(contacts.begin_events[i].shape_a);
        i2d_shape_is_valid(contacts.begin_events[i].shape_b);
    }
    for (int32_t i = 0; i < contacts.end_count; ++i) {
        i2d_shape_is_valid(contacts.end_events[i].shape_a);
    }
    const i2d_sensor_events sensors = i2d_world_get_sensor_events(w);
    for (int32_t i = 0; i < sensors.begin_count; ++i) {
        i2d_shape_is_valid(sensors.begin_events[i].visitor_shape);
    }
    for (int32_t i = 0; i < sensors.end_count; ++i) {
        i2d_shape_is_valid(sensors.end_events[i].sensor_shape);
    }
    const i2d_body_events moves = i2d_world_get_body_events(w);
    for (int32_t i = 0; i < moves.move_count; ++i) {
        const i2d_transform xf = moves.move_events[i].transform;
        if (!finite2(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s)) {
            fail("non-finite transform in a move event", xf.p.x, xf.p.y);
        }
        check_body_finite(moves.move_events[i].body);
    }
    // Quarantine is the last line of defence: a world fed only finite values must never
    // need it, so a quarantined body is a finding like a NaN.
    if (moves.quarantine_count > 0) {
        const i2d_vec2 at = moves.quarantine_events[0].transform.p;
        fail("a body was quarantined (its state went non-finite)", at.x, at.y);
    }
}

// ---- The instructions ------------------------------------------------------------------

// A batch of up to four worlds picked as any world is (bad ids and repeats among them),
// on worker settings as a world def gets them: refused whole, or each world stepped and
// checked. The batch's worlds count as stepping for an intruding job system.
void step_batch(FuzzInput& in) {
    constexpr int max_batch = 4;
    i2d_world_id worlds[max_batch];
    const int count = in.byte() % (max_batch + 1);
    for (int i = 0; i < count; ++i) {
        worlds[i] = pick_world(in);
    }
    i2d_batch_def def = i2d_default_batch_def();
    if (in.byte() < 96) {
        worker_settings(in, def);
    }
    const float dt = in.byte() < 200 ? 1.0f / 60.0f : in.real();
    const int32_t batch_count = in.byte() < 250 ? count : static_cast<int32_t>(in.u32());
    const i2d_world_id* list = in.byte() < 8 ? nullptr : worlds;
    if (g_stepping_count + count > max_nested_steps) {
        return;  // deep enough: the harness declines, not the library
    }
    for (int i = 0; i < count; ++i) {
        g_stepping[g_stepping_count++] = worlds[i];
    }
    const i2d_status status = i2d_worlds_step(list, batch_count, dt, 4, maybe_null(in, def));
    g_stepping_count -= count;
    if (g_trace) {
        std::fprintf(stderr, "  batch of %d (count %d): %s\n", count, int(batch_count), i2d_status_string(status));
    }
    if (status != I2D_OK) {
        return;
    }
    check_all_finite();
    for (int i = 0; i < count; ++i) {
        read_events(worlds[i]);
    }
}

// Bodies of up to four worlds read and given velocities in one call each, and the
// worlds' event counts (bad ids, non-finite velocities, NULL arrays and negative counts
// among them): refused whole, or every body left finite.
void batch_state(FuzzInput& in) {
    constexpr int max_items = 4;
    i2d_body_id bodies[max_items];
    i2d_world_id worlds[max_items];
    i2d_vec2 linear[max_items];
    float angular[max_items];
    const int count = in.byte() % (max_items + 1);
    for (int i = 0; i < count; ++i) {
        bodies[i] = pick_body(in);
        worlds[i] = pick_world(in);
        linear[i] = in.vec2();
        angular[i] = in.real();
    }
    // Never more than the arrays hold: a count past them is the caller's overrun.
    const int32_t listed = in.byte() < 250 ? count : -static_cast<int32_t>(in.byte());
    i2d_transform transforms[max_items];
    i2d_vec2 linear_read[max_items];
    float angular_read[max_items];
    bool awake[max_items];
    int32_t begins[max_items], ends[max_items];
    i2d_worlds_get_body_states(in.byte() < 8 ? nullptr : bodies, listed, in.flag() ? transforms : nullptr,
                               in.flag() ? linear_read : nullptr, in.flag() ? angular_read : nullptr,
                               in.flag() ? awake : nullptr);
    const i2d_status written = i2d_worlds_set_body_velocities(
        in.byte() < 8 ? nullptr : bodies, listed, in.flag() ? linear : nullptr, in.flag() ? angular : nullptr);
    if (g_trace) {
        std::fprintf(stderr, "  velocities of %d bodies (count %d): %s\n", count, int(listed),
                     i2d_status_string(written));
    }
    if (written == I2D_OK) {
        check_all_finite();
    }
    i2d_worlds_get_contact_event_counts(in.byte() < 8 ? nullptr : worlds, listed, in.flag() ? begins : nullptr,
                                        in.flag() ? ends : nullptr);
}

void run_world_call(FuzzInput& in, uint8_t op) {
    switch (op) {
        case 0: {
            const i2d_world_def def = world_def(in);
            if (g_trace) {
                std::fprintf(stderr,
                             "  world def: gravity (%g, %g) slop %g hertz %g damping %g push %g restitution_threshold %g "
                             "max_speed %g sleep %d %g %g recycling %d workers %d jobs %d\n",
                             def.gravity.x, def.gravity.y, def.contact_slop, def.contact_hertz,
                             def.contact_damping_ratio, def.contact_push_max_speed, def.restitution_threshold,
                             def.maximum_linear_speed, int(def.enable_sleep), def.sleep_speed_threshold,
                             def.time_to_sleep, int(def.enable_contact_recycling), def.worker_count,
                             def.user_task_context ? int(static_cast<FuzzJobs*>(def.user_task_context)->order) : -1);
            }
            const i2d_world_id w = i2d_world_create(maybe_null(in, def));
            if (!I2D_IS_NULL(w) && g_held->created_count < 256) {
                g_held->created[g_held->created_count++] = w;
            }
            keep(g_held->worlds, g_held->world_count, max_worlds_held, w, in.byte());
            break;
        }
        case 1: i2d_world_destroy(pick_world(in)); break;
        case 2: {
            const i2d_world_id w = pick_world(in);
            const float dt = in.byte() < 200 ? 1.0f / 60.0f : in.real();
            const int32_t substeps = in.byte() < 200 ? 4 : static_cast<int32_t>(in.u32());
            trace_bodies();
            if (step_world(w, dt, substeps) == I2D_OK) {
                check_all_finite();
            }
            read_events(w);
            break;
        }
        case 3: i2d_world_set_gravity(pick_world(in), in.vec2()); break;
        case 4: {
            const i2d_world_id w = pick_world(in);
            i2d_world_get_gravity(w);
            i2d_world_get_counters(w);
            i2d_world_get_profile(w);
            i2d_world_get_state_hash(w);
            i2d_world_get_simd_path(w);
            i2d_world_is_valid(w);
            break;
        }
        case 5: i2d_world_rebuild_static_tree(pick_world(in)); break;
        default: {
            if (in.byte() < 128) {
                step_batch(in);
                break;
            }
            if (in.byte() < 64) {
                batch_state(in);
                break;
            }
            int32_t path = 0, status = 0;
            in.raw_enum(&path);
            in.raw_enum(&status);
            fuzz_simd_path_supported(path);
            if (fuzz_status_string(status) == nullptr) {
                fail("status string is NULL", 0, 0);
            }
            break;
        }
    }
}

void run_body_call(FuzzInput& in, uint8_t op) {
    switch (op) {
        case 0: {
            const i2d_world_id w = pick_world(in);
            const i2d_body_def def = body_def(in);
            keep(g_held->bodies, g_held->body_count, max_bodies_held, i2d_body_create(w, maybe_null(in, def)), in.byte());
            break;
        }
        case 1: i2d_body_destroy(pick_body(in)); break;
        case 2: {
            const i2d_body_id b = pick_body(in);
            const i2d_vec2 p = in.vec2();
            const i2d_rot q = in.flag() ? i2d_make_rot(in.real()) : i2d_rot{in.real(), in.real()};
            i2d_body_set_transform(b, p, q);
            break;
        }
        case 3: i2d_body_set_linear_velocity(pick_body(in), in.vec2()); break;
        case 4: i2d_body_set_angular_velocity(pick_body(in), in.real()); break;
        case 5: i2d_body_apply_force(pick_body(in), in.vec2(), in.vec2(), in.flag()); break;
        case 6: i2d_body_apply_force_to_center(pick_body(in), in.vec2(), in.flag()); break;
        case 7: i2d_body_apply_torque(pick_body(in), in.real(), in.flag()); break;
        case 8: i2d_body_apply_linear_impulse(pick_body(in), in.vec2(), in.vec2(), in.flag()); break;
        case 9: i2d_body_apply_angular_impulse(pick_body(in), in.real(), in.flag()); break;
        case 10: i2d_body_set_awake(pick_body(in), in.flag()); break;
        case 11: i2d_body_set_user_data(pick_body(in), in.flag() ? g_held : nullptr); break;
        case 13: {
            // Mostly the three types, now and then any integer a C caller could pass.
            const int32_t type = in.byte() > 240 ? static_cast<int32_t>(in.u32()) : int32_t(in.byte() % 3);
            fuzz_body_set_type(pick_body(in).bits, type);
            break;
        }
        case 12: {
            const i2d_body_id b = pick_body(in);
            i2d_shape_id out[8];
            const int32_t capacity = in.flag() ? in.count(8) : static_cast<int32_t>(in.u32());
            const bool null_out = in.byte() > 230;
            i2d_body_get_shapes(b, null_out ? nullptr : out, capacity > 8 && !null_out ? 8 : capacity);
            break;
        }
        default: {
            const i2d_body_id b = pick_body(in);
            i2d_body_is_valid(b);
            i2d_body_get_world(b);
            i2d_body_get_type(b);
            i2d_body_get_rotation(b);
            if (!finite2(i2d_body_get_position(b))) {
                fail("non-finite body position", 0, 0);
            }
            i2d_body_get_mass(b);
            i2d_body_get_rotational_inertia(b);
            i2d_body_get_world_center_of_mass(b);
            i2d_body_get_local_center_of_mass(b);
            i2d_body_get_world_point(b, in.vec2());
            i2d_body_get_local_point(b, in.vec2());
            i2d_body_get_world_point_velocity(b, in.vec2());
            i2d_body_is_awake(b);
            i2d_body_is_quarantined(b);
            i2d_body_get_user_data(b);
            i2d_body_get_shape_count(b);
            check_body_finite(b);
            break;
        }
    }
}

void run_shape_call(FuzzInput& in, uint8_t op) {
    switch (op) {
        case 0: case 1: case 2: case 3: case 4: case 5: {
            const i2d_body_id b = pick_body(in);
            const i2d_shape_def def = shape_def(in);
            const i2d_shape_def* d = maybe_null(in, def);
            if (g_trace) {
                std::fprintf(stderr, "  shape def: density %g friction %g restitution %g rolling %g tangent %g\n",
                             def.density, def.friction, def.restitution, def.rolling_resistance, def.tangent_speed);
            }
            i2d_shape_id s = I2D_NULL_SHAPE_ID;
            if (op == 0) {
                const i2d_circle c{in.small_vec2(), in.small_real()};
                s = i2d_shape_create_circle(b, d, in.byte() < 245 ? &c : nullptr);
            } else if (op == 1) {
                s = i2d_shape_create_box(b, d, in.small_real(), in.small_real());
            } else if (op == 2) {
                const float hw = in.small_real(), hh = in.small_real();
                const i2d_vec2 center = in.small_vec2();
                s = i2d_shape_create_offset_box(b, d, hw, hh, center, i2d_make_rot(in.real()));
            } else if (op == 3) {
                i2d_vec2 points[10];
                for (auto& p : points) {
                    p = in.small_vec2();
                }
                const int32_t count = in.flag() ? in.count(10) : static_cast<int32_t>(in.u32());
                s = i2d_shape_create_polygon(b, d, in.byte() < 245 ? points : nullptr, count > 10 ? 10 : count);
            } else if (op == 4) {
                const i2d_polygon p = polygon(in);
                s = i2d_shape_create_polygon_from(b, d, in.byte() < 245 ? &p : nullptr);
            } else {
                const i2d_vec2 c1 = in.small_vec2(), c2 = in.small_vec2();
                if (g_trace) {
                    std::fprintf(stderr, "  capsule or segment (%a, %a) (%a, %a)\n", c1.x, c1.y, c2.x, c2.y);
                }
                s = in.flag() ? i2d_shape_create_capsule(b, d, c1, c2, in.small_real())
                              : i2d_shape_create_segment(b, d, c1, c2);
            }
            keep(g_held->shapes, g_held->shape_count, max_shapes_held, s, in.byte());
            break;
        }
        case 6: i2d_shape_destroy(pick_shape(in)); break;
        case 7: i2d_shape_set_friction(pick_shape(in), in.real()); break;
        case 8: i2d_shape_set_restitution(pick_shape(in), in.real()); break;
        case 9: i2d_shape_set_filter(pick_shape(in), filter(in)); break;
        case 10: i2d_shape_set_user_data(pick_shape(in), in.flag() ? g_held : nullptr); break;
        case 12: {  // a chain on any body, maybe destroyed at once, through a segment or its id
            i2d_vec2 points[12];
            for (auto& p : points) {
                p = in.flag() ? in.small_vec2() : in.vec2();
            }
            i2d_surface_material materials[9];
            for (auto& m : materials) {
                m = i2d_surface_material{in.real(), in.real(), in.real(), in.real()};
            }
            i2d_chain_def def = i2d_default_chain_def();
            def.points = in.byte() < 245 ? points : nullptr;
            const int32_t count = in.flag() ? in.count(12) : static_cast<int32_t>(in.u32());
            def.count = count > 12 ? 12 : count;
            def.is_loop = in.flag();
            def.materials = in.byte() < 245 ? materials : nullptr;
            // As many as the array holds at most: count() may say one more.
            const int32_t material_count = in.flag() ? in.count(9) : 0;
            def.material_count = material_count > 9 ? 9 : material_count;
            def.filter = filter(in);
            if (in.byte() > 250) {
                def.internal_cookie = in.u32();
            }
            const i2d_chain_id chain = i2d_chain_create(pick_body(in), &def);
            i2d_shape_id segments[12];
            const int32_t n = i2d_chain_get_segments(chain, segments, 12);
            if (n > 0) {
                keep(g_held->shapes, g_held->shape_count, max_shapes_held, segments[0], in.byte());
                i2d_shape_get_chain(segments[0]);
                i2d_shape_destroy(segments[0]);  // refused: a chain's segment
            }
            if (in.flag()) {
                i2d_chain_destroy(chain);
            }
            i2d_chain_is_valid(chain);
            break;
        }
        default: {
            const i2d_shape_id s = pick_shape(in);
            i2d_shape_is_valid(s);
            i2d_shape_get_body(s);
            i2d_shape_get_type(s);
            i2d_shape_get_circle(s);
            i2d_shape_get_polygon(s);
            i2d_shape_get_capsule(s);
            i2d_shape_get_segment(s);
            i2d_shape_get_aabb(s);
            i2d_shape_get_density(s);
            i2d_shape_get_friction(s);
            i2d_shape_get_restitution(s);
            i2d_shape_get_filter(s);
            i2d_shape_is_sensor(s);
            i2d_shape_get_user_data(s);
            break;
        }
    }
}

i2d_query_filter query_filter(FuzzInput& in) {
    i2d_query_filter f = i2d_default_query_filter();
    if (in.flag()) {
        f.category_bits = in.u64();
        f.mask_bits = in.u64();
    }
    return f;
}

// ---- Joints --------------------------------------------------------------------------

// Any kind's def (any_def), its defaults, cookie and create call, and where each kind's
// float settings are (k_def_floats, which create_joint sets to anything; bools it sets
// only to true or false, all a C caller can store in a bool) come from
// ../api/any_joint_def.h, shared with the C API's joint tests.

// The settings' setters, each taking a real.
using JointFloatSetter = i2d_status (*)(i2d_joint_id, float);
const JointFloatSetter joint_float_setters[] = {
    i2d_joint_set_force_threshold,          i2d_joint_set_torque_threshold,
    i2d_revolute_joint_set_reference_angle, i2d_revolute_joint_set_lower_angle,
    i2d_revolute_joint_set_upper_angle,     i2d_revolute_joint_set_motor_speed,
    i2d_revolute_joint_set_max_motor_torque, i2d_revolute_joint_set_hertz,
    i2d_revolute_joint_set_damping_ratio,   i2d_revolute_joint_set_target_angle,
    i2d_prismatic_joint_set_lower_translation, i2d_prismatic_joint_set_upper_translation,
    i2d_prismatic_joint_set_motor_speed,    i2d_prismatic_joint_set_max_motor_force,
    i2d_prismatic_joint_set_hertz,          i2d_prismatic_joint_set_target_translation,
    i2d_distance_joint_set_length,          i2d_distance_joint_set_min_length,
    i2d_distance_joint_set_max_length,      i2d_distance_joint_set_hertz,
    i2d_distance_joint_set_motor_speed,     i2d_distance_joint_set_max_motor_force,
    i2d_weld_joint_set_linear_hertz,        i2d_weld_joint_set_angular_hertz,
    i2d_weld_joint_set_angular_damping_ratio, i2d_wheel_joint_set_hertz,
    i2d_wheel_joint_set_lower_translation,  i2d_wheel_joint_set_motor_speed,
    i2d_wheel_joint_set_max_motor_torque,   i2d_motor_joint_set_angular_offset,
    i2d_motor_joint_set_max_force,          i2d_motor_joint_set_correction_factor,
    i2d_mouse_joint_set_hertz,              i2d_mouse_joint_set_max_force,
};
using JointFlagSetter = i2d_status (*)(i2d_joint_id, bool);
const JointFlagSetter joint_flag_setters[] = {
    i2d_joint_set_collide_connected,      i2d_revolute_joint_set_enable_limit, i2d_revolute_joint_set_enable_motor,
    i2d_revolute_joint_set_enable_spring, i2d_prismatic_joint_set_enable_limit, i2d_prismatic_joint_set_enable_motor,
    i2d_prismatic_joint_set_enable_spring, i2d_distance_joint_set_enable_limit, i2d_distance_joint_set_enable_spring,
    i2d_distance_joint_set_enable_motor,  i2d_wheel_joint_set_enable_spring,   i2d_wheel_joint_set_enable_limit,
    i2d_wheel_joint_set_enable_motor,
};
using JointVecSetter = i2d_status (*)(i2d_joint_id, i2d_vec2);
const JointVecSetter joint_vec_setters[] = {
    i2d_joint_set_local_anchor_a,        i2d_joint_set_local_anchor_b, i2d_prismatic_joint_set_local_axis_a,
    i2d_wheel_joint_set_local_axis_a,    i2d_motor_joint_set_linear_offset, i2d_mouse_joint_set_target,
};
using JointRangeSetter = i2d_status (*)(i2d_joint_id, float, float);
const JointRangeSetter joint_range_setters[] = {
    i2d_revolute_joint_set_limits, i2d_prismatic_joint_set_limits, i2d_wheel_joint_set_limits,
    i2d_distance_joint_set_length_range,
};

template <class T, size_t N>
constexpr int count_of(const T (&)[N]) {
    return int(N);
}

i2d_joint_id create_joint(FuzzInput& in) {
    const i2d_world_id w = pick_world(in);
    const i2d_joint_type kind = i2d_joint_type(in.byte() % JOINT_KIND_COUNT);
    const i2d_body_id body_a = pick_body(in);
    const i2d_body_id body_b = pick_body(in);
    any_def def = default_def(kind, body_a, body_b);
    i2d_joint_base& base = *base_of(&def);
    for (int edits = in.count(4); edits > 0; --edits) {
        switch (in.byte() % 6) {
            case 0: base.local_anchor_a = in.small_vec2(); base.local_anchor_b = in.small_vec2(); break;
            case 1: base.collide_connected = in.flag(); break;
            case 2: base.force_threshold = in.real(); base.torque_threshold = in.real(); break;
            case 3: *cookie_of(&def, kind) = in.u32(); break;
            default: {
                // Any float of the kind's settings, to anything.
                const def_float& f = k_def_floats[in.byte() % DEF_FLOAT_COUNT];
                if (f.kind == kind) {
                    set_def_float(&def, f.offset, in.real());
                }
                break;
            }
        }
    }
    const bool null_def = in.byte() >= 245;
    if (g_trace) {
        const i2d_body_id held_a = base.body_a, held_b = base.body_b;
        int a = -1, b = -1;
        for (int i = 0; i < g_held->body_count; ++i) {
            a = g_held->bodies[i].bits == held_a.bits ? i : a;
            b = g_held->bodies[i].bits == held_b.bits ? i : b;
        }
        std::fprintf(stderr, "  joint def: kind %d bodies %d %d anchors (%g, %g) (%g, %g) collide %d null %d\n",
                     int(kind), a, b, base.local_anchor_a.x, base.local_anchor_a.y, base.local_anchor_b.x,
                     base.local_anchor_b.y, int(base.collide_connected), int(null_def));
    }
    return create_any(w, kind, null_def ? nullptr : &def);
}

// Reads what a joint reports; on a live joint of a world of finite bodies every number
// must be finite.
void read_joint(i2d_joint_id j) {
    const bool live = i2d_joint_is_valid(j);
    i2d_joint_get_type(j);
    i2d_joint_get_world(j);
    i2d_joint_get_body_a(j);
    i2d_joint_get_body_b(j);
    i2d_joint_get_local_anchor_a(j);
    i2d_joint_get_user_data(j);
    const i2d_vec2 force = i2d_joint_get_reaction_force(j);
    const float measures[] = {
        i2d_joint_get_reaction_torque(j),         i2d_revolute_joint_get_angle(j),
        i2d_revolute_joint_get_motor_torque(j),   i2d_prismatic_joint_get_translation(j),
        i2d_prismatic_joint_get_speed(j),         i2d_prismatic_joint_get_motor_force(j),
        i2d_distance_joint_get_current_length(j), i2d_distance_joint_get_motor_force(j),
        i2d_wheel_joint_get_translation(j),       i2d_wheel_joint_get_motor_torque(j),
    };
    // The measured revolute angle and every angle the API stores wound lie in (-pi, pi]
    // (issue 44: a reference of 100 rad read back as 100 and measured -93.7); getters on
    // another kind's joint read 0.
    const float angles[] = {
        i2d_revolute_joint_get_angle(j),            i2d_revolute_joint_get_reference_angle(j),
        i2d_revolute_joint_get_target_angle(j),     i2d_prismatic_joint_get_reference_angle(j),
        i2d_weld_joint_get_reference_angle(j),      i2d_motor_joint_get_angular_offset(j),
    };
    if (!live) {
        return;
    }
    constexpr float pi_f = 3.14159265f;
    for (float angle : angles) {
        if (!(angle > -pi_f && angle <= pi_f)) {
            fail("a joint angle outside (-pi, pi]", angle, 0);
        }
    }
    if (!finite2(force)) {
        fail("non-finite joint reaction force", force.x, force.y);
    }
    for (float m : measures) {
        if (!std::isfinite(m)) {
            fail("non-finite joint measure", m, 0);
        }
    }
}

void run_joint_call(FuzzInput& in, uint8_t op) {
    switch (op) {
        case 0: case 1: {
            const i2d_joint_id j = create_joint(in);
            keep(g_held->joints, g_held->joint_count, max_joints_held, j, in.byte());
            break;
        }
        case 2: i2d_joint_destroy(pick_joint(in)); break;
        case 3: case 4: {
            const i2d_joint_id j = pick_joint(in);
            joint_float_setters[in.byte() % count_of(joint_float_setters)](j, in.real());
            break;
        }
        case 5: {
            const i2d_joint_id j = pick_joint(in);
            joint_flag_setters[in.byte() % count_of(joint_flag_setters)](j, in.flag());
            break;
        }
        case 6: {
            const i2d_joint_id j = pick_joint(in);
            joint_vec_setters[in.byte() % count_of(joint_vec_setters)](j, in.vec2());
            break;
        }
        case 7: {
            const i2d_joint_id j = pick_joint(in);
            const float lower = in.real();
            joint_range_setters[in.byte() % count_of(joint_range_setters)](j, lower, in.real());
            break;
        }
        case 8: i2d_joint_set_user_data(pick_joint(in), in.flag() ? g_held : nullptr); break;
        case 9: i2d_joint_wake_bodies(pick_joint(in)); break;
        case 10: {
            const i2d_world_id w = pick_world(in);
            const i2d_joint_events events = i2d_world_get_joint_events(w);
            i2d_world_get_joint_count(w);
            for (int32_t i = 0; i < events.count; ++i) {
                read_joint(events.events[i].joint);  // a breakable joint's listing
                if (in.flag()) {
                    i2d_joint_destroy(events.events[i].joint);
                }
            }
            break;
        }
        default: read_joint(pick_joint(in)); break;
    }
}

void run_query_call(FuzzInput& in, uint8_t op) {
    CallbackContext context{&in, 0};
    const i2d_world_id w = pick_world(in);
    const i2d_aabb box{in.vec2(), in.vec2()};
    switch (op) {
        case 0:
            i2d_world_overlap_aabb(w, box, query_filter(in), in.byte() < 245 ? overlap_callback : nullptr, &context);
            break;
        case 1:
            i2d_world_overlap_point(w, in.vec2(), query_filter(in), in.byte() < 245 ? overlap_callback : nullptr,
                                    &context);
            break;
        case 2: {
            i2d_shape_id out[16];
            const int32_t capacity = in.flag() ? in.count(16) : static_cast<int32_t>(in.u32());
            const bool null_out = in.byte() > 230;
            i2d_world_overlap_aabb_ids(w, box, query_filter(in), null_out ? nullptr : out,
                                       capacity > 16 && !null_out ? 16 : capacity);
            break;
        }
        case 3: {
            const i2d_vec2 origin = in.vec2(), translation = in.vec2();
            const i2d_ray_result r = i2d_world_cast_ray_closest(w, origin, translation, query_filter(in));
            check_cast_length(translation, i2d_last_status());
            if (r.hit && (!finite2(r.point) || !finite2(r.normal))) {
                fail("non-finite closest ray hit", r.point.x, r.fraction);
            }
            if (r.hit) {
                check_unit_normal(r.normal, "a closest ray hit's normal is not unit");
            }
            break;
        }
        case 5: {  // shape casts and overlaps with a proxy made from hostile points
            i2d_vec2 points[9];
            for (auto& p : points) {
                p = in.flag() ? in.small_vec2() : in.vec2();
            }
            const int32_t count = in.flag() ? in.count(9) : static_cast<int32_t>(in.u32());
            i2d_shape_proxy proxy = i2d_make_proxy(in.byte() < 245 ? points : nullptr, count > 9 ? 9 : count,
                                                   in.real());
            if (in.byte() > 240) {
                proxy.count = static_cast<int32_t>(in.u32());  // a hand-made proxy, maybe broken
                proxy.radius = in.real();
            }
            if (in.flag()) {
                const i2d_vec2 translation = in.vec2();
                const i2d_ray_result r = i2d_world_cast_shape_closest(w, &proxy, translation, query_filter(in));
                check_cast_length(translation, i2d_last_status());
                if (r.hit && (!finite2(r.point) || !finite2(r.normal) || !(r.fraction >= 0.0f && r.fraction <= 1.0f))) {
                    fail("non-finite closest shape cast", r.point.x, r.fraction);
                }
                if (r.hit) {
                    check_unit_normal(r.normal, "a closest shape cast's normal is not unit");
                }
                const i2d_vec2 swept = in.vec2();
                const i2d_query_filter f = query_filter(in);
                check_cast_length(swept, i2d_world_cast_shape(w, &proxy, swept, f,
                                                             in.byte() < 245 ? ray_callback : nullptr, &context));
            } else {
                i2d_shape_id out[16];
                // count() may say 17 (one past its limit), which this buffer cannot take.
                const int32_t capacity = in.count(16);
                i2d_world_overlap_shape_ids(w, in.byte() < 245 ? &proxy : nullptr, query_filter(in), out,
                                            capacity > 16 ? 16 : capacity);
                i2d_world_overlap_shape(w, &proxy, query_filter(in), in.byte() < 245 ? overlap_callback : nullptr,
                                        &context);
            }
            break;
        }
        case 6: {  // the array variants of rays and points
            i2d_ray_result hits[16];
            const int32_t capacity = in.flag() ? in.count(16) : static_cast<int32_t>(in.u32());
            const bool null_out = in.byte() > 230;
            const i2d_vec2 origin = in.vec2(), translation = in.vec2();
            const i2d_query_filter f = query_filter(in);
            i2d_world_cast_ray_all(w, origin, translation, f, null_out ? nullptr : hits,
                                   capacity > 16 && !null_out ? 16 : capacity);
            check_cast_length(translation, i2d_last_status());
            for (int32_t i = 0; i < (capacity < 16 ? capacity : 16) && !null_out; ++i) {
                i2d_shape_is_valid(hits[i].shape);
            }
            i2d_shape_id ids[16];
            // count() may say 17 (one past its limit), which this buffer cannot take.
            const int32_t id_capacity = in.count(16);
            i2d_world_overlap_point_ids(w, in.vec2(), query_filter(in), ids, id_capacity > 16 ? 16 : id_capacity);
            break;
        }
        default: {
            const i2d_vec2 origin = in.vec2(), translation = in.vec2();
            const i2d_query_filter f = query_filter(in);
            check_cast_length(translation, i2d_world_cast_ray(w, origin, translation, f,
                                                              in.byte() < 245 ? ray_callback : nullptr, &context));
            break;
        }
    }
}

// The world-free functions: any input, never a crash.
void run_pure_call(FuzzInput& in, uint8_t op) {
    const i2d_circle circle{in.vec2(), in.real()};
    const i2d_capsule capsule{in.vec2(), in.vec2(), in.real()};
    const i2d_segment segment{in.vec2(), in.vec2()};
    const i2d_polygon poly = polygon(in);
    const i2d_transform xfa = transform(in), xfb = transform(in);
    switch (op) {
        case 0: i2d_collide_circles(circle, i2d_circle{in.vec2(), in.real()}); break;
        case 1: i2d_collide_aabbs(i2d_aabb{in.vec2(), in.vec2()}, i2d_aabb{in.vec2(), in.vec2()}); break;
        case 2: i2d_collide_aabb_circle(i2d_aabb{in.vec2(), in.vec2()}, circle); break;
        case 3: i2d_collide_capsule_circle(&capsule, xfa, &circle, xfb); break;
        case 4: i2d_collide_segment_circle(&segment, xfa, &circle, xfb); break;
        case 5: i2d_collide_polygon_circle(&poly, xfa, in.flag() ? &circle : nullptr, xfb); break;
        case 6: i2d_collide_capsules(&capsule, xfa, &capsule, xfb); break;
        case 7: i2d_collide_segment_capsule(&segment, xfa, &capsule, xfb); break;
        case 8: i2d_collide_polygon_capsule(&poly, xfa, &capsule, xfb); break;
        case 9: i2d_collide_segment_polygon(&segment, xfa, &poly, xfb); break;
        case 10: i2d_collide_polygons(&poly, xfa, in.flag() ? &poly : nullptr, xfb); break;
        case 11: i2d_compute_circle_mass(&circle, in.real()); break;
        case 12: i2d_compute_capsule_mass(&capsule, in.real()); break;
        case 13: i2d_compute_polygon_mass(in.flag() ? &poly : nullptr, in.real()); break;
        case 14: i2d_ray_cast_circle(&circle, xfa, in.vec2(), in.vec2()); break;
        case 15: i2d_ray_cast_capsule(&capsule, xfa, in.vec2(), in.vec2()); break;
        case 16: i2d_ray_cast_segment(&segment, xfa, in.vec2(), in.vec2()); break;
        case 17: i2d_ray_cast_polygon(&poly, xfa, in.vec2(), in.vec2()); break;
        case 18: i2d_make_offset_box(in.real(), in.real(), in.vec2(), i2d_rot{in.real(), in.real()}); break;
        default: {
            i2d_rot_get_angle(i2d_rot{in.real(), in.real()});
            const i2d_rot q = i2d_make_rot(in.real());
            i2d_version();
            i2d_last_status();
            i2d_last_error_message();
            if (!std::isfinite(q.c) || !std::isfinite(q.s)) {
                // i2d_make_rot refuses non-finite angles with the identity.
                fail("i2d_make_rot returned a non-finite rotation", q.c, q.s);
            }
            break;
        }
    }
}

// Joint calls take the body group's second alias from this sub on (opcodes 2 + 6 * 30
// and up; 13 calls), so that earlier programs keep their meaning but for those opcodes.
constexpr uint8_t joint_sub_first = 30;

#include "fuzz_runtime_calls.inl"
#include "fuzz_draw_calls.inl"
#include "fuzz_hook_calls.inl"
#include "fuzz_mover_calls.inl"

// Query-group instructions: the character mover in [mover_sub_first, draw_sub_first), debug
// draws in [draw_sub_first, hook_sub_first), contact hook and explosion calls from
// hook_sub_first on.
constexpr uint8_t mover_sub_first = 14;
constexpr uint8_t draw_sub_first = 24;
constexpr uint8_t hook_sub_first = 34;

// Shape instructions from this sub-opcode on are runtime API calls.
constexpr uint8_t runtime_sub_first = 26;

void run_program(FuzzInput& in) {
    int steps_left = 64;  // bounds the run time of one input
    while (!in.empty()) {
        const uint8_t op = in.byte();
        const uint8_t group = op % 6;
        const uint8_t sub = static_cast<uint8_t>(op / 6);
        if (g_trace) {
            std::fprintf(stderr, "last status %s %s\nop group %d sub %d\n", i2d_status_string(i2d_last_status()),
                         i2d_last_error_message(), group, sub);
            trace_bodies();
        }
        if (group == 0) {
            if ((sub % 7 == 2 || sub % 7 == 6) && --steps_left < 0) {
                continue;
            }
            run_world_call(in, sub % 7);
        } else if (group == 2 && sub >= joint_sub_first) {
            run_joint_call(in, static_cast<uint8_t>(sub - joint_sub_first));
        } else if (group == 1 || group == 2) {
            run_body_call(in, sub % 15);
        } else if (group == 3 && sub >= runtime_sub_first) {
            run_runtime_call(in, sub);
        } else if (group == 3) {
            run_shape_call(in, sub % 13);
        } else if (group == 4 && sub >= hook_sub_first) {
            run_hook_call(in, sub);
        } else if (group == 4 && sub >= draw_sub_first) {
            run_draw_call(in, sub);
        } else if (group == 4 && sub >= mover_sub_first) {
            run_mover_call(in, sub);
        } else if (group == 4) {
            run_query_call(in, sub % 7);
        } else {
            run_pure_call(in, sub % 20);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Held held;
    g_held = &held;
    FuzzInput in(data, size);
    g_in = &in;
    run_program(in);
    check_all_finite();
    for (int i = 0; i < held.created_count; ++i) {
        i2d_world_destroy(held.created[i]);  // live ones are freed, destroyed ones refused
    }
    g_held = nullptr;
    g_in = nullptr;
    return 0;
}
