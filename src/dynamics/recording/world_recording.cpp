// SPDX-License-Identifier: MIT
// World::start_recording and stop_recording, and the snapshot record a restore leaves.
#include <vector>

#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"

namespace i2d {

void World::start_recording(RecordWriter write, void* context) {
    recorder_ = std::make_unique<Recorder>(write, context, lock_depth_);
    recorder_->write_header();
    record_snapshot();
}

void World::stop_recording() { recorder_.reset(); }

// The world as it is now, as a replay starts from it.
void World::record_snapshot() {
    RecordScope record(recorder_.get(), RecordedOp::snapshot);
    if (record) {
        std::vector<unsigned char> bytes(snapshot_size());
        save_snapshot(bytes.data(), bytes.size());
        record.out().bytes(bytes.data(), bytes.size());
    }
}

}  // namespace i2d
