// SPDX-License-Identifier: MIT
// i2d_body_get_contact_data, i2d_shape_get_contact_data, i2d_shape_get_sensor_overlaps:
// what touches what as the last step left it, copied into the caller's arrays.
//
// They are getters: they read the world and never change it, so they skip the lock check
// and work inside query callbacks.
#include "boundary.hpp"
#include "convert.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

bool valid_out(Call& call, const void* out, int32_t capacity) {
    if (capacity < 0 || (capacity > 0 && out == nullptr)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", int(capacity));
    }
    return true;
}

i2d_shape_id shape_id(const World& world, const IdFields& id, int32_t shape) {
    return make_shape_id(id, shape, world.shapes().generation(shape));
}

i2d_contact_data to_public(const World& world, const IdFields& id, const ContactData& c) {
    i2d_contact_data out{};
    out.shape_a = shape_id(world, id, c.shape_a);
    out.shape_b = shape_id(world, id, c.shape_b);
    out.manifold = capi::to_public(c.manifold);
    for (int32_t i = 0; i < c.manifold.point_count; ++i) {
        out.normal_impulses[i] = c.normal_impulses[i];
        out.tangent_impulses[i] = c.tangent_impulses[i];
    }
    return out;
}

// Counts every touching contact of the body (or of one of its shapes) and copies the
// first `capacity` of them.
int32_t copy_contact_data(const World& world, const IdFields& id, int32_t body, int32_t shape, i2d_contact_data* out,
                          int32_t capacity) {
    int32_t count = 0;
    world.visit_touching_contacts(body, shape, [&](const ContactData& c) {
        if (count < capacity) {
            out[count] = to_public(world, id, c);
        }
        ++count;
    });
    return count;
}

}  // namespace

I2D_API int32_t i2d_body_get_contact_data(i2d_body_id id, i2d_contact_data* out, int32_t capacity) {
    return guarded("i2d_body_get_contact_data", int32_t(0), [&](Call& call) -> int32_t {
        BodyRef b;
        if (!call.body(id, b) || !valid_out(call, out, capacity)) {
            return 0;
        }
        return copy_contact_data(*b.world, b.id, b.index, null_index, out, capacity);
    });
}

I2D_API int32_t i2d_shape_get_contact_data(i2d_shape_id id, i2d_contact_data* out, int32_t capacity) {
    return guarded("i2d_shape_get_contact_data", int32_t(0), [&](Call& call) -> int32_t {
        ShapeRef s;
        if (!call.shape(id, s) || !valid_out(call, out, capacity)) {
            return 0;
        }
        return copy_contact_data(*s.world, s.id, s.shape().body, s.index, out, capacity);
    });
}

I2D_API int32_t i2d_shape_get_sensor_overlaps(i2d_shape_id sensor, i2d_shape_id* out, int32_t capacity) {
    return guarded("i2d_shape_get_sensor_overlaps", int32_t(0), [&](Call& call) -> int32_t {
        ShapeRef s;
        if (!call.shape(sensor, s) || !valid_out(call, out, capacity)) {
            return 0;
        }
        if (!s.shape().is_sensor) {
            call.fail(I2D_ERR_INVALID_ARGUMENT,
                      "the shape is not a sensor: only sensors have visitors (use i2d_shape_get_contact_data)");
            return 0;
        }
        int32_t count = 0;
        s.world->visit_sensor_overlaps(s.index, [&](int32_t visitor) {
            if (count < capacity) {
                out[count] = shape_id(*s.world, s.id, visitor);
            }
            ++count;
        });
        return count;
    });
}
