// SPDX-License-Identifier: MIT
// The contact and hinge kernels four lanes at a time in WebAssembly SIMD, in the module
// built with -msimd128 (the JavaScript package loads the scalar module where the engine
// has no SIMD).
#include "dynamics/solver/simd/contact_block.hpp"

#if defined(__wasm_simd128__)
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/solver/simd/hinge_kernels.hpp"
#include "dynamics/solver/simd/lanes_wasm128.hpp"

namespace i2d {

const ContactKernels* wasm128_contact_kernels() {
    static const ContactKernels kernels{4,
                                        "wasm128",
                                        &KernelsOf<LanesWasm128>::warm_start,
                                        &KernelsOf<LanesWasm128>::solve,
                                        &KernelsOf<LanesWasm128>::restitution,
                                        &KernelsOf<LanesWasm128>::final_separations,
                                        &KernelsOf<LanesWasm128>::finish_pack,
                                        &HingeKernelsOf<LanesWasm128>::warm_start,
                                        &HingeKernelsOf<LanesWasm128>::solve};
    return &kernels;
}

}  // namespace i2d
#else
namespace i2d {
const ContactKernels* wasm128_contact_kernels() { return nullptr; }
}  // namespace i2d
#endif
