// SPDX-License-Identifier: MIT
// ImpactChains: finding the gaps that close within the step, and resolving the chains.
#include "dynamics/solver/impact_chain.hpp"

#include <algorithm>
#include <limits>

#include "dynamics/contact/contact_set.hpp"
#include "dynamics/solver/impact.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// The solver moves the body: it takes impulses.
bool moved_by_solver(const Contact& c, int32_t edge) {
    return (c.flags & (edge == 0 ? contact_moves_a : contact_moves_b)) != 0;
}

// A body as the impact sees it: one the solver does not move keeps its velocity if it is
// kinematic and is still otherwise (static, or asleep: the solver's fixed state).
ImpactBody impact_body(const Body& b, bool moves) {
    const bool has_velocity = moves || b.type == BodyType::kinematic;
    return {b.center, has_velocity ? b.linear_velocity : Vec2{}, has_velocity ? b.angular_velocity : 0.0f,
            moves ? b.inv_mass : 0.0f, moves ? b.inv_inertia : 0.0f};
}

// The earliest a point of the contact closes its gap within the horizon (s), or false
// when none does.
bool closing_point(const Contact& c, const ImpactBody& a, const ImpactBody& b, float threshold, float horizon,
                   float& time) {
    bool closes = false;
    for (int32_t i = 0; i < c.point_count; ++i) {
        const ContactPoint& p = c.points[i];
        const Vec2 relative = (b.linear_velocity + cross(b.angular_velocity, p.anchor_b)) -
                              (a.linear_velocity + cross(a.angular_velocity, p.anchor_a));
        const float approach = -dot(relative, c.normal);
        const float gap = max_of(p.separation, 0.0f);
        if (approach > threshold && gap < approach * horizon) {
            const float t = gap / approach;
            time = closes ? min_of(time, t) : t;
            closes = true;
        }
    }
    return closes;
}

}  // namespace

void ImpactChains::run(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts) {
    heap_.clear();
    if (taken_.size() < std::size_t(contacts.pool().capacity())) {
        taken_.resize(std::size_t(contacts.pool().capacity()), 0);
    }
    for (const int32_t contact : contacts.solvable()) {
        Candidate c;
        if (candidate_of(step, bodies, contacts, contact, c)) {
            push(c);
        }
    }
    while (!heap_.empty()) {
        const Candidate c = pop();
        if (taken_[std::size_t(c.contact)]) {
            continue;  // each contact takes one impact a step; the substeps take the rest
        }
        taken_[std::size_t(c.contact)] = 1;
        taken_list_.push_back(c.contact);
        resolve(step, bodies, contacts, c);
    }
    for (const int32_t contact : taken_list_) {
        taken_[std::size_t(contact)] = 0;
    }
    taken_list_.clear();
}

bool ImpactChains::candidate_of(const StepContext& step, const Pool<Body>& bodies, const ContactSet& contacts,
                                int32_t contact, Candidate& out) const {
    const Contact& c = contacts.pool()[contact];
    if (!(c.restitution >= chain_min_restitution) || !is_solvable(c) ||
        !(moved_by_solver(c, 0) || moved_by_solver(c, 1))) {
        return false;
    }
    const ImpactBody a = impact_body(bodies[c.edges[0].body], moved_by_solver(c, 0));
    const ImpactBody b = impact_body(bodies[c.edges[1].body], moved_by_solver(c, 1));
    out = {0.0f, contact, false};
    // The step, and one substep more: the last relax stops what would close its gap within
    // a substep of the step's end, so the substeps would take that impact too.
    const float horizon = step.time_step + step.substep;
    return closing_point(c, a, b, step.settings.restitution_threshold, horizon, out.time);
}

// The heap keeps the earliest on top: the later of two sinks. Ties go to the lower contact
// index, so the order never depends on how the heap was filled.
bool ImpactChains::later(const Candidate& x, const Candidate& y) {
    return x.time > y.time || (x.time == y.time && x.contact > y.contact);
}

void ImpactChains::push(const Candidate& c) {
    heap_.push_back(c);
    std::push_heap(heap_.begin(), heap_.end(), later);
}

ImpactChains::Candidate ImpactChains::pop() {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Candidate c = heap_.back();
    heap_.pop_back();
    return c;
}

// The contact's impact alone, on all its points (the gap is taken as closed). An impact
// that starts no chain (no other contact of its bodies newly closes within the step) is
// undone, bit for bit, and left to the substeps; false then, or when nothing approached.
bool ImpactChains::resolve(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts, const Candidate& c) {
    Contact& k = contacts.pool()[c.contact];
    Body& body_a = bodies[k.edges[0].body];
    Body& body_b = bodies[k.edges[1].body];
    const bool moves_a = moved_by_solver(k, 0), moves_b = moved_by_solver(k, 1);
    ImpactBody a = impact_body(body_a, moves_a), b = impact_body(body_b, moves_b);
    Manifold manifold;
    manifold.normal = k.normal;
    manifold.point_count = k.point_count;
    for (int32_t i = 0; i < k.point_count; ++i) {
        manifold.points[i].point = body_a.center + k.points[i].anchor_a;
        manifold.points[i].penetration = -k.points[i].separation;
    }
    const ImpactMaterial material{k.friction, k.restitution, step.settings.restitution_threshold, k.tangent_speed};
    const ImpactResult r = resolve_impact(manifold, std::numeric_limits<float>::max(), material, a, b);
    if (r.point_index < 0) {
        return false;
    }
    find_neighbours(step, bodies, contacts, c.contact);
    const Vec2 saved_va = body_a.linear_velocity, saved_vb = body_b.linear_velocity;
    const float saved_wa = body_a.angular_velocity, saved_wb = body_b.angular_velocity;
    const float max_spin = step.max_spin();
    if (moves_a) {
        body_a.linear_velocity = a.linear_velocity;
        body_a.angular_velocity = clamp(a.angular_velocity, -max_spin, max_spin);
    }
    if (moves_b) {
        body_b.linear_velocity = b.linear_velocity;
        body_b.angular_velocity = clamp(b.angular_velocity, -max_spin, max_spin);
    }
    started_.clear();
    for (const Neighbour& n : neighbours_) {
        Candidate next;  // its time from now
        if (!n.was_closing && candidate_of(step, bodies, contacts, n.contact, next)) {
            started_.push_back({c.time + next.time, n.contact, true});
        }
    }
    if (!c.in_chain && started_.empty()) {
        body_a.linear_velocity = saved_va;
        body_a.angular_velocity = saved_wa;
        body_b.linear_velocity = saved_vb;
        body_b.angular_velocity = saved_wb;
        return false;
    }
    for (const Candidate& next : started_) {
        push(next);
    }
    if ((k.flags & contact_hit_events) != 0 && r.approach_speed > k.hit_speed) {
        k.hit_speed = r.approach_speed;  // the hit event the substeps would have given
        k.hit_point = r.point_index;
    }
    return true;
}

// The other contacts of the impact's moving bodies not yet taken, each once, and whether
// they were closing before the impact.
void ImpactChains::find_neighbours(const StepContext& step, const Pool<Body>& bodies, const ContactSet& contacts,
                                   int32_t contact) {
    neighbours_.clear();
    const Contact& k = contacts.pool()[contact];
    for (int32_t edge = 0; edge < 2; ++edge) {
        if (!moved_by_solver(k, edge)) {
            continue;
        }
        const int32_t other_body = k.edges[edge ^ 1].body;
        contacts.visit_contacts(k.edges[edge].body, [&](int32_t next, int32_t other) {
            // Between the impact's two bodies: listed once, from A.
            const bool seen = edge == 1 && other == other_body && moved_by_solver(k, 0);
            if (next == contact || taken_[std::size_t(next)] || seen) {
                return;
            }
            Candidate before;
            neighbours_.push_back({next, candidate_of(step, bodies, contacts, next, before)});
        });
    }
}

}  // namespace i2d
