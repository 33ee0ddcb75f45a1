// SPDX-License-Identifier: MIT
// checksum64: a 64-bit checksum of bytes, the same on every platform, that tells any
// change of one byte (or of the length) for certain and any other change with
// probability 1 - 2^-64, fast enough to run over a snapshot as it is saved and restored.
//
// Design note: four lanes take 8-byte words in turn, each lane step
// lane = rotl(lane + word * k1, 31) * k2 a bijection of the word for a given lane and of
// the lane for a given word, so a changed word changes its lane and every later state of
// it; the lanes are summed through rotations, which keeps one changed lane changed, and
// the sum is mixed with the length by bijective steps. The four independent chains keep
// the multiplier busy: several gigabytes a second, where a byte at a time (FNV-1a, the
// state hash's) manages about one.
#pragma once

#include <cstddef>
#include <cstdint>

namespace i2d {

uint64_t checksum64(const void* data, std::size_t size);

}  // namespace i2d
