// SPDX-License-Identifier: MIT
#include "dynamics/recording/recorder.hpp"

namespace i2d {

Recorder::Recorder(RecordWriter write, void* context, int32_t& lock_depth)
    : write_(write), context_(context), lock_depth_(lock_depth) {}

void Recorder::write_header() {
    std::vector<unsigned char> header;
    ByteWriter out(header);
    out.bytes(recording_magic, sizeof recording_magic);
    out.u32(recording_format_version);
    out.u32(0);
    ++lock_depth_;
    write_(header.data(), header.size(), context_);
    --lock_depth_;
}

// The record's size and checks go in front of what the scope wrote.
void Recorder::emit() {
    seal_record(record_.data(), record_.size() - record_header_size);
    ++lock_depth_;
    write_(record_.data(), record_.size(), context_);
    --lock_depth_;
}

RecordScope::RecordScope(Recorder* recorder, RecordedOp op) : recorder_(recorder) {
    if (recorder_ == nullptr || recorder_->depth_++ > 0) {
        return;
    }
    active_ = true;
    recorder_->record_.clear();
    ByteWriter& out = recorder_->out_;
    out = ByteWriter(recorder_->record_);
    out.u32(0);  // checksum, filled in by emit
    out.u8(static_cast<uint8_t>(op));
    out.u32(0);  // payload size, likewise
    out.u32(0);  // the size's check, likewise
}

RecordScope::~RecordScope() {
    if (recorder_ == nullptr) {
        return;
    }
    --recorder_->depth_;
    if (active_) {
        recorder_->emit();
    }
}

}  // namespace i2d
