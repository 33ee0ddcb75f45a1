// SPDX-License-Identifier: MIT
// The contact and hinge kernels four lanes at a time in SSE2, on every x86-64 CPU.
#include "dynamics/solver/simd/contact_block.hpp"

#if defined(__SSE2__) || defined(_M_X64)
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/solver/simd/hinge_kernels.hpp"
#include "dynamics/solver/simd/lanes_sse2.hpp"

namespace i2d {

const ContactKernels* sse2_contact_kernels() {
    static const ContactKernels kernels{4,
                                        "sse2",
                                        &KernelsOf<LanesSse2>::warm_start,
                                        &KernelsOf<LanesSse2>::solve,
                                        &KernelsOf<LanesSse2>::restitution,
                                        &KernelsOf<LanesSse2>::final_separations,
                                        &KernelsOf<LanesSse2>::finish_pack,
                                        &HingeKernelsOf<LanesSse2>::warm_start,
                                        &HingeKernelsOf<LanesSse2>::solve};
    return &kernels;
}

}  // namespace i2d
#else
namespace i2d {
const ContactKernels* sse2_contact_kernels() { return nullptr; }
}  // namespace i2d
#endif
