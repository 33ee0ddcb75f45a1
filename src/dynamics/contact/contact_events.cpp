// SPDX-License-Identifier: MIT
// ContactSet: the end of the step: begin, end and hit events, and the contacts whose
// fat boxes parted destroyed.
#include "collision/manifold.hpp"
#include "core/prefetch.hpp"
#include "dynamics/contact/contact_set.hpp"

namespace i2d {

namespace {

// A sensor reports overlap only: its gaps (speculative points) do not count.
Manifold without_speculative_points(Manifold m) {
    int32_t kept = 0;
    for (int32_t i = 0; i < m.point_count; ++i) {
        if (m.points[i].penetration >= 0.0f) {
            m.points[kept++] = m.points[i];
        }
    }
    m.point_count = kept;
    return m;
}

}  // namespace

PendingEnd ContactSet::pair_of(const Contact& c) const {
    const bool sensor_is_b = (c.flags & contact_sensor) != 0 && !shapes_[c.shape_a].is_sensor;
    const int32_t first = sensor_is_b ? c.shape_b : c.shape_a, second = sensor_is_b ? c.shape_a : c.shape_b;
    return {first, second, shapes_.generation(first), shapes_.generation(second)};
}

ShapePairEvent ContactSet::event_of(const Contact& c) const {
    const PendingEnd pair = pair_of(c);
    return {events_.ids.shape_id(pair.shape_a, pair.generation_a), events_.ids.shape_id(pair.shape_b, pair.generation_b)};
}

// The contact's manifold as a begin event shows it: world points where A's anchors are.
Manifold ContactSet::manifold_of(const Contact& c) const {
    Manifold m;
    m.normal = c.normal;
    m.point_count = c.point_count;
    const Vec2 center_a = bodies_[c.edges[0].body].center;
    for (int32_t i = 0; i < c.point_count; ++i) {
        m.points[i].point = center_a + c.points[i].anchor_a;
        m.points[i].penetration = -c.points[i].separation;
        m.points[i].id = c.point_ids[i];
    }
    return m;
}

// Events compare the end of the step with its start, so that applying a step's begin
// events and then its end events always gives the true final state.
void ContactSet::report_touch_changes(const Contact& c, bool touching_now) {
    if ((c.flags & contact_report_events) == 0) {
        return;
    }
    const bool at_start = (c.flags & contact_touching_at_start) != 0;
    const bool sensor = (c.flags & contact_sensor) != 0;
    WorldEvents& e = events_.current;
    if (!at_start && touching_now) {
        if (sensor) {
            e.sensor_begin.push_back(event_of(c));
        } else {
            const ShapePairEvent pair = event_of(c);
            e.contact_begin.push_back({pair.shape_a, pair.shape_b, manifold_of(c)});
        }
    }
    if (at_start && !touching_now) {
        (sensor ? e.sensor_end : e.contact_end).push_back(event_of(c));
    }
}

// A sensor overlap is tested afresh where the step left the bodies, by the workers; the
// contacts to destroy or report on are flagged, and one thread then acts on them
// backwards, because destroying a contact moves the last awake contact into its place.
void ContactSet::end_step(const StepContext& step) {
    const int32_t count = int32_t(awake_.size());
    collide_flags_.resize(std::size_t(count));
    run_over_awake<&ContactSet::end_range>(step);
    for (int32_t k = count - 1; k >= 0; --k) {
        const uint8_t flags = collide_flags_[std::size_t(k)];
        if (flags == 0) {
            continue;
        }
        const int32_t index = awake_[std::size_t(k)];
        if (flags & hits) {
            report_hit(pool_[index]);
        }
        if (flags & ends) {
            destroy_contact(index, true);
        } else if (flags & reports) {
            report_touch_changes(pool_[index], (pool_[index].flags & contact_touching) != 0);
        }
    }
}

void ContactSet::end_range(const StepContext& step, ContactSet& self, const NoStageArg&, int32_t begin, int32_t end,
                           int32_t) {
    // A short pass over contacts in no order: the line of the flags and the hit speed is
    // asked for well ahead.
    constexpr int32_t contacts_ahead = 16;
    for (int32_t k = begin; k < end; ++k) {
        if (k + contacts_ahead < end) {
            prefetch_line(&self.pool_[self.awake_[std::size_t(k + contacts_ahead)]].flags);
        }
        Contact& c = self.pool_[self.awake_[std::size_t(k)]];
        uint8_t flags = 0;
        if (c.flags & contact_disjoint) {
            flags = ends;
        } else {
            if (!is_solid(c)) {
                const Shape& a = self.shapes_[c.shape_a];
                const Shape& b = self.shapes_[c.shape_b];
                const Manifold m = without_speculative_points(collide_shapes(
                    a.geometry, self.bodies_[a.body].transform, b.geometry, self.bodies_[b.body].transform,
                    step.tolerances.speculative_distance, step.tolerances.linear_slop));
                c.flags |= m.point_count > 0 ? uint32_t(contact_touching) : 0u;
            }
            const bool at_start = (c.flags & contact_touching_at_start) != 0;
            const bool now = (c.flags & contact_touching) != 0;
            flags = (c.flags & contact_report_events) && at_start != now ? reports : 0;
        }
        flags |= c.hit_speed > step.settings.hit_event_threshold ? hits : 0;
        self.collide_flags_[std::size_t(k)] = flags;
    }
}

void ContactSet::report_hit(const Contact& c) {
    const ShapePairEvent pair = event_of(c);
    const Vec2 point = bodies_[c.edges[0].body].center + c.points[c.hit_point].anchor_a;
    events_.current.contact_hits.push_back({pair.shape_a, pair.shape_b, point, c.normal, c.hit_speed});
}

}  // namespace i2d
