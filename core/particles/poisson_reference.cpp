#include "particles/poisson_reference.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <numbers>

namespace sphkern {

double kernel_square_integral(const Kernel& kernel, int dim, double k)
{
    auto radial = [&](double q) {
        const double w = kernel.w(q, dim, k);
        return w * w * (dim == 3 ? 4 * std::numbers::pi * q * q : 2 * std::numbers::pi * q);
    };
    // Kernels are piecewise: 15 levels of bisection find their joints to far below the
    // tolerance asked.
    return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(radial, 0.0, kernel.support(), 15, 1e-12);
}

double poisson_rms_e0(const Kernel& kernel, int dim, double k, double eta, std::size_t n)
{
    const double N = static_cast<double>(n), eta_d = std::pow(eta, dim);
    const double mean = kernel.w(0, dim, k) / eta_d - 1 / N;
    const double variance = (N - 1) * (kernel_square_integral(kernel, dim, k) / eta_d / N - 1 / (N * N));
    return std::sqrt(variance + mean * mean);
}

} // namespace sphkern
