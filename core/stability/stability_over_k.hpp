// Stability against k: the verdict of the Brillouin-zone scan (one scanner, the same at
// every k whoever asks) at evenly spaced k for the curves; the stable intervals from a cover
// of k of their own (verdict_cover.hpp), exact to 1e-6 in k whatever the step count.
#pragma once

#include "analysis/acceptance.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/stability_scan.hpp"

#include <string>
#include <vector>

namespace sphkern {

// Changes of verdict are found to this width in k.
inline constexpr double stability_k_tolerance = 1e-6;

struct StabilitySample {
    double k = 0;
    std::vector<double> branch_minima;            // ascending branch order; only the lowest is refined
    bool stable = true;                           // no omega^2 below -1e-9 anywhere (long waves included)
    Verdict verdict = Verdict::stable;            // at the horizon
    double longitudinal = 0;                      // of the lowest branch's minimum, at the folded wave vector
    Eigen::Vector3d at = Eigen::Vector3d::Zero(); // the wave vector of the lowest omega^2, first zone
    ModeCharacter mode;                           // of that mode
    double growth_time = INFINITY;                // 1 / sqrt(-omega^2) in d/c
    double floor = INFINITY;                      // the lowest valley floor away from Γ
    double long_wave = 0;                         // the long-wave minimum of omega^2 / kappa^2
};

struct StabilityOverK {
    std::string bravais;
    double horizon = default_horizon;
    std::vector<StabilitySample> samples; // the evenly spaced k
    std::vector<StabilitySample> between; // the other k the intervals looked at, ascending
    std::vector<KInterval> stable;        // no mode grows
    std::vector<KInterval> usable;        // no mode grows faster than the horizon (stable or weak)
};

// `steps` + 1 samples over [k_min, k_max] (the curve; the intervals do not depend on it);
// `grid` the first zone grid per axis (0: default).
StabilityOverK stability_over_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                double gamma, int grid, int threads, double horizon = default_horizon,
                                HModel h_model = HModel::fixed);

// The sample at one k, as every mode computes it.
StabilitySample stability_sample(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int grid,
                                 int threads, double horizon);

// The parts of the `accurate` intervals (condition (22)) where the lattice is usable (no
// mode grows faster than the horizon).
std::vector<KInterval> accurate_and_stable(const std::vector<KInterval>& accurate, const StabilityOverK& stability);

} // namespace sphkern
