// SPDX-License-Identifier: MIT
// i2d_world_get_*_events: the world's event arrays, handed out without a copy.
#include <cstddef>

#include "boundary.hpp"

using namespace i2d;
using namespace i2d::capi;

// The core's event records are the public structs, byte for byte.
static_assert(sizeof(ContactBeginEvent) == sizeof(i2d_contact_begin_event), "event layout");
static_assert(offsetof(ContactBeginEvent, manifold) == offsetof(i2d_contact_begin_event, manifold), "event layout");
static_assert(sizeof(Manifold) == sizeof(i2d_manifold), "event layout");
static_assert(offsetof(Manifold, points) == offsetof(i2d_manifold, points), "event layout");
static_assert(sizeof(ShapePairEvent) == sizeof(i2d_contact_end_event), "event layout");
static_assert(sizeof(ShapePairEvent) == sizeof(i2d_sensor_begin_event), "event layout");
static_assert(sizeof(ShapePairEvent) == sizeof(i2d_sensor_end_event), "event layout");
static_assert(offsetof(ContactBeginEvent, shape_b) == offsetof(i2d_contact_begin_event, shape_b), "event layout");
static_assert(offsetof(ShapePairEvent, shape_b) == offsetof(i2d_sensor_begin_event, visitor_shape), "event layout");
static_assert(sizeof(BodyMoveEvent) == sizeof(i2d_body_move_event), "event layout");
static_assert(sizeof(ContactHitEvent) == sizeof(i2d_contact_hit_event), "event layout");
static_assert(offsetof(ContactHitEvent, point) == offsetof(i2d_contact_hit_event, point), "event layout");
static_assert(offsetof(ContactHitEvent, normal) == offsetof(i2d_contact_hit_event, normal), "event layout");
static_assert(offsetof(ContactHitEvent, approach_speed) == offsetof(i2d_contact_hit_event, approach_speed),
              "event layout");
static_assert(offsetof(BodyMoveEvent, body) == offsetof(i2d_body_move_event, body), "event layout");
static_assert(offsetof(BodyMoveEvent, user_data) == offsetof(i2d_body_move_event, user_data), "event layout");
static_assert(offsetof(BodyMoveEvent, fell_asleep) == offsetof(i2d_body_move_event, fell_asleep), "event layout");

static_assert(sizeof(BodyQuarantineEvent) == sizeof(i2d_body_quarantine_event), "event layout");
static_assert(offsetof(BodyQuarantineEvent, body) == offsetof(i2d_body_quarantine_event, body), "event layout");
static_assert(offsetof(BodyQuarantineEvent, user_data) == offsetof(i2d_body_quarantine_event, user_data),
              "event layout");
static_assert(offsetof(BodyQuarantineEvent, former_type) == offsetof(i2d_body_quarantine_event, former_type),
              "event layout");
static_assert(int32_t(BodyType::static_body) == I2D_BODY_STATIC && int32_t(BodyType::kinematic) == I2D_BODY_KINEMATIC &&
                  int32_t(BodyType::dynamic) == I2D_BODY_DYNAMIC,
              "a quarantine event's former type is the public enum's value");

namespace {

template <class Public, class Core>
const Public* as_public(const std::vector<Core>& events) {
    return events.empty() ? nullptr : reinterpret_cast<const Public*>(events.data());
}

}  // namespace

I2D_API i2d_contact_events i2d_world_get_contact_events(i2d_world_id id) {
    return guarded("i2d_world_get_contact_events", i2d_contact_events{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return i2d_contact_events{};
        }
        const WorldEvents& e = w.world->events();
        return i2d_contact_events{as_public<i2d_contact_begin_event>(e.contact_begin), int32_t(e.contact_begin.size()),
                                  as_public<i2d_contact_end_event>(e.contact_end), int32_t(e.contact_end.size()),
                                  as_public<i2d_contact_hit_event>(e.contact_hits), int32_t(e.contact_hits.size())};
    });
}

I2D_API i2d_sensor_events i2d_world_get_sensor_events(i2d_world_id id) {
    return guarded("i2d_world_get_sensor_events", i2d_sensor_events{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return i2d_sensor_events{};
        }
        const WorldEvents& e = w.world->events();
        return i2d_sensor_events{as_public<i2d_sensor_begin_event>(e.sensor_begin), int32_t(e.sensor_begin.size()),
                                 as_public<i2d_sensor_end_event>(e.sensor_end), int32_t(e.sensor_end.size())};
    });
}

I2D_API i2d_body_events i2d_world_get_body_events(i2d_world_id id) {
    return guarded("i2d_world_get_body_events", i2d_body_events{}, [&](Call& call) {
        WorldRef w;
        if (!call.world(id, w)) {
            return i2d_body_events{};
        }
        const WorldEvents& e = w.world->events();
        return i2d_body_events{as_public<i2d_body_move_event>(e.body_moves), int32_t(e.body_moves.size()),
                               as_public<i2d_body_quarantine_event>(e.body_quarantines),
                               int32_t(e.body_quarantines.size())};
    });
}
