// SWIFT's kernel gamma of a kernel: its support over twice its standard deviation,
// H / (2 sigma), sigma^2 the kernel's variance per dimension (Dehnen & Aly 2012), so that
// SWIFT's h = H / gamma. Computed from the kernel, so it exists for every kernel whose second
// moment is positive.
#pragma once

#include "kernels/kernel.hpp"

namespace sphkern {

// By quadrature; NaN when the kernel's second moment is not positive (the 2D super-Gaussian's is -1).
double swift_gamma(const Kernel& kernel, int dim);

} // namespace sphkern
