// SPDX-License-Identifier: MIT
// What the CPU running the library can do, asked once at run time.
#pragma once

namespace i2d {

/// The CPU (and the operating system, which must save the wide registers) supports AVX2.
bool cpu_has_avx2();
/// The same for AVX-512F (and its 512-bit register state).
bool cpu_has_avx512f();

}  // namespace i2d
