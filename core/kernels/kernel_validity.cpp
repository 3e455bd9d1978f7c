#include "kernels/kernel_validity.hpp"

#include "kernels/kernel_integrals.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

namespace sphkern {

ExitCode kernel_fault_code(const Kernel& kernel)
{
    return kernel.definition().from_expression ? ExitCode::input : ExitCode::plugin;
}

void require_usable_kernel(const Kernel& kernel, int dim, double k)
{
    const double integral = kernel_integral_estimate(kernel, dim, k);
    if (std::isfinite(integral) && integral > 0) return;
    throw Error(kernel_fault_code(kernel),
                fmt::format("kernel {} ({}): its {}D normalisation is {:.6g} at k = {:.6g}, expected a finite "
                            "positive integral (are the parameters in the kernel's valid range?)",
                            kernel.label(), kernel.definition().source, dim, integral, k));
}

void fail_non_finite_kernel(const Kernel& kernel, const char* what, double q, int dim, double k)
{
    throw Error(kernel_fault_code(kernel),
                fmt::format("kernel {} ({}): {} is not finite at q = {:.17g} (D = {}, k = {:.17g}); no result is given",
                            kernel.label(), kernel.definition().source, what, q, dim, k));
}

void fail_overflowing_kernel(const Kernel& kernel, int dim, double k, const std::string& sum,
                             std::span<const double> q_values)
{
    std::vector<double> qs(q_values.begin(), q_values.end());
    const int samples = 256;
    for (int i = 0; i <= samples; ++i) qs.push_back(kernel.support() * i / samples);
    double largest = 0;
    const char* what = "W";
    for (double q : qs)
        for (const auto& [name, value] :
             {std::pair{"W", kernel.w(q, dim, k)}, std::pair{"dW/dr", kernel.dw(q, dim, k)}})
            if (std::abs(value) > largest) largest = std::abs(value), what = name;
    if (!(largest > 1e100)) return;
    double from = INFINITY, to = -INFINITY;
    for (double q : qs)
        if (std::abs(kernel.w(q, dim, k)) > 1e-6 * largest || std::abs(kernel.dw(q, dim, k)) > 1e-6 * largest)
            from = std::min(from, q), to = std::max(to, q);
    throw Error(
        kernel_fault_code(kernel),
        fmt::format("kernel {} ({}): {} reaches {:.4g} for q in [{:.6g}, {:.6g}] (D = {}, k = {:.6g}), and {} of its "
                    "finite values overflows a double; expected values of order 1",
                    kernel.label(), kernel.definition().source, what, largest, from, to, dim, k, sum));
}

void fail_non_finite_sum(const Kernel& kernel, int dim, double k, const std::string& where, const std::string& scale,
                         std::span<const double> neighbour_q)
{
    for (double q : neighbour_q) {
        if (!std::isfinite(kernel.w(q, dim, k))) fail_non_finite_kernel(kernel, "W", q, dim, k);
        if (!std::isfinite(kernel.dw(q, dim, k))) fail_non_finite_kernel(kernel, "dW/dr", q, dim, k);
    }
    const int samples = 64;
    for (int i = 0; i <= samples; ++i) {
        const double q = kernel.support() * i / samples;
        if (!std::isfinite(kernel.w(q, dim, k))) fail_non_finite_kernel(kernel, "W", q, dim, k);
        if (!std::isfinite(kernel.dw(q, dim, k))) fail_non_finite_kernel(kernel, "dW/dr", q, dim, k);
    }
    fail_overflowing_kernel(kernel, dim, k, "the sum at " + where, neighbour_q);
    fail_input(fmt::format("{} is outside what kernel {} can be evaluated at: the sums at {} overflow (expected a "
                           "smoothing length of order the particle spacing)",
                           scale, kernel.label(), where));
}

} // namespace sphkern
