// SPDX-License-Identifier: MIT
// The contact and hinge kernels eight lanes at a time in AVX2. This file alone is built with
// -mavx2 (see src/CMakeLists.txt), and it is called only after the CPU said it has AVX2,
// so that one library serves every x86-64 CPU. It shares no inline code with the rest
// of the library: everything it instantiates has internal linkage (lanes_avx2.hpp), so
// the linker cannot hand AVX2 code to a caller on another CPU.
#include "dynamics/solver/simd/contact_block.hpp"

#if defined(__AVX2__)
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/solver/simd/hinge_kernels.hpp"
#include "dynamics/solver/simd/lanes_avx2.hpp"

namespace i2d {

const ContactKernels* avx2_contact_kernels() {
    static const ContactKernels kernels{8,
                                        "avx2",
                                        &KernelsOf<LanesAvx2>::warm_start,
                                        &KernelsOf<LanesAvx2>::solve,
                                        &KernelsOf<LanesAvx2>::restitution,
                                        &KernelsOf<LanesAvx2>::final_separations,
                                        &KernelsOf<LanesAvx2>::finish_pack,
                                        &HingeKernelsOf<LanesAvx2>::warm_start,
                                        &HingeKernelsOf<LanesAvx2>::solve};
    return &kernels;
}

}  // namespace i2d
#else
namespace i2d {
const ContactKernels* avx2_contact_kernels() { return nullptr; }
}  // namespace i2d
#endif
