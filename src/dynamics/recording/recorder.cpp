// SPDX-License-Identifier: MIT
#include "dynamics/recording/recorder.hpp"

#include "core/checksum.hpp"

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

// The record's size and checksum go in front of what the scope wrote.
void Recorder::emit() {
    const std::size_t payload = record_.size() - record_header_size;
    unsigned char* size_at = record_.data() + 5;
    for (int i = 0; i < 4; ++i) {
        size_at[i] = static_cast<unsigned char>(payload >> (8 * i));
    }
    const uint64_t sum = checksum64(record_.data() + 4, record_.size() - 4);
    for (int i = 0; i < 4; ++i) {
        record_[std::size_t(i)] = static_cast<unsigned char>(sum >> (8 * i));
    }
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
