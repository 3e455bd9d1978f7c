#include "particles/smoothing_lengths.hpp"

#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace sphkern {

namespace {

double unit_ball(int dimension) { return dimension == 2 ? std::numbers::pi : 4 * std::numbers::pi / 3; }

} // namespace

double neighbour_number(double eta, double support, int dimension)
{
    return unit_ball(dimension) * std::pow(support * eta, dimension);
}

double eta_for_neighbour_number(double nh, double support, int dimension)
{
    return std::pow(nh / unit_ball(dimension), 1.0 / dimension) / support;
}

ParticleValues smoothing_lengths(const ParticleSet& set, const Kernel& kernel, const SmoothingSpec& spec,
                                 double mean_volume, int threads)
{
    const int dim = set.dimension;
    const double R = kernel.support();
    auto fill = [&](const auto& value) { return fill_particle_values(set.size(), threads, value); };
    auto uniform = [&](double value) { return fill([value](std::size_t) { return value; }); };
    switch (spec.rule) {
    case SmoothingRule::eta:
        if (!std::isfinite(spec.value) || spec.value <= 0 || spec.value > 100)
            fail_usage(fmt::format("--eta {}: expected a number in (0, 100]", spec.value));
        return uniform(spec.value * std::pow(mean_volume, 1.0 / dim));
    case SmoothingRule::nh:
        if (!std::isfinite(spec.value) || spec.value < 1 || spec.value > 1e5)
            fail_usage(fmt::format("--nh {}: expected a neighbour number in [1, 100000]", spec.value));
        return uniform(eta_for_neighbour_number(spec.value, R, dim) * std::pow(mean_volume, 1.0 / dim));
    case SmoothingRule::k:
        if (set.spacing <= 0)
            fail_input(fmt::format("{}: --k needs a lattice (h = k d); for other sets give --eta or --nh", set.name));
        if (!k_in_range(spec.value)) fail_usage(fmt::format("--k {}: expected a number in (0, 100]", spec.value));
        return uniform(spec.value * set.spacing);
    case SmoothingRule::file: break;
    }
    if (set.h.empty())
        fail_input(fmt::format("{}: the file has no smoothing lengths; give --eta E or --nh N", set.name));
    const double x = spec.support_per_h > 0 ? spec.support_per_h : set.support_per_h;
    if (!(x > 0) || !std::isfinite(x))
        fail_input(fmt::format("{}: the file's smoothing lengths need a convention: --support-per-h X, the support radius "
                               "over the stored h (GADGET and SPlisHSPlasH 1, SWIFT its kernel gamma, PySPH the kernel's R, "
                               "DualSPHysics 2), or give --eta E or --nh N",
                               set.name));
    return fill([&](std::size_t i) { return x * set.h[i] / R; });
}

} // namespace sphkern
