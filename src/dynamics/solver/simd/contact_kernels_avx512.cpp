// SPDX-License-Identifier: MIT
// The contact and hinge kernels sixteen lanes at a time in AVX-512F. Like the AVX2 file, this one
// alone is built for its instruction set (-mavx512f, see src/CMakeLists.txt), called only
// after the CPU said it has it, and shares no inline code with the rest of the library.
#include "dynamics/solver/simd/contact_block.hpp"

#if defined(__AVX512F__)
#if defined(__GNUC__) && !defined(__clang__)
// GCC 12's own AVX-512 intrinsics start from deliberately undefined registers, which its
// flow analysis then reports as maybe uninitialized (a false positive later GCCs fixed).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/solver/simd/hinge_kernels.hpp"
#include "dynamics/solver/simd/lanes_avx512.hpp"

namespace i2d {

const ContactKernels* avx512_contact_kernels() {
    static const ContactKernels kernels{16,
                                        "avx512",
                                        &KernelsOf<LanesAvx512>::warm_start,
                                        &KernelsOf<LanesAvx512>::solve,
                                        &KernelsOf<LanesAvx512>::restitution,
                                        &KernelsOf<LanesAvx512>::final_separations,
                                        &KernelsOf<LanesAvx512>::finish_pack,
                                        &HingeKernelsOf<LanesAvx512>::warm_start,
                                        &HingeKernelsOf<LanesAvx512>::solve};
    return &kernels;
}

}  // namespace i2d
#else
namespace i2d {
const ContactKernels* avx512_contact_kernels() { return nullptr; }
}  // namespace i2d
#endif
