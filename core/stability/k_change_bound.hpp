// How fast omega^2 of the lowest branch changes with k, wave vector by wave vector (the method
// document, "Over k"). At a simple eigenvalue d(omega^2)/dk = xi^H (dM/dk) xi
// (Hellmann-Feynman), measured by central differences in k (k +- 1e-5 k) on the first zone
// grid (one point per orbit, rate_grid.hpp), at any other kappa on demand, and along the same
// directions for the long-wave limit.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/rate_grid.hpp"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace sphkern {

// The rates are sampled in kappa and in k: over a cell of k they are taken as the largest at
// its ends and its middle, times this (an estimate of their supremum, not a proof).
inline constexpr double k_change_safety = 2;

struct OmegaRate {
    double omega2 = 0; // the lowest omega^2 (c^2/d^2), or omega^2 / kappa^2 in the long-wave limit (c^2)
    double rate = 0;   // |d omega2 / dk|
};

class KChangeRates {
public:
    KChangeRates(const Kernel& kernel, const Lattice& lattice, const RateGrid& grid, double k, double gamma,
                 HModel h_model);

    double k() const { return k_; }
    std::size_t size() const { return grid_.size(); } // the grid's orbits
    const OmegaRate& on_grid(std::size_t i) const { return grid_[i]; }
    OmegaRate at(const Eigen::Vector3d& kappa) const;
    // Along the direction of grid point i; one site only (several: empty).
    const std::vector<OmegaRate>& long_wave() const { return long_wave_; }

private:
    double k_, eps_;
    Dispersion lo_, hi_;
    std::vector<OmegaRate> grid_, long_wave_;
};

} // namespace sphkern
