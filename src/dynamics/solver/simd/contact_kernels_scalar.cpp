// SPDX-License-Identifier: MIT
// The contact and hinge kernels one lane at a time: the path every platform has, and the one the
// overflow colour takes on every path.
#include "dynamics/solver/simd/contact_kernels.hpp"
#include "dynamics/solver/simd/hinge_kernels.hpp"
#include "dynamics/solver/simd/lanes_scalar.hpp"

namespace i2d {

const ContactKernels& scalar_contact_kernels() {
    static const ContactKernels kernels{1,
                                        "scalar",
                                        &KernelsOf<Lanes1>::warm_start,
                                        &KernelsOf<Lanes1>::solve,
                                        &KernelsOf<Lanes1>::restitution,
                                        &KernelsOf<Lanes1>::final_separations,
                                        &KernelsOf<Lanes1>::finish_pack,
                                        &HingeKernelsOf<Lanes1>::warm_start,
                                        &HingeKernelsOf<Lanes1>::solve};
    return kernels;
}

}  // namespace i2d
