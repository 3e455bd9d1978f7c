#include "kernels/fourier_transform.hpp"

#include "kernels/kernel.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/bessel.hpp>

#include <algorithm>
#include <cmath>

namespace sphkern {

double radial_fourier_transform(const std::function<double(double)>& f, double support, const std::vector<double>& cuts,
                                double kh, int dim)
{
    using boost::math::constants::pi;
    auto integrand = [&](double q) {
        const double x = kh * q;
        if (dim == 1) return 2 * f(q) * std::cos(x);
        if (dim == 2) return 2 * pi<double>() * f(q) * q * boost::math::cyl_bessel_j(0, x);
        return 4 * pi<double>() * f(q) * q * q * (x < 1e-8 ? 1 - x * x / 6 : std::sin(x) / x);
    };
    std::vector<double> edges{0.0};
    for (double c : cuts)
        if (c > 0 && c < support) edges.push_back(c);
    edges.push_back(support);
    std::sort(edges.begin(), edges.end());
    const double part = pi<double>() / std::max(kh, 1.0); // half an oscillation or shorter
    double sum = 0;
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
        const double a = edges[i], b = edges[i + 1];
        if (b <= a) continue;
        const int n = static_cast<int>(std::ceil((b - a) / part));
        for (int j = 0; j < n; ++j)
            sum += boost::math::quadrature::gauss_kronrod<double, 21>::integrate(integrand, a + (b - a) * j / n,
                                                                                 a + (b - a) * (j + 1) / n, 3, 1e-11);
    }
    return sum;
}

double fourier_transform_by_quadrature(const Kernel& kernel, double kh, int dim, double k)
{
    std::vector<double> cuts = kernel.definition().breakpoints;
    for (double t : kernel.definition().truncations) cuts.push_back(t);
    return radial_fourier_transform([&](double q) { return kernel.w_truncated(q, dim, k); }, kernel.support(), cuts, kh,
                                    dim);
}

} // namespace sphkern
