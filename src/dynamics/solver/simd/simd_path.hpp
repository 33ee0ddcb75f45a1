// SPDX-License-Identifier: MIT
// SimdPath: which contact kernels a world uses. Every path gives the same bits; the
// widest the CPU supports is the fastest, and a world def (or a test) may force another.
#pragma once

#include <cstdint>


namespace i2d {

struct ContactKernels;

enum class SimdPath : uint8_t { automatic, scalar, sse2, avx2, avx512, neon, wasm128, count };

/// Whether this build and this CPU can run the path (automatic always can).
bool simd_path_supported(SimdPath path);
/// The path `automatic` stands for here: the widest supported.
SimdPath widest_simd_path();
/// The kernels of a supported path (automatic resolved).
const ContactKernels& contact_kernels_for(SimdPath path);

}  // namespace i2d
