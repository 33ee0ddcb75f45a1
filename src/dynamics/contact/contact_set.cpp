// SPDX-License-Identifier: MIT
// ContactSet: creation from broadphase pairs, the narrowphase, links into islands, events
// and destruction with the body contact lists kept consistent.
#include "dynamics/contact/contact_set.hpp"

#include <cmath>

#include "collision/geometry.hpp"
#include "collision/manifold.hpp"
#include "core/assert.hpp"
#include "core/dense_list.hpp"
#include "core/prefetch.hpp"
#include "core/reserve.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "math/math.hpp"

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

// How far apart the two shapes may be and still meet within the step: the fixed
// speculative distance plus how far their surfaces can approach in one step (relative
// speed, and spin times extent). Contacts within it get points the solver can stop at.
float speculative_margin(const Body& a, const Body& b, float time_step) {
    const float approach = length(b.linear_velocity - a.linear_velocity) +
                           std::fabs(a.angular_velocity) * a.max_extent + std::fabs(b.angular_velocity) * b.max_extent;
    return speculative_distance + time_step * approach;
}

bool is_moving(const Body& b) {
    return b.awake_index != null_index &&
           (b.linear_velocity.x != 0.0f || b.linear_velocity.y != 0.0f || b.angular_velocity != 0.0f);
}

bool is_asleep(const Body& b) { return b.island != null_index && b.awake_index == null_index; }

// The solver moves a body only while it is dynamic and awake.
uint32_t moves_flag(const Body& b, int32_t edge) {
    const bool moves = b.type == BodyType::dynamic && b.awake_index != null_index;
    return moves ? (edge == 0 ? uint32_t(contact_moves_a) : uint32_t(contact_moves_b)) : 0u;
}

// Returns whether anything the colouring reads changed.
bool set_solver_state(Contact& c, int32_t edge, const Body& b) {
    int32_t& state = edge == 0 ? c.state_a : c.state_b;
    const uint32_t flag = edge == 0 ? contact_moves_a : contact_moves_b;
    const uint32_t flags = (c.flags & ~flag) | moves_flag(b, edge);
    const bool changed = state != b.awake_index || flags != c.flags;
    state = b.awake_index;
    c.flags = flags;
    return changed;
}

}  // namespace

void ContactSet::add_awake(int32_t contact) {
    dense_list_add(awake_, contact, [this](int32_t c) -> int32_t& { return contacts_[c].awake_index; });
    ++layout_version_;
}

void ContactSet::remove_awake(int32_t contact) {
    dense_list_remove(awake_, contact, [this](int32_t c) -> int32_t& { return contacts_[c].awake_index; });
    ++layout_version_;
}

void ContactSet::create_contact(int32_t shape_a, int32_t shape_b) {
    if (!pair_set_.insert(pair_key(shape_a, shape_b))) {
        return;  // the pair has a contact already
    }
    // Room in the awake list for every contact slot first, so that waking never allocates.
    reserve_room(awake_, std::size_t(contacts_.capacity()) + 1);
    const int32_t index = contacts_.allocate();
    if (index == null_index) {
        pair_set_.remove(pair_key(shape_a, shape_b));
        return;  // 16.7 million contacts: the pair goes without one
    }
    const Shape& a = shapes_[shape_a];
    const Shape& b = shapes_[shape_b];
    Contact& c = contacts_[index];
    c.shape_a = shape_a;
    c.shape_b = shape_b;
    if (a.is_sensor || b.is_sensor) {
        const Shape& visitor = a.is_sensor ? b : a;
        c.flags = contact_sensor | (visitor.enable_sensor_events ? contact_report_events : 0u);
    } else {
        c.flags = (a.enable_contact_events && b.enable_contact_events ? uint32_t(contact_report_events) : 0u) |
                  (a.enable_hit_events || b.enable_hit_events ? uint32_t(contact_hit_events) : 0u);
    }
    mix_material(c, a, b);
    const int32_t body_of[2] = {a.body, b.body};
    for (int32_t e = 0; e < 2; ++e) {
        Body& body = bodies_[body_of[e]];
        ContactEdge& edge = c.edges[e];
        edge.body = body_of[e];
        edge.next_key = body.head_contact_key;
        if (body.head_contact_key != null_index) {
            contacts_[contact_of_key(body.head_contact_key)].edges[edge_of_key(body.head_contact_key)].prev_key =
                (index << 1) | e;
        }
        body.head_contact_key = (index << 1) | e;
        ++body.contact_count;
    }
    // A pair found while both bodies rest (a shape created or refiltered beside them)
    // wakes them, or nothing would ever update it.
    if (!islands_.is_awake(a.body) && !islands_.is_awake(b.body)) {
        islands_.wake_body(a.body);
        islands_.wake_body(b.body);
    }
    if (contacts_[index].awake_index == null_index) {
        add_awake(index);
    }
}

// Contact events name the pair in shape order; sensor events name the sensor first.
ShapePairEvent ContactSet::event_of(const Contact& c) const {
    const bool sensor_is_b = (c.flags & contact_sensor) != 0 && !shapes_[c.shape_a].is_sensor;
    const uint64_t a = events_.ids.shape_id(c.shape_a, shapes_.generation(c.shape_a));
    const uint64_t b = events_.ids.shape_id(c.shape_b, shapes_.generation(c.shape_b));
    return sensor_is_b ? ShapePairEvent{b, a} : ShapePairEvent{a, b};
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

void ContactSet::destroy_contact(int32_t index, bool during_step) {
    if (!during_step) {
        // The caller took something away from under or beside these bodies.
        islands_.wake_body(contacts_[index].edges[0].body);
        islands_.wake_body(contacts_[index].edges[1].body);
    }
    Contact& c = contacts_[index];
    if (c.flags & contact_island_link) {
        islands_.unlink(c.edges[0].body);
    }
    if (c.awake_index != null_index) {
        remove_awake(index);
    }
    if (during_step) {
        report_touch_changes(c, false);
    } else if ((c.flags & contact_touching) && (c.flags & contact_report_events)) {
        // Between steps the last step reported the pair as touching: it ends now, and
        // the end waits for the next step's arrays so that the current ones stay valid.
        const bool sensor = (c.flags & contact_sensor) != 0;
        (sensor ? events_.pending_sensor_ends : events_.pending_contact_ends).push_back(event_of(c));
    }
    for (int32_t e = 0; e < 2; ++e) {
        const ContactEdge& edge = c.edges[e];
        Body& body = bodies_[edge.body];
        if (edge.prev_key != null_index) {
            contacts_[contact_of_key(edge.prev_key)].edges[edge_of_key(edge.prev_key)].next_key = edge.next_key;
        } else {
            body.head_contact_key = edge.next_key;
        }
        if (edge.next_key != null_index) {
            contacts_[contact_of_key(edge.next_key)].edges[edge_of_key(edge.next_key)].prev_key = edge.prev_key;
        }
        --body.contact_count;
    }
    pair_set_.remove(pair_key(c.shape_a, c.shape_b));
    contacts_.free(index);
}

// Called between steps: destroying a shape (all its contacts go), changing its filter
// (only the contacts the new filter forbids go; the others keep touching, no events).
void ContactSet::destroy_contacts_of_shape(int32_t shape, bool only_filtered_out) {
    int32_t key = bodies_[shapes_[shape].body].head_contact_key;
    while (key != null_index) {
        const Contact& c = contacts_[contact_of_key(key)];
        const int32_t next = c.edges[edge_of_key(key)].next_key;
        const bool involved = c.shape_a == shape || c.shape_b == shape;
        if (involved && (!only_filtered_out || !should_collide(shapes_[c.shape_a].filter, shapes_[c.shape_b].filter))) {
            destroy_contact(contact_of_key(key), false);
        }
        key = next;
    }
}

void ContactSet::destroy_contacts_between(int32_t body_a, int32_t body_b) {
    int32_t key = bodies_[body_a].head_contact_key;
    while (key != null_index) {
        const Contact& c = contacts_[contact_of_key(key)];
        const int32_t next = c.edges[edge_of_key(key)].next_key;
        if (c.edges[edge_of_key(key) ^ 1].body == body_b) {
            destroy_contact(contact_of_key(key), false);
        }
        key = next;
    }
}

void ContactSet::mix_materials_of_shape(int32_t shape) {
    ++layout_version_;  // the colouring notes whether any contact is elastic
    visit_contacts(shapes_[shape].body, [&](int32_t contact, int32_t) {
        Contact& c = contacts_[contact];
        if (c.shape_a == shape || c.shape_b == shape) {
            mix_material(c, shapes_[c.shape_a], shapes_[c.shape_b]);
        }
    });
}

void ContactSet::body_woke(int32_t body) {
    visit_contacts(body, [&](int32_t contact, int32_t) {
        Contact& c = contacts_[contact];
        if (c.awake_index == null_index) {
            add_awake(contact);
            if (is_solvable(c)) {
                solvable_.push_back(contact);
            }
        }
        const int32_t edge = c.edges[0].body == body ? 0 : 1;
        layout_version_ += set_solver_state(c, edge, bodies_[body]) ? 1u : 0u;
    });
}

void ContactSet::body_slept(int32_t body) {
    visit_contacts(body, [&](int32_t contact, int32_t other) {
        if (contacts_[contact].awake_index != null_index && !islands_.is_awake(other)) {
            remove_awake(contact);
        }
    });
}

// Most candidates are pairs that have a contact already: the pair set answers that
// with one lookup, before the shapes and bodies are read.
bool ContactSet::may_pair(int32_t shape_a, int32_t shape_b) const {
    if (pair_set_.contains(pair_key(shape_a, shape_b))) {
        return false;
    }
    const Shape& a = shapes_[shape_a];
    const Shape& b = shapes_[shape_b];
    if (a.body == b.body || (a.is_sensor && b.is_sensor)) {
        return false;
    }
    if (bodies_[a.body].type != BodyType::dynamic && bodies_[b.body].type != BodyType::dynamic) {
        return false;
    }
    return should_collide(a.filter, b.filter) && !joints_.keeps_apart(a.body, b.body);
}

// One pair-finding stage's range: the self search's parts, or the queries.
template <bool SelfSearch>
void ContactSet::pair_range(const StepContext&, ContactSet& self, const PairStage& arg, int32_t begin, int32_t end,
                            int32_t) {
    std::vector<ShapePairCandidate>& out = self.block_pairs_[arg.list][std::size_t(begin / arg.items_per_block)];
    out.clear();
    const auto accept = [&self](int32_t a, int32_t b) { return self.may_pair(a, b); };
    const auto ahead = [&self](int32_t a, int32_t b) { self.pair_set_.prefetch(pair_key(a, b)); };
    if constexpr (SelfSearch) {
        self.querying_->self_pairs(begin, end, accept, out, ahead);
    } else {
        self.querying_->query_pairs(begin, end, accept, out, ahead);
    }
}

// New pairs, block by block in the broadphase's order, become contacts on this thread.
// Creation order is the awake list's order, which the colouring follows, and so the order
// of solving: the self search's pairs are first put in the order of their earlier leaf
// in the tree's storage, close to the order the queries give. Made as the search found
// them, many_pyramids' step took 8 % longer (its solve 10 %); sorted by shape ids (row by
// row), the 70-row pyramid crept 5.9 cm sideways in 2000 steps instead of 0.35 cm (row
// order gives every box's contacts the same pattern of colours: a bias to one side).
void ContactSet::find_new_contacts(const StepContext& step, BroadPhase& broad_phase) {
    const int32_t queries = broad_phase.begin_pair_queries();
    const int32_t self_parts = broad_phase.self_part_count();
    const int32_t workers = tasks_.worker_count();
    const bool parallel = workers > 1 && (queries >= parallel_min_moved_proxies || self_parts > 0);
    stages_.clear();
    stages_.push_back(make_stage<&ContactSet::pair_range<true>>(*this, PairStage{0}, self_parts, workers, parallel,
                                                                self_search_parts_per_work_block));
    stages_.push_back(make_stage<&ContactSet::pair_range<false>>(*this, PairStage{1}, queries, workers, parallel,
                                                                 proxies_per_work_block));
    for (int32_t s = 0; s < 2; ++s) {
        Stage& stage = stages_[std::size_t(s)];
        stage.set_arg(PairStage{s, stage.items_per_block});
        const std::size_t blocks = std::size_t(stage.block_count());
        if (block_pairs_[s].size() < blocks) {
            block_pairs_[s].resize(blocks);
        }
    }
    querying_ = &broad_phase;
    runner_.run(tasks_, stages_, parallel, &step);
    querying_ = nullptr;
    broad_phase.end_pair_queries();
    for (int32_t s = 0; s < 2; ++s) {
        new_pairs_.clear();
        const Stage& stage = stages_[std::size_t(s)];
        for (int32_t b = 0; b < (stage.item_count > 0 ? stage.block_count() : 0); ++b) {
            const std::vector<ShapePairCandidate>& found = block_pairs_[s][std::size_t(b)];
            new_pairs_.insert(new_pairs_.end(), found.begin(), found.end());
        }
        if (s == 0) {
            radix_sort(new_pairs_, new_pairs_scratch_, [&](const ShapePairCandidate& p) {
                const uint32_t a = broad_phase.storage_order_of(shapes_[p.shape_a].proxy_key);
                const uint32_t b = broad_phase.storage_order_of(shapes_[p.shape_b].proxy_key);
                return a < b ? a : b;
            });
        }
        for (const ShapePairCandidate& pair : new_pairs_) {
            create_contact(pair.shape_a, pair.shape_b);
        }
    }
}

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
        const Contact& c = contacts_[index];
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

// One stage over the awake contacts, shared by the workers when there are enough.
template <auto F>
void ContactSet::run_over_awake(const StepContext& step) {
    const int32_t count = int32_t(awake_.size());
    const bool parallel = tasks_.worker_count() > 1 && count >= parallel_min_contacts;
    stages_.assign(1, make_stage<F>(*this, NoStageArg{}, count, tasks_.worker_count(), parallel, contacts_per_work_block));
    runner_.run(tasks_, stages_, parallel, &step);
}

// The awake list is in no spatial order: the contacts (and their shapes and bodies)
// it names next are asked for ahead, so that their cache misses overlap. Forced inline:
// a const function that only prefetches looks pure to GCC, which dropped every call.
I2D_FORCE_INLINE void ContactSet::prefetch_for_collide(int32_t k, int32_t count) const {
    constexpr int32_t contacts_ahead = 12, neighbours_ahead = 6;
    if (k + contacts_ahead < count) {
        prefetch_object(contacts_[awake_[std::size_t(k + contacts_ahead)]]);
    }
    if (k + neighbours_ahead < count) {
        const Contact& c = contacts_[awake_[std::size_t(k + neighbours_ahead)]];
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
        self.collide_flags_[std::size_t(k)] = self.collide_one(k, step.time_step);
    }
}

// Updates the k-th awake contact, writing only to it; returns its CollideFlags.
uint8_t ContactSet::collide_one(int32_t k, float time_step) {
    Contact& c = contacts_[awake_[std::size_t(k)]];
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
        if (!recycle(c, bodies_[a.body], bodies_[b.body])) {
            update_contact(c, a, b, time_step);
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

// Material is mixed when the contact is made and whenever a shape's material changes,
// not every step: the geometric mean costs two square roots.
void ContactSet::mix_material(Contact& c, const Shape& a, const Shape& b) const {
    c.friction = mix(settings_.friction_mixing, a.friction, b.friction);
    c.restitution = mix(settings_.restitution_mixing, a.restitution, b.restitution);
    c.rolling_resistance = a.rolling_resistance == 0.0f && b.rolling_resistance == 0.0f
                               ? 0.0f
                               : max_of(a.rolling_resistance * rounding_radius(a.geometry),
                                        b.rolling_resistance * rounding_radius(b.geometry));
    // Each surface moves counter-clockwise around its own shape: along +left_perp(n)
    // for A, whose outward normal is n, and along -left_perp(n) for B. No slip between
    // the moving surfaces means dot(vB - vA, left_perp(n)) = speed A + speed B.
    c.tangent_speed = a.tangent_speed + b.tangent_speed;
}

bool ContactSet::recycle(Contact& c, const Body& a, const Body& b) const {
    if (!settings_.enable_contact_recycling) {
        return false;
    }
    const float extent = max_of(a.type == BodyType::static_body ? 0.0f : a.max_extent,
                                b.type == BodyType::static_body ? 0.0f : b.max_extent);
    return recycle_manifold(c, a.transform, a.center, b.transform, b.center, extent,
                            RecycleLimits{recycle_touching_distance, recycle_apart_distance, recycle_min_cos});
}

// Shapes whose tight boxes are farther apart than the speculative margin along an axis
// are at least that far apart: the narrowphase would give no points, and is skipped.
void ContactSet::update_contact(Contact& c, const Shape& a, const Shape& b, float time_step) {
    const Body& body_a = bodies_[a.body];
    const Body& body_b = bodies_[b.body];
    const float margin = speculative_margin(body_a, body_b, time_step);
    const float gap = max_of(max_of(a.aabb.lower.x - b.aabb.upper.x, b.aabb.lower.x - a.aabb.upper.x),
                             max_of(a.aabb.lower.y - b.aabb.upper.y, b.aabb.lower.y - a.aabb.upper.y));
    const bool chain = a.geometry.type == ShapeType::chain_segment || b.geometry.type == ShapeType::chain_segment;
    const bool held = chain && (c.flags & contact_held_by_chain) != 0;
    Manifold fresh;
    if (held) {
        fresh = collide_held_by_chain(a.geometry, body_a.transform, b.geometry, body_b.transform, margin);
    } else if (gap <= margin) {
        fresh = collide_shapes(a.geometry, body_a.transform, b.geometry, body_b.transform, margin);
    }
    if (chain) {
        c.flags = fresh.point_count > 0 ? c.flags | contact_held_by_chain : c.flags & ~uint32_t(contact_held_by_chain);
    }
    update_points(c, fresh, body_a.center, body_b.center);
    remember_poses(c, body_a.transform, body_a.center, body_b.transform, body_b.center);
}

void ContactSet::forget_manifolds(int32_t body) {
    visit_contacts(body, [&](int32_t contact, int32_t) { contacts_[contact].flags &= ~uint32_t(contact_recyclable); });
}

// Contacts that gained their first point join their bodies' islands; those that lost
// their last one leave.
void ContactSet::update_links() {
#if defined(I2D_VALIDATE)
    // What the solver colours next: exactly the awake solid contacts with points, in order.
    std::size_t next = 0;
    for (const int32_t index : awake_) {
        const Contact& c = contacts_[index];
        if (is_solvable(c)) {
            I2D_ASSERT(next < solvable_.size() && solvable_[next] == index);
            ++next;
        }
    }
    I2D_ASSERT(next == solvable_.size());
#endif
    for (const int32_t index : point_changes_) {
        Contact& c = contacts_[index];
        const int32_t body_a = c.edges[0].body, body_b = c.edges[1].body;
        const bool linked = (c.flags & contact_island_link) != 0;
        const bool joins = bodies_[body_a].type == BodyType::dynamic && bodies_[body_b].type == BodyType::dynamic;
        if (c.point_count > 0 && !linked && joins) {
            c.flags |= contact_island_link;
            islands_.link(body_a, body_b);
        } else if (c.point_count == 0 && linked) {
            c.flags &= ~uint32_t(contact_island_link);
            islands_.unlink(body_a);
        }
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
            report_hit(contacts_[index]);
        }
        if (flags & ends) {
            destroy_contact(index, true);
        } else if (flags & reports) {
            report_touch_changes(contacts_[index], (contacts_[index].flags & contact_touching) != 0);
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
            prefetch_line(&self.contacts_[self.awake_[std::size_t(k + contacts_ahead)]].flags);
        }
        Contact& c = self.contacts_[self.awake_[std::size_t(k)]];
        uint8_t flags = 0;
        if (c.flags & contact_disjoint) {
            flags = ends;
        } else {
            if (!is_solid(c)) {
                const Shape& a = self.shapes_[c.shape_a];
                const Shape& b = self.shapes_[c.shape_b];
                const Manifold m = without_speculative_points(collide_shapes(
                    a.geometry, self.bodies_[a.body].transform, b.geometry, self.bodies_[b.body].transform));
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

int32_t ContactSet::touching_count() const {
    int32_t count = 0;
    for (int32_t i = 0; i < contacts_.capacity(); ++i) {
        if (contacts_.is_live(i) && (contacts_[i].flags & (contact_touching | contact_sensor)) == contact_touching) {
            ++count;
        }
    }
    return count;
}

void ContactSet::validate() const {
#if defined(I2D_VALIDATE)
    for (int32_t k = 0; k < int32_t(awake_.size()); ++k) {
        I2D_ASSERT(contacts_.is_live(awake_[k]) && contacts_[awake_[k]].awake_index == k);
    }
    I2D_ASSERT(pair_set_.count() == contacts_.count());
    for (int32_t i = 0; i < contacts_.capacity(); ++i) {
        if (!contacts_.is_live(i)) {
            continue;
        }
        const Contact& c = contacts_[i];
        I2D_ASSERT(c.shape_a < c.shape_b && shapes_.is_live(c.shape_a) && shapes_.is_live(c.shape_b));
        I2D_ASSERT(pair_set_.contains(pair_key(c.shape_a, c.shape_b)));
        // Exactly the contacts with an awake body are updated each step.
        const bool has_awake_body = islands_.is_awake(c.edges[0].body) || islands_.is_awake(c.edges[1].body);
        I2D_ASSERT(has_awake_body == (c.awake_index != null_index));
        // A link joins two bodies of one island.
        if (c.flags & contact_island_link) {
            I2D_ASSERT(bodies_[c.edges[0].body].island == bodies_[c.edges[1].body].island);
        }
    }
#endif
}

}  // namespace i2d
