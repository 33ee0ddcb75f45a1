// SPDX-License-Identifier: MIT
// ContactSet: what touches what as the last step left it, read between steps (the C
// API's contact data and sensor overlaps).
//
// Both walk one body's contact list, not the pool: a body has a handful of contacts, a
// world may have a million. They read only, so that a query's callback may call them.
#include "dynamics/contact/contact_set.hpp"

namespace i2d {

namespace {

// Touching as the events see it: within the slop when the last step ended (the solver's
// flag), a sensor's overlap excluded.
bool touches(const Contact& c) { return (c.flags & (contact_touching | contact_sensor)) == contact_touching; }

bool involves(const Contact& c, int32_t shape) { return c.shape_a == shape || c.shape_b == shape; }

}  // namespace

// The manifold is the begin event's (manifold_of), so that the two never disagree on
// where a point is; the impulses are those the solver stored at the end of the step.
void ContactSet::visit_touching(int32_t body, int32_t shape, FunctionRef<void(const ContactData&)> visit) const {
    visit_contacts(body, [&](int32_t index, int32_t) {
        const Contact& c = pool_[index];
        if (!touches(c) || (shape != null_index && !involves(c, shape))) {
            return;
        }
        ContactData data;
        data.shape_a = c.shape_a;
        data.shape_b = c.shape_b;
        data.manifold = manifold_of(c);
        for (int32_t i = 0; i < c.point_count; ++i) {
            data.normal_impulses[i] = c.points[i].normal_impulse;
            data.tangent_impulses[i] = c.points[i].tangent_impulse;
        }
        visit(data);
    });
}

// A visit's begin event came when its contact began touching with events reported, and
// its end comes when it stops touching or goes: the visits now open are exactly the
// reporting sensor contacts that touch.
void ContactSet::visit_sensor_visitors(int32_t sensor, FunctionRef<void(int32_t visitor)> visit) const {
    visit_contacts(shapes_[sensor].body, [&](int32_t index, int32_t) {
        const Contact& c = pool_[index];
        const uint32_t open = contact_sensor | contact_touching | contact_report_events;
        if ((c.flags & open) == open && involves(c, sensor)) {
            visit(c.shape_a == sensor ? c.shape_b : c.shape_a);
        }
    });
}

}  // namespace i2d
