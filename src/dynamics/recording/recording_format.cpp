// SPDX-License-Identifier: MIT
#include "dynamics/recording/recording_format.hpp"

#include "core/checksum.hpp"

namespace i2d {

namespace {

constexpr std::size_t op_offset = 4, size_offset = 5, size_check_offset = 9;

void put_u32(unsigned char* at, uint32_t value) {
    for (int i = 0; i < 4; ++i) {
        at[i] = static_cast<unsigned char>(value >> (8 * i));
    }
}

}  // namespace

uint32_t record_size_check(const unsigned char* record) {
    return uint32_t(checksum64(record + op_offset, size_check_offset - op_offset));
}

void seal_record(unsigned char* record, std::size_t payload_size) {
    put_u32(record + size_offset, uint32_t(payload_size));
    put_u32(record + size_check_offset, record_size_check(record));
    put_u32(record, uint32_t(checksum64(record + op_offset, record_header_size - op_offset + payload_size)));
}

}  // namespace i2d
