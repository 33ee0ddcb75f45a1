// SPDX-License-Identifier: MIT
// The contact and hinge kernels four lanes at a time in NEON, on every AArch64 CPU.
#include "dynamics/solver/simd/contact_block.hpp"

#if defined(__aarch64__) || defined(_M_ARM64)
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/solver/simd/hinge_kernels.hpp"
#include "dynamics/solver/simd/lanes_neon.hpp"

namespace i2d {

const ContactKernels* neon_contact_kernels() {
    static const ContactKernels kernels{4,
                                        "neon",
                                        &KernelsOf<LanesNeon>::warm_start,
                                        &KernelsOf<LanesNeon>::solve,
                                        &KernelsOf<LanesNeon>::restitution,
                                        &KernelsOf<LanesNeon>::final_separations,
                                        &KernelsOf<LanesNeon>::finish_pack,
                                        &HingeKernelsOf<LanesNeon>::warm_start,
                                        &HingeKernelsOf<LanesNeon>::solve};
    return &kernels;
}

}  // namespace i2d
#else
namespace i2d {
const ContactKernels* neon_contact_kernels() { return nullptr; }
}  // namespace i2d
#endif
