// SPDX-License-Identifier: MIT
// i2d_worlds_get_body_states, i2d_worlds_set_body_velocities and
// i2d_worlds_get_contact_event_counts: the bulk state calls across worlds, for a batch of
// environments that reads and writes one body of each of hundreds of worlds a frame.
//
// As in bulk_state_api.cpp, every id and value is checked before anything is written, so
// a refused call leaves the caller's arrays and every world as they were; the ids are
// decoded again for the writes rather than kept (no allocation per call), and the writes
// go through the same World setters as the per-body calls.
#include "boundary.hpp"
#include "bulk_checks.hpp"
#include "convert.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// Every id a live body of a live world (and, to write, of an unlocked one).
bool valid_bodies(Call& call, const i2d_body_id* bodies, int32_t count, bool writing) {
    if (!valid_count(call, count, bodies, "bodies")) {
        return false;
    }
    for (int32_t i = 0; i < count; ++i) {
        BodyRef b;
        if (!call.body(bodies[i], b) || (writing && !call.unlocked(*b.world))) {
            return call.fail_in(ElementName("bodies", i).text);
        }
    }
    return true;
}

// The body an id that valid_bodies accepted names.
BodyRef checked_body(Call& call, i2d_body_id id) {
    BodyRef b;
    call.body(id, b);
    return b;
}

}  // namespace

I2D_API i2d_status i2d_worlds_get_body_states(const i2d_body_id* bodies, int32_t count, i2d_transform* transforms,
                                              i2d_vec2* linear, float* angular, bool* awake) {
    return guarded("i2d_worlds_get_body_states", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        if (!valid_bodies(call, bodies, count, false)) {
            return last_status();
        }
        for (int32_t i = 0; i < count; ++i) {
            const BodyRef b = checked_body(call, bodies[i]);
            const Body& body = b.body();
            if (transforms != nullptr) {
                transforms[i] = to_public(body.transform);
            }
            if (linear != nullptr) {
                linear[i] = to_public(body.linear_velocity);
            }
            if (angular != nullptr) {
                angular[i] = body.angular_velocity;
            }
            if (awake != nullptr) {
                awake[i] = b.world->is_awake(b.index);
            }
        }
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_worlds_set_body_velocities(const i2d_body_id* bodies, int32_t count, const i2d_vec2* linear,
                                                  const float* angular) {
    return guarded("i2d_worlds_set_body_velocities", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        if (!valid_bodies(call, bodies, count, true) || !valid_velocities(call, count, linear, angular)) {
            return last_status();
        }
        for (int32_t i = 0; i < count; ++i) {
            const BodyRef b = checked_body(call, bodies[i]);
            if (linear != nullptr) {
                b.world->set_linear_velocity(b.index, capi::to_core(linear[i]));
            }
            if (angular != nullptr) {
                b.world->set_angular_velocity(b.index, angular[i]);
            }
        }
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_worlds_get_contact_event_counts(const i2d_world_id* worlds, int32_t count,
                                                        int32_t* begin_counts, int32_t* end_counts) {
    return guarded("i2d_worlds_get_contact_event_counts", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        if (!valid_count(call, count, worlds, "worlds")) {
            return last_status();
        }
        for (int32_t i = 0; i < count; ++i) {
            WorldRef w;
            if (!call.world(worlds[i], w)) {
                call.fail_in(ElementName("worlds", i).text);
                return last_status();
            }
        }
        for (int32_t i = 0; i < count; ++i) {
            WorldRef w;
            call.world(worlds[i], w);
            const WorldEvents& events = w.world->events();
            if (begin_counts != nullptr) {
                begin_counts[i] = int32_t(events.contact_begin.size());
            }
            if (end_counts != nullptr) {
                end_counts[i] = int32_t(events.contact_end.size());
            }
        }
        return I2D_OK;
    });
}
