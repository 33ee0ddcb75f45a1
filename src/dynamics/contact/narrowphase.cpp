// SPDX-License-Identifier: MIT
// ContactSet: the narrowphase over the awake contacts, and the links it changes.
#include <cmath>

#include "collision/manifold.hpp"
#include "core/assert.hpp"
#include "core/prefetch.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// Whether the body starts the step fast (is_fast_travel on the velocity it starts with),
// so that the continuous stage will sweep it unless the step slows it down, and free: a
// body held by joints keeps its speculative reach, since moving it alone back to its
// time of impact would pull its joints apart (a heap of 100 ragdolls dropped from up to
// 20 m opened joint gaps of 11 cm).
bool starts_fast_and_free(const Body& b, float time_step) {
    return b.type == BodyType::dynamic &&
           is_fast_travel(b, time_step * (length(b.linear_velocity) + std::fabs(b.angular_velocity) * b.max_extent)) &&
           b.joint_count == 0;
}

// How far apart the two shapes may be and still meet within the step: the world's
// speculative distance plus how far their surfaces can approach in one step (relative
// speed, and spin times extent). Contacts within it get points the solver can stop at.
// Except where the continuous stage takes the impact: a fast free body and what it is
// swept against (continuous.hpp) meet at their time of impact, where the impact is solved
// (impact.hpp), so their contact keeps the world's speculative distance (Box2D v3's).
// A point from farther away is a poor guide: its normal, taken where the step starts,
// may be a corner's that the body never reaches (a ball 4 m from a wall's end was
// stopped 14 cm short of the wall's face and sent off sideways), and its anchor, midway
// between the shapes, turns with the body by as much (a spinning ball's contact saw the
// gap grow as it closed, and let the ball through its face at speed).
float speculative_margin(const Body& a, const Body& b, const StepContext& step) {
    const float approach = length(b.linear_velocity - a.linear_velocity) +
                           std::fabs(a.angular_velocity) * a.max_extent + std::fabs(b.angular_velocity) * b.max_extent;
    const float reach = step.time_step * approach;
    if (step.settings.enable_continuous && reach > 0.0f &&
        ((is_swept_against(a, b) && starts_fast_and_free(a, step.time_step)) ||
         (is_swept_against(b, a) && starts_fast_and_free(b, step.time_step)))) {
        return step.tolerances.speculative_distance;
    }
    return step.tolerances.speculative_distance + reach;
}

bool is_moving(const Body& b) {
    return b.awake_index != null_index &&
           (b.linear_velocity.x != 0.0f || b.linear_velocity.y != 0.0f || b.angular_velocity != 0.0f);
}

bool is_asleep(const Body& b) { return b.island != null_index && b.awake_index == null_index; }

}  // namespace

// Once per step over the awake contacts. A contact whose fat boxes stopped overlapping
// stops touching and is destroyed at the end of the step, so that a pair never has two
// contacts (and two event histories) in one step. A contact that gains or loses points
// against a sleeping body wakes it (something arrived or left), as does one whose other
// body moves (a kinematic platform set going). Touching is cleared here and set again
// by the solver for the contacts that end the step within the slop.
void ContactSet::collide(const StepContext& step) {
    islands_to_wake_.clear();
    point_changes_.clear();
    const int32_t count = int32_t(awake_.size());
    collide_flags_.resize(std::size_t(count));
    run_over_awake<&ContactSet::collide_range>(step);

    bool layout_change = false;
    solvable_.clear();
    for (int32_t k = 0; k < count; ++k) {
        const uint8_t flags = collide_flags_[std::size_t(k)];
        if (flags == 0) {
            continue;
        }
        layout_change = layout_change || (flags & layout_changed) != 0;
        const int32_t index = awake_[std::size_t(k)];
        if (flags & has_points) {
            solvable_.push_back(index);
        }
        const Contact& c = pool_[index];
        for (int32_t e = 0; e < 2; ++e) {
            if (flags & (e == 0 ? wakes_a : wakes_b)) {
                islands_to_wake_.push_back(bodies_[c.edges[e].body].island);
            }
        }
        if (flags & points_changed) {
            point_changes_.push_back(index);
        }
    }
    layout_version_ += layout_change ? 1u : 0u;
}

// The awake list is in no spatial order: the contacts (and their shapes and bodies)
// it names next are asked for ahead, so that their cache misses overlap. Forced inline:
// a const function that only prefetches looks pure to GCC, which dropped every call.
I2D_FORCE_INLINE void ContactSet::prefetch_for_collide(int32_t k, int32_t count) const {
    constexpr int32_t contacts_ahead = 12, neighbours_ahead = 6;
    if (k + contacts_ahead < count) {
        prefetch_object(pool_[awake_[std::size_t(k + contacts_ahead)]]);
    }
    if (k + neighbours_ahead < count) {
        const Contact& c = pool_[awake_[std::size_t(k + neighbours_ahead)]];
        prefetch_line(&shapes_[c.shape_a]);
        prefetch_line(&shapes_[c.shape_b]);
        prefetch_object(bodies_[c.edges[0].body]);
        prefetch_object(bodies_[c.edges[1].body]);
    }
}

void ContactSet::collide_range(const StepContext& step, ContactSet& self, const NoStageArg&, int32_t begin,
                               int32_t end, int32_t) {
    const int32_t count = int32_t(self.awake_.size());
    for (int32_t k = begin; k < end; ++k) {
        self.prefetch_for_collide(k, end < count ? end : count);
        self.collide_flags_[std::size_t(k)] = self.collide_one(k, step);
    }
}

// Updates the k-th awake contact, writing only to it; returns its CollideFlags.
uint8_t ContactSet::collide_one(int32_t k, const StepContext& step) {
    Contact& c = pool_[awake_[std::size_t(k)]];
    const uint32_t at_start = (c.flags & contact_touching) ? uint32_t(contact_touching_at_start) : 0u;
    c.flags = (c.flags & ~uint32_t(contact_touching | contact_touching_at_start)) | at_start;
    const Shape& a = shapes_[c.shape_a];
    const Shape& b = shapes_[c.shape_b];
    const bool state_a_changed = set_solver_state(c, 0, bodies_[a.body]);
    const bool state_b_changed = set_solver_state(c, 1, bodies_[b.body]);
    const int32_t old_point_count = c.point_count;
    const bool had_points = old_point_count > 0;
    c.hit_speed = 0.0f;
    if (!proxies_meet(a, b)) {
        c.flags |= contact_disjoint;
        c.point_count = 0;
    } else if (is_solid(c)) {
        if (!recycle(c, bodies_[a.body], bodies_[b.body], step.tolerances)) {
            update_contact(c, a, b, step);
        }
        if ((c.flags & contact_pre_solve) != 0 && pre_solve_refuses(c)) {  // the flag first: no call
            c.point_count = 0;
            c.flags &= ~uint32_t(contact_recyclable);  // the hook is asked again next step
        }
    }
    uint8_t flags = is_solid(c) ? point_change_flags(c, had_points) : 0;
    if (is_solvable(c)) {
        flags |= has_points;
    }
    if (state_a_changed || state_b_changed || c.point_count != old_point_count) {
        flags |= layout_changed;
    }
    return flags;
}

uint8_t ContactSet::point_change_flags(const Contact& c, bool had_points) const {
    const bool has_points = c.point_count > 0;
    if (!had_points && !has_points) {
        return 0;
    }
    uint8_t flags = 0;
    for (int32_t e = 0; e < 2; ++e) {
        const Body& body = bodies_[c.edges[e].body];
        if (is_asleep(body) && (had_points != has_points || is_moving(bodies_[c.edges[e ^ 1].body]))) {
            flags |= e == 0 ? wakes_a : wakes_b;
        }
    }
    return flags | (had_points != has_points ? points_changed : 0);
}

bool ContactSet::recycle(Contact& c, const Body& a, const Body& b, const Tolerances& tolerances) const {
    if (!settings_.enable_contact_recycling) {
        return false;
    }
    const float extent = max_of(a.type == BodyType::static_body ? 0.0f : a.max_extent,
                                b.type == BodyType::static_body ? 0.0f : b.max_extent);
    const RecycleLimits limits{tolerances.recycle_touching_distance, tolerances.recycle_apart_distance,
                               recycle_min_cos};
    return recycle_manifold(c, a.transform, a.center, b.transform, b.center, extent, limits);
}

// Shapes whose tight boxes are farther apart than the speculative margin along an axis
// are at least that far apart: the narrowphase would give no points, and is skipped.
void ContactSet::update_contact(Contact& c, const Shape& a, const Shape& b, const StepContext& step) {
    const Body& body_a = bodies_[a.body];
    const Body& body_b = bodies_[b.body];
    const float margin = speculative_margin(body_a, body_b, step);
    const float slop = step.tolerances.linear_slop;
    const float gap = max_of(max_of(a.aabb.lower.x - b.aabb.upper.x, b.aabb.lower.x - a.aabb.upper.x),
                             max_of(a.aabb.lower.y - b.aabb.upper.y, b.aabb.lower.y - a.aabb.upper.y));
    const bool chain = a.geometry.type == ShapeType::chain_segment || b.geometry.type == ShapeType::chain_segment;
    const bool held = chain && (c.flags & contact_held_by_chain) != 0;
    Manifold fresh;
    if (held) {
        fresh = collide_held_by_chain(a.geometry, body_a.transform, b.geometry, body_b.transform, margin, slop);
    } else if (gap <= margin) {
        fresh = collide_shapes(a.geometry, body_a.transform, b.geometry, body_b.transform, margin, slop);
    }
    if (chain) {
        c.flags = fresh.point_count > 0 ? c.flags | contact_held_by_chain : c.flags & ~uint32_t(contact_held_by_chain);
    }
    update_points(c, fresh, body_a.center, body_b.center);
    remember_poses(c, body_a.transform, body_a.center, body_b.transform, body_b.center);
}

// The pre-solve hook may turn a contact with points off for this step: it then has none,
// so the solver neither pushes nor counts it as touching (an end event if it was).
bool ContactSet::pre_solve_refuses(const Contact& c) const {
    if (hooks_.pre_solve.call == nullptr || c.point_count == 0) {
        return false;
    }
    return !hooks_.allows_contact(events_.ids, shapes_, c.shape_a, c.shape_b, manifold_of(c));
}

// Contacts that gained their first point join their bodies' islands; those that lost
// their last one leave.
void ContactSet::update_links() {
#if defined(I2D_VALIDATE)
    // What the solver colours next: exactly the awake solid contacts with points, in order.
    std::size_t next = 0;
    for (const int32_t index : awake_) {
        const Contact& c = pool_[index];
        if (is_solvable(c)) {
            I2D_ASSERT(next < solvable_.size() && solvable_[next] == index);
            ++next;
        }
    }
    I2D_ASSERT(next == solvable_.size());
#endif
    for (const int32_t index : point_changes_) {
        Contact& c = pool_[index];
        const int32_t body_a = c.edges[0].body, body_b = c.edges[1].body;
        const bool linked = (c.flags & contact_island_link) != 0;
        const bool joins = bodies_[body_a].type == BodyType::dynamic && bodies_[body_b].type == BodyType::dynamic;
        if (c.point_count > 0 && !linked && joins) {
            c.flags |= contact_island_link;
            link_changes_.push_back({body_a, body_b, true});
        } else if (c.point_count == 0 && linked) {
            c.flags &= ~uint32_t(contact_island_link);
            link_changes_.push_back({body_a, body_b, false});
        }
    }
}

}  // namespace i2d
