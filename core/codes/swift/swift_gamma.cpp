#include "codes/swift/swift_gamma.hpp"

#include "kernels/kernel_integrals.hpp"

#include <cmath>

namespace sphkern {

double swift_gamma(const Kernel& kernel, int dim)
{
    // The variance per dimension in units of h^2, at a k where the kernel does not depend on k.
    const double k = 1;
    const double variance = kernel_integral(kernel, dim, k, 2).first / kernel_integral(kernel, dim, k).first / dim;
    return variance > 0 ? kernel.support() / (2 * std::sqrt(variance)) : NAN;
}

} // namespace sphkern
