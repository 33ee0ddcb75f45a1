// SPDX-License-Identifier: MIT
// Recorder: streams a world's recording (recording_format.hpp) to the caller's writer.
//
// Design note: each of the world's public calls that changes it opens a RecordScope and
// writes its arguments; the record goes out when the outermost scope closes, so a call
// made inside another (a body's destruction destroying its shapes) is not recorded twice
// and a step's record can end with the hash the step produced. The writer runs with the
// world locked: it may not call back into the world it records.
#pragma once

#include <cstdint>
#include <vector>

#include "core/byte_stream.hpp"
#include "core/field_io.hpp"
#include "dynamics/recording/recorded_fields.hpp"
#include "dynamics/recording/recording_format.hpp"

namespace i2d {

class Recorder {
public:
    /// `lock_depth`: the world's lock, held while the writer runs.
    Recorder(RecordWriter write, void* context, int32_t& lock_depth);

    /// Writes the recording's header.
    void write_header();

private:
    friend class RecordScope;
    void emit();

    RecordWriter write_;
    void* context_;
    int32_t& lock_depth_;
    int32_t depth_ = 0;                  // recorded calls open, nested
    std::vector<unsigned char> record_;  // the record being written, reused
    ByteWriter out_;                     // onto record_
};

/// One recorded call: active when the world records and no recorded call encloses it.
class RecordScope {
public:
    RecordScope(Recorder* recorder, RecordedOp op);
    ~RecordScope();
    RecordScope(const RecordScope&) = delete;
    RecordScope& operator=(const RecordScope&) = delete;

    explicit operator bool() const { return active_; }
    /// Adds the call's arguments (recorded_fields.hpp says how each kind is stored); does
    /// nothing unless active.
    template <class... Args>
    void write(const Args&... args) {
        if (active_) {
            SaveIo io(recorder_->out_);
            (save_recorded(io, args), ...);
        }
    }
    /// Where bytes of the call's own making go; only while active.
    ByteWriter& out() { return recorder_->out_; }

private:
    // Two words: a call that changes the world opens one whether or not it records.
    Recorder* recorder_;
    bool active_ = false;
};

}  // namespace i2d
