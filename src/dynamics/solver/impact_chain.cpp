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
        // The impacts of one moment, each contact once a step (the substeps take the rest).
        group_.clear();
        const float moment = heap_.front().time;
        while (!heap_.empty() && heap_.front().time <= moment + simultaneous_time &&
               int32_t(group_.size()) < max_simultaneous_impacts) {
            const Candidate c = pop();
            if (!taken_[std::size_t(c.contact)]) {
                taken_[std::size_t(c.contact)] = 1;
                taken_list_.push_back(c.contact);
                group_.push_back(c);
            }
        }
        resolve_by_bodies(step, bodies, contacts);
    }
    for (const int32_t contact : taken_list_) {
        taken_[std::size_t(contact)] = 0;
    }
    taken_list_.clear();
}

// The moment's impacts that share a moving body, directly or through others, are solved
// together; the others apart, each kept or undone on its own.
void ImpactChains::resolve_by_bodies(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts) {
    const int32_t count = int32_t(group_.size());
    int32_t part_of[max_simultaneous_impacts];
    for (int32_t i = 0; i < count; ++i) {
        part_of[i] = i;
    }
    const auto moving_bodies_meet = [&](int32_t i, int32_t j) {
        const Contact& x = contacts.pool()[group_[std::size_t(i)].contact];
        const Contact& y = contacts.pool()[group_[std::size_t(j)].contact];
        for (int32_t ex = 0; ex < 2; ++ex) {
            for (int32_t ey = 0; ey < 2; ++ey) {
                if (moved_by_solver(x, ex) && moved_by_solver(y, ey) && x.edges[ex].body == y.edges[ey].body) {
                    return true;
                }
            }
        }
        return false;
    };
    for (int32_t i = 0; i < count; ++i) {
        for (int32_t j = i + 1; j < count; ++j) {
            if (part_of[j] != part_of[i] && moving_bodies_meet(i, j)) {
                const int32_t from = part_of[j];
                for (int32_t k = 0; k < count; ++k) {
                    part_of[k] = part_of[k] == from ? part_of[i] : part_of[k];
                }
            }
        }
    }
    for (int32_t part = 0; part < count; ++part) {
        part_.clear();
        for (int32_t i = 0; i < count; ++i) {
            if (part_of[i] == part) {
                part_.push_back(group_[std::size_t(i)]);
            }
        }
        if (!part_.empty()) {
            resolve(step, bodies, contacts);
        }
    }
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

// A part's impacts together, on all their contacts' points (the gaps taken as closed).
// A part that starts no chain (no other contact of its bodies newly closes within the
// step), unless a chain made it, is undone, bit for bit, and left to the substeps.
void ImpactChains::resolve(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts) {
    impact_bodies_.clear();
    body_of_slot_.clear();
    const auto slot_of = [&](int32_t body, bool moves) {
        for (std::size_t s = 0; s < body_of_slot_.size(); ++s) {
            if (body_of_slot_[s] == body) {
                return int32_t(s);
            }
        }
        body_of_slot_.push_back(body);
        impact_bodies_.push_back(impact_body(bodies[body], moves));
        return int32_t(body_of_slot_.size()) - 1;
    };
    impacts_.clear();
    bool in_chain = false;
    for (const Candidate& c : part_) {
        const Contact& k = contacts.pool()[c.contact];
        ImpactContact impact;
        impact.manifold = contacts.manifold_of(k);
        impact.material = {k.friction, k.restitution, step.settings.restitution_threshold, k.tangent_speed};
        impact.body_a = slot_of(k.edges[0].body, moved_by_solver(k, 0));
        impact.body_b = slot_of(k.edges[1].body, moved_by_solver(k, 1));
        impacts_.push_back(impact);
        in_chain = in_chain || c.in_chain;
    }
    results_.resize(impacts_.size());
    resolve_impacts(impacts_.data(), int32_t(impacts_.size()), impact_bodies_.data(), results_.data());
    find_neighbours(step, bodies, contacts);
    // Swapped in: the impact's velocities on the moving bodies, theirs kept to go back to.
    const float max_spin = step.max_spin();
    for (std::size_t s = 0; s < body_of_slot_.size(); ++s) {
        ImpactBody& v = impact_bodies_[s];
        if (v.inv_mass == 0.0f) {
            continue;  // a body the solver does not move
        }
        Body& body = bodies[body_of_slot_[s]];
        std::swap(body.linear_velocity, v.linear_velocity);
        const float spin = clamp(v.angular_velocity, -max_spin, max_spin);
        v.angular_velocity = body.angular_velocity;
        body.angular_velocity = spin;
    }
    started_.clear();
    const float moment = part_.front().time;
    for (const Neighbour& n : neighbours_) {
        Candidate next;  // its time from now
        if (!n.was_closing && candidate_of(step, bodies, contacts, n.contact, next)) {
            started_.push_back({moment + next.time, n.contact, true});
        }
    }
    if (!in_chain && started_.empty()) {
        for (std::size_t s = 0; s < body_of_slot_.size(); ++s) {
            const ImpactBody& v = impact_bodies_[s];
            if (v.inv_mass != 0.0f) {
                bodies[body_of_slot_[s]].linear_velocity = v.linear_velocity;
                bodies[body_of_slot_[s]].angular_velocity = v.angular_velocity;
            }
        }
        return;
    }
    for (const Candidate& next : started_) {
        push(next);
    }
    for (std::size_t g = 0; g < part_.size(); ++g) {
        Contact& k = contacts.pool()[part_[g].contact];
        const ImpactResult& r = results_[g];
        if ((k.flags & contact_hit_events) != 0 && r.point_index >= 0 && r.approach_speed > k.hit_speed) {
            k.hit_speed = r.approach_speed;  // the hit event the substeps would have given
            k.hit_point = r.point_index;
        }
    }
}

// The other contacts of the part's moving bodies not yet taken, each once, and whether
// they were closing before the impact.
void ImpactChains::find_neighbours(const StepContext& step, const Pool<Body>& bodies, const ContactSet& contacts) {
    neighbours_.clear();
    for (std::size_t s = 0; s < body_of_slot_.size(); ++s) {
        if (impact_bodies_[s].inv_mass == 0.0f) {
            continue;
        }
        contacts.visit_contacts(body_of_slot_[s], [&](int32_t next, int32_t) {
            if (taken_[std::size_t(next)] ||
                std::any_of(neighbours_.begin(), neighbours_.end(),
                            [next](const Neighbour& n) { return n.contact == next; })) {
                return;
            }
            Candidate before;
            neighbours_.push_back({next, candidate_of(step, bodies, contacts, next, before)});
        });
    }
}

}  // namespace i2d
