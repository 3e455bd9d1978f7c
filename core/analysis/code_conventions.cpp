#include "analysis/code_conventions.hpp"

#include "kernels/kernel_integrals.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

const std::vector<CodeConvention>& code_conventions()
{
    static const std::vector<CodeConvention> all{{"pysph", "hdx"},
                                                 {"dualsphysics", "coefh"},
                                                 {"swift", "eta"},
                                                 {"gadget", "N_ngb"},
                                                 {"splishsplash", "H/r_p"}};
    return all;
}

const CodeConvention& code_convention(const std::string& name, const std::string& what)
{
    std::string names;
    for (const auto& c : code_conventions()) {
        if (c.name == name) return c;
        names += (names.empty() ? "" : ", ") + c.name;
    }
    throw Error(ExitCode::usage, fmt::format("{} {}: unknown convention, expected one of {}", what, name, names));
}

double swift_gamma(const Kernel& kernel, int dim)
{
    // The variance per dimension in units of h^2, at a k where the kernel does not depend on k.
    const double k = 1;
    const double variance = kernel_integral(kernel, dim, k, 2).first / kernel_integral(kernel, dim, k).first / dim;
    return variance > 0 ? kernel.support() / (2 * std::sqrt(variance)) : NAN;
}

std::string convention_undefined(const CodeConvention& convention, const Kernel& kernel, int dim)
{
    if (convention.name == "swift" && !std::isfinite(swift_gamma(kernel, dim)))
        return fmt::format("not defined: {}'s second moment in {}D is not positive, so SWIFT's kernel gamma is not",
                           kernel.name(), dim);
    return {};
}

double in_convention(const CodeConvention& convention, const Kernel& kernel, int dim, double a_p, double k)
{
    const double volume = a_p, spacing = std::pow(volume, 1.0 / dim); // in units of d^D and d
    const double support = kernel.support() * k;                        // H / d
    if (convention.name == "pysph") return k / spacing;
    if (convention.name == "dualsphysics") return support / (2 * std::sqrt(double(dim)) * spacing);
    if (convention.name == "swift") return support / (swift_gamma(kernel, dim) * spacing);
    if (convention.name == "gadget") {
        const double ball = dim == 3 ? 4 * M_PI / 3 : dim == 2 ? M_PI : 2;
        return ball * std::pow(support, dim) / volume;
    }
    return 2 * support / spacing; // splishsplash
}

} // namespace sphkern
