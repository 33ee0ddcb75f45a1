// SPDX-License-Identifier: MIT
// Replay: a recording (dynamics/recording/recording_format.hpp) run again in a world of
// its own, each step's hash checked against the recorded one.
//
// Design note: the recording is read whole at open (framing and checksums), then its
// records are applied in order. A record whose public call passes its arguments to the
// core unchanged is replayed through that call, so the C API's checks apply; one whose
// call would change them on the way (normalising a rotation again may move a bit) goes to
// the core directly, after the same rules (loaded_values.hpp). A recording is thus held
// to what a caller may do, and a doctored one gets a refusal, never a crash.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "boundary.hpp"
#include "dynamics/recording/recording_format.hpp"

namespace i2d::capi {

class Replay {
public:
    /// Reads the recording and makes its world; null, with the status set, when refused.
    static std::unique_ptr<Replay> open(Call& call, const void* data, std::size_t size, const i2d_world_def* runtime);
    ~Replay();
    Replay(const Replay&) = delete;
    Replay& operator=(const Replay&) = delete;

    i2d_world_id world() const { return world_; }
    int32_t step() const { return steps_done_; }
    int32_t step_count() const { return int32_t(step_records_.size()); }
    int32_t divergent_step() const { return divergent_step_; }

    /// Runs up to `count` steps; returns how many ran. With stop_at_divergence, stops after
    /// a step whose hash differs.
    int32_t run(Call& call, int32_t count, bool stop_at_divergence);
    /// Goes to step `step`, from the first snapshot again when it lies behind.
    bool seek(Call& call, int32_t step);

private:
    struct Record {
        RecordedOp op;
        std::size_t payload_at, payload_size;
    };

    Replay() = default;
    const char* read_records();
    bool apply(Call& call, const Record& record);
    bool apply_step(Call& call, const Record& record);

    std::vector<unsigned char> bytes_;
    uint32_t format_version_ = 0;  // of the recording: older ones lack fields newer ones have
    std::vector<Record> records_;
    std::vector<std::size_t> step_records_;  // index in records_ of each step's record
    std::size_t next_record_ = 1;            // record 0 is the first snapshot
    int32_t steps_done_ = 0;
    int32_t divergent_step_ = -1;
    bool broken_ = false;  // a record was refused: the world no longer follows the recording
    i2d_world_id world_ = I2D_NULL_WORLD_ID;
};

}  // namespace i2d::capi
