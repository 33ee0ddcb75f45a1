// SPDX-License-Identifier: MIT
// The step, top-down: Box2D v3's pipeline of pairs, one narrowphase, the soft step with
// its substeps, bounds, events and sleep.
#include "core/state_hash.hpp"
#include "core/timer.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

namespace {

// Marks the world as stepping for as long as step runs, even when it leaves by throwing.
class SteppingMark {
public:
    explicit SteppingMark(bool& stepping) : stepping_(stepping) { stepping_ = true; }
    ~SteppingMark() { stepping_ = false; }
    SteppingMark(const SteppingMark&) = delete;
    SteppingMark& operator=(const SteppingMark&) = delete;

private:
    bool& stepping_;
};

}  // namespace

// A recorded step ends with the hash it produced, which a replay checks.
void World::step(float time_step, int32_t substep_count) {
    RecordScope record(recorder_.get(), RecordedOp::step);
    record.write(time_step, substep_count);
    run_step(time_step, substep_count);
    if (record) {
        record.write(state_hash());
    }
}

void World::run_step(float time_step, int32_t substep_count) {
    const SteppingMark mark(stepping_);
    Timer total(profiling_), timer(profiling_);
    profile_ = StepProfile{};
    stages_->events.begin_step();
    if (time_step == 0.0f) {
        return;  // a paused world: nothing moves, nothing is tested (Box2D's rule)
    }
    const StepContext step(settings_, time_step, substep_count, stages_->tasks.worker_count());
    cover_step_ahead(time_step);
    stages_->contacts.find_new_contacts(step, stages_->broad_phase, [this](int32_t body) { wake_body(body); });
    profile_.pairs += timer.lap_ms();

    stages_->contacts.collide(step);
    // Waking adds to the awake contacts, so it waits until the narrowphase is done; the
    // woken contacts' manifolds are current, since sleeping bodies did not move.
    for (const int32_t island : stages_->contacts.islands_to_wake()) {
        stages_->islands.wake_island(island);
        follow_woken_bodies();
    }
    stages_->contacts.update_links();
    apply_link_changes();
    profile_.collide += timer.lap_ms();

    stages_->solver.step(step);
    profile_.solve += timer.lap_ms();
    if (settings_.enable_continuous) {
        stages_->continuous.run(step, stages_->solver.fast_bodies());
    }
    profile_.continuous += timer.lap_ms();
    stages_->broad_phase.commit_moves_in_place(&stages_->tasks);
    profile_.update_bounds += timer.lap_ms();

    stages_->contacts.end_step(step);
    apply_link_changes();
    if (settings_.enable_continuous) {
        report_sensor_crossings();
    }
    profile_.events += timer.lap_ms();
    if (settings_.enable_sleep) {
        stages_->islands.sleep_rested_islands(
            settings_.time_to_sleep,
            [this](int32_t body, FunctionRef<void(int32_t)> follow) { visit_island_links(body, follow); },
            [this](int32_t body) { report_falling_asleep(body); }, [this](int32_t body) { stages_->contacts.body_slept(body); });
    }
    profile_.sleep += timer.lap_ms();
    if (!stages_->solver.non_finite_bodies().empty()) {
        quarantine_non_finite_bodies();
    }
    validate();
    profile_.step = total.lap_ms();
}

// A body falling asleep reports a move event even if it did not move.
void World::report_falling_asleep(int32_t body) {
    Body& b = bodies_[body];
    std::vector<BodyMoveEvent>& moves = stages_->events.current.body_moves;
    if (b.move_event == null_index) {
        b.move_event = int32_t(moves.size());
        moves.push_back({b.transform, stages_->events.ids.body_id(body, bodies_.generation(body)), b.user_data, false});
    }
    moves[std::size_t(b.move_event)].fell_asleep = true;
}

// A body whose solved state overflowed (the solver left it where the step found it, at
// rest) is frozen there rather than allowed to spread NaN: made static, so that nothing
// moves it and it moves nothing, its joints' impulses forgotten (they were solved
// against its NaN), and reported. Its contacts end with set_type; those ends belong to
// this step's arrays, which the caller has not seen yet.
void World::quarantine_non_finite_bodies() {
    const std::size_t contact_ends_before = stages_->events.pending_contact_ends.size();
    const std::size_t sensor_ends_before = stages_->events.pending_sensor_ends.size();
    for (const int32_t body : stages_->solver.non_finite_bodies()) {
        const Body& b = bodies_[body];
        stages_->events.current.body_quarantines.push_back(
            {b.transform, stages_->events.ids.body_id(body, bodies_.generation(body)), b.user_data, int32_t(b.type)});
        forget_joint_impulses(body);
        set_type(body, BodyType::static_body);
        bodies_[body].quarantined = true;
    }
    EventRecorder& events = stages_->events;
    events.take_pending(events.pending_contact_ends, contact_ends_before, events.current.contact_end);
    events.take_pending(events.pending_sensor_ends, sensor_ends_before, events.current.sensor_end);
}

// A fast body that passed through a sensor within the step neither began nor ended the
// step in it: the sensor reports the visit as a begin and an end together. Visits the
// contact saw (touching at either end of the step) were reported already.
void World::report_sensor_crossings() {
    for (const SensorCrossing& crossing : stages_->continuous.sensor_crossings()) {
        bool seen = false;
        stages_->contacts.visit_contacts(shapes_[crossing.visitor_shape].body, [&](int32_t contact, int32_t) {
            const Contact& c = stages_->contacts.pool()[contact];
            const bool same = (c.shape_a == crossing.sensor_shape && c.shape_b == crossing.visitor_shape) ||
                              (c.shape_b == crossing.sensor_shape && c.shape_a == crossing.visitor_shape);
            seen = seen || (same && (c.flags & (contact_touching | contact_touching_at_start)) != 0);
        });
        if (!seen) {
            const ShapePairEvent e{stages_->events.ids.shape_id(crossing.sensor_shape, shapes_.generation(crossing.sensor_shape)),
                                   stages_->events.ids.shape_id(crossing.visitor_shape,
                                                        shapes_.generation(crossing.visitor_shape))};
            stages_->events.current.sensor_begin.push_back(e);
            stages_->events.current.sensor_end.push_back(e);
        }
    }
}

WorldCounters World::counters() const {
    WorldCounters c;
    c.body_count = bodies_.count();
    c.shape_count = shapes_.count();
    c.pair_count = stages_->contacts.pool().count();
    c.contact_count = stages_->contacts.touching_count();
    for (int32_t k = 0; k < int32_t(ProxyKind::count); ++k) {
        c.tree_heights[k] = stages_->broad_phase.tree(ProxyKind(k)).height();
    }
    c.awake_body_count = int32_t(stages_->islands.awake_bodies().size());
    c.sleeping_island_count = stages_->islands.sleeping_island_count();
    return c;
}

uint64_t World::state_hash() const {
    StateHash hash;
    for (int32_t i = 0; i < bodies_.capacity(); ++i) {
        if (!bodies_.is_live(i)) {
            continue;
        }
        const Body& b = bodies_[i];
        hash.add(i);
        hash.add_bytes(&b.transform, sizeof b.transform);
        hash.add_bytes(&b.linear_velocity, sizeof b.linear_velocity);
        hash.add(b.angular_velocity);
    }
    const Pool<Contact>& contacts = stages_->contacts.pool();
    for (int32_t i = 0; i < contacts.capacity(); ++i) {
        if (!contacts.is_live(i)) {
            continue;
        }
        const Contact& c = contacts[i];
        hash.add(i);
        for (int32_t k = 0; k < c.point_count; ++k) {
            hash.add(c.points[k].normal_impulse);
            hash.add(c.points[k].tangent_impulse);
        }
        hash.add(c.rolling_impulse);
    }
    return hash.value();
}

}  // namespace i2d
