#include "particles/smoothing_lengths.hpp"

#include "particles/density_smoothing.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

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

PerParticle smoothing_lengths(const ParticleSet& set, const Kernel& kernel, const SmoothingSpec& spec,
                              double mean_volume, int threads, MeasureCollector* measures)
{
    if (measures && spec.rule != SmoothingRule::density)
        throw std::logic_error("smoothing_lengths: only the density's solve measures the particles");
    const int dim = set.dimension;
    const double R = kernel.support();
    auto uniform = [&](double value) { return PerParticle::same(set.size(), value); };
    switch (spec.rule) {
    case SmoothingRule::eta: return uniform(spec.value * std::pow(mean_volume, 1.0 / dim));
    case SmoothingRule::nh:
        return uniform(eta_for_neighbour_number(spec.value, R, dim) * std::pow(mean_volume, 1.0 / dim));
    case SmoothingRule::k:
        if (set.spacing <= 0) throw std::logic_error("smoothing_lengths: k without a lattice spacing");
        return uniform(spec.value * set.spacing);
    case SmoothingRule::density:
        return density_smoothing_lengths(kernel, set, spec.value, mean_volume, threads, spec.by_number,
                                         spec.self_weight, measures);
    case SmoothingRule::file: break;
    }
    const double x = spec.support_per_h > 0 ? spec.support_per_h : set.support_per_h;
    if (set.h.size() != set.size() || !(x > 0))
        throw std::logic_error("smoothing_lengths: a file h without h or a convention");
    return PerParticle::of(fill_particle_values(set.size(), threads, [&](std::size_t i) { return x * set.h[i] / R; }));
}

} // namespace sphkern
