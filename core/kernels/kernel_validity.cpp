#include "kernels/kernel_validity.hpp"

#include "kernels/kernel_check.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

ExitCode kernel_fault_code(const Kernel& kernel)
{
    return kernel.definition().from_expression ? ExitCode::input : ExitCode::plugin;
}

void require_usable_kernel(const Kernel& kernel, int dim, double k)
{
    const double integral = kernel_integral(kernel, dim, k).first;
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

} // namespace sphkern
