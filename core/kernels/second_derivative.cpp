#include "kernels/second_derivative.hpp"

#include "kernels/kernel.hpp"

#include <boost/math/differentiation/finite_difference.hpp>

#include <array>
#include <cmath>

namespace sphkern {

namespace {

// Boost's sixth-order stencil reaches 3 steps of (eps/168)^(1/7) ~ 2.8e-3 either side.
constexpr double central_reach = 0.01;
constexpr double one_sided_step = 2e-3;

// f'(x) from f(x), f(x + s), ..., f(x + 6 s), exact for polynomials of degree 6.
double one_sided(const Kernel& kernel, double q, int dim, double k, double s)
{
    static constexpr std::array<double, 7> c{-49.0 / 20, 6.0, -15.0 / 2, 20.0 / 3, -15.0 / 4, 6.0 / 5, -1.0 / 6};
    double sum = 0;
    for (int i = 0; i < 7; ++i) sum += c[i] * kernel.dw(q + i * s, dim, k);
    return sum / s;
}

} // namespace

double numerical_second_derivative(const Kernel& kernel, double q, int dim, double k)
{
    // The nearest place where dW/dr may have a kink: a breakpoint, a truncation, or q = 0.
    double nearest = 0, distance = q;
    auto consider = [&](double b) {
        if (std::abs(q - b) < distance) distance = std::abs(q - b), nearest = b;
    };
    for (double b : kernel.definition().breakpoints) consider(b);
    for (double b : kernel.definition().truncations) consider(b);
    if (distance >= central_reach)
        return boost::math::differentiation::finite_difference_derivative(
            [&](double x) { return kernel.dw(x, dim, k); }, q);
    // On a breakpoint itself the inner side counts, as q <= R counts as inside.
    const bool forward = q > nearest || q < central_reach;
    return one_sided(kernel, q, dim, k, forward ? one_sided_step : -one_sided_step);
}

} // namespace sphkern
