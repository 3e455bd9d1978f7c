// Stability against k: the minimum of every branch of omega^2 over the Brillouin zone at
// evenly spaced k, and the k intervals where the lattice is stable (each edge between a
// stable and an unstable sample refined by bisection to 1e-6).
#pragma once

#include "analysis/acceptance.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct StabilitySample {
    double k = 0;
    std::vector<double> branch_minima; // ascending branch order; only the lowest is refined
    bool stable = true;
    double longitudinal = 0;           // of the lowest branch's minimum
};

struct StabilityOverK {
    std::string bravais;
    std::vector<StabilitySample> samples;
    std::vector<KInterval> stable;
};

// `steps` + 1 samples over [k_min, k_max]; `grid` points per reciprocal axis.
StabilityOverK stability_over_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                double gamma, int grid, int threads);

// The parts of the `accurate` intervals (condition (22)) where the lattice is stable too.
std::vector<KInterval> accurate_and_stable(const std::vector<KInterval>& accurate, const StabilityOverK& stability);

} // namespace sphkern
