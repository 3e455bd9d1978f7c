#include "kernels/kernel_integrals.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <numbers>

namespace sphkern {

namespace {

// q^n of the radial weights: up to q^2 as products (q * q is correctly rounded) at a fraction of
// pow's cost; the normalisation check integrates one at every k a scan over k evaluates.
double radial_power_of(double q, int n) { return n == 0 ? 1 : n == 1 ? q : n == 2 ? q * q : std::pow(q, n); }

} // namespace

double sphere_area(int dim) { return dim == 1 ? 2.0 : dim == 2 ? 2 * std::numbers::pi : 4 * std::numbers::pi; }

std::vector<double> piece_edges(const Kernel& kernel)
{
    std::vector<double> edges = {0.0};
    for (double b : kernel.definition().breakpoints) edges.push_back(b);
    edges.push_back(kernel.support());
    return edges;
}

std::pair<double, double> radial_integral(const Kernel& kernel, int dim, const std::function<double(double)>& f)
{
    double total = 0, error = 0;
    const auto edges = piece_edges(kernel);
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
        double piece_error = 0;
        total += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double q) { return f(q) * radial_power_of(q, dim - 1); }, edges[i], edges[i + 1], 15, 1e-15,
            &piece_error);
        error += piece_error;
    }
    return {sphere_area(dim) * total, sphere_area(dim) * error};
}

double kernel_integral_estimate(const Kernel& kernel, int dim, double k)
{
    double total = 0;
    const auto edges = piece_edges(kernel);
    for (std::size_t i = 0; i + 1 < edges.size(); ++i)
        total += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double q) { return kernel.w(q, dim, k) * radial_power_of(q, dim - 1); }, edges[i], edges[i + 1], 0);
    return sphere_area(dim) * total;
}

std::pair<double, double> kernel_integral(const Kernel& kernel, int dim, double k, int radial_power)
{
    return radial_integral(kernel, dim,
                           [&](double q) { return kernel.w(q, dim, k) * radial_power_of(q, radial_power); });
}

} // namespace sphkern
