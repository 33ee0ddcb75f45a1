// SPDX-License-Identifier: MIT
// World: creation, and the wiring that keeps the stages in step: waking, links between the
// islands and the contact set, contacts that go when something is taken away.
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"

#include <atomic>

#include "dynamics/world/world_stages.hpp"

namespace i2d {

namespace {

// Serials of the process's worlds: a rollback state restores only into its own world.
std::atomic<uint64_t> next_world_serial{1};

}  // namespace

World::World(const WorldDef& def)
    : settings_(def),
      stages_(std::make_unique<WorldStages>(settings_, bodies_, shapes_)),
      serial_(next_world_serial.fetch_add(1, std::memory_order_relaxed)),
      profiling_(def.enable_profile) {}

World::~World() = default;

const Pool<Joint>& World::joints() const { return stages_->joints.pool(); }

void World::wake_body(int32_t body) {
    RecordScope record(recorder_.get(), RecordedOp::wake_body);
    record.write(body);
    stages_->islands.wake_body(body);
    follow_woken_bodies();
}

void World::wake_all() {
    RecordScope record(recorder_.get(), RecordedOp::wake_all);
    stages_->islands.wake_all();
    follow_woken_bodies();
}

void World::sleep_body(int32_t body) {
    RecordScope record(recorder_.get(), RecordedOp::sleep_body);
    record.write(body);
    stages_->islands.sleep_island_of(body, [this](int32_t b, FunctionRef<void(int32_t)> follow) { visit_island_links(b, follow); },
                             [this](int32_t b) { stages_->contacts.body_slept(b); });
}

// The contacts of bodies whose island woke join the awake contact list, in the order the
// bodies joined the awake list.
void World::follow_woken_bodies() {
    for (const int32_t body : stages_->islands.woken_bodies()) {
        stages_->contacts.body_woke(body);
    }
    stages_->islands.clear_woken();
}

void World::apply_link_changes() {
    stages_->islands.apply(stages_->contacts.link_changes());
    stages_->contacts.clear_link_changes();
}

void World::destroy_contacts_of_shape(int32_t shape, bool only_filtered_out) {
    stages_->contacts.destroy_contacts_of_shape(shape, only_filtered_out, [this](int32_t body) { wake_body(body); });
    apply_link_changes();
}

void World::destroy_contacts_between(int32_t body_a, int32_t body_b) {
    stages_->contacts.destroy_contacts_between(body_a, body_b, [this](int32_t body) { wake_body(body); });
    apply_link_changes();
}

// What links a body into its island: solid contacts with points, and joints.
void World::visit_island_links(int32_t body, FunctionRef<void(int32_t other)> follow) const {
    stages_->contacts.visit_links(body, follow);
    stages_->joints.visit_links(body, follow);
}

// Resting bodies must feel the new gravity.
void World::set_gravity(Vec2 gravity) {
    RecordScope record(recorder_.get(), RecordedOp::set_gravity);
    record.write(gravity);
    ++structure_version_;
    settings_.gravity = gravity;
    wake_all();
}

// Turning sleep off wakes every body: none may stay asleep in a world without sleep.
void World::set_settings(const WorldDef& settings) {
    RecordScope record(recorder_.get(), RecordedOp::set_world_settings);
    record.write(settings);
    ++structure_version_;
    WorldDef next = settings;
    next.worker_count = settings_.worker_count;
    next.tasks = settings_.tasks;
    next.simd_path = settings_.simd_path;
    next.enable_profile = settings_.enable_profile;
    next.length_units_per_meter = settings_.length_units_per_meter;
    const bool wake = settings_.enable_sleep && !next.enable_sleep;
    settings_ = next;
    if (wake) {
        wake_all();
    }
}

void World::set_id_encoder(const IdEncoder& ids) { stages_->events.ids = ids; }

int32_t World::worker_count() const { return stages_->tasks.worker_count(); }

SimdPath World::simd_path() const { return stages_->solver.simd_path(); }

const WorldEvents& World::events() const { return stages_->events.current; }

}  // namespace i2d
