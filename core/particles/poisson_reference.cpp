#include "particles/poisson_reference.hpp"

#include "kernels/kernel_integrals.hpp"

#include <cmath>

namespace sphkern {

double kernel_square_integral(const Kernel& kernel, int dim, double k)
{
    return radial_integral(kernel, dim, [&](double q) { return std::pow(kernel.w(q, dim, k), 2); }).first;
}

double poisson_rms_e0(const Kernel& kernel, int dim, double k, double eta, std::size_t n)
{
    const double N = static_cast<double>(n), eta_d = std::pow(eta, dim);
    const double mean = kernel.w(0, dim, k) / eta_d - 1 / N;
    const double variance = (N - 1) * (kernel_square_integral(kernel, dim, k) / eta_d / N - 1 / (N * N));
    return std::sqrt(variance + mean * mean);
}

} // namespace sphkern
