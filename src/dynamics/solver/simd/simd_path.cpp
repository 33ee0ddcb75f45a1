// SPDX-License-Identifier: MIT
// Choosing contact kernels by instruction set at run time.
#include "dynamics/solver/simd/simd_path.hpp"

#include "core/cpu_features.hpp"
#include "dynamics/solver/simd/contact_block.hpp"

namespace i2d {

bool simd_path_supported(SimdPath path) {
    switch (path) {
        case SimdPath::automatic:
        case SimdPath::scalar: return true;
        case SimdPath::sse2: return sse2_contact_kernels() != nullptr;
        case SimdPath::avx2: return avx2_contact_kernels() != nullptr && cpu_has_avx2();
        case SimdPath::avx512: return avx512_contact_kernels() != nullptr && cpu_has_avx512f();
        case SimdPath::neon: return neon_contact_kernels() != nullptr;
        case SimdPath::wasm128: return wasm128_contact_kernels() != nullptr;
        case SimdPath::count: break;
    }
    return false;
}

SimdPath widest_simd_path() {
    if (simd_path_supported(SimdPath::avx512)) {
        return SimdPath::avx512;
    }
    if (simd_path_supported(SimdPath::avx2)) {
        return SimdPath::avx2;
    }
    if (simd_path_supported(SimdPath::neon)) {
        return SimdPath::neon;
    }
    if (simd_path_supported(SimdPath::wasm128)) {
        return SimdPath::wasm128;
    }
    return simd_path_supported(SimdPath::sse2) ? SimdPath::sse2 : SimdPath::scalar;
}

const ContactKernels& contact_kernels_for(SimdPath path) {
    switch (path == SimdPath::automatic ? widest_simd_path() : path) {
        case SimdPath::sse2: return *sse2_contact_kernels();
        case SimdPath::avx2: return *avx2_contact_kernels();
        case SimdPath::avx512: return *avx512_contact_kernels();
        case SimdPath::neon: return *neon_contact_kernels();
        case SimdPath::wasm128: return *wasm128_contact_kernels();
        default: return scalar_contact_kernels();
    }
}

}  // namespace i2d
