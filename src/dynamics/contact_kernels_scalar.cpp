// SPDX-License-Identifier: MIT
// The contact and hinge kernels one lane at a time: the path every platform has, and the one the
// overflow colour takes on every path.
#include "dynamics/contact_kernels.hpp"
#include "dynamics/hinge_kernels.hpp"
#include "math/lanes_scalar.hpp"

namespace i2d {

const ContactKernels& scalar_contact_kernels() {
    static const ContactKernels kernels{1,
                                        "scalar",
                                        &KernelsOf<Lanes1>::warm_start,
                                        &KernelsOf<Lanes1>::solve,
                                        &KernelsOf<Lanes1>::restitution,
                                        &HingeKernelsOf<Lanes1>::warm_start,
                                        &HingeKernelsOf<Lanes1>::solve};
    return kernels;
}

}  // namespace i2d
