// The wave vectors at which the rates over k are measured (k_change_bound.hpp): the first zone
// grid, folded into the first zone, Γ left out, one per orbit of the spectrum's symmetries.
// omega^2, and the long-wave limit along the wave vector's direction, are the same at every
// point of an orbit, so its other points need no evaluation of their own.
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"

#include <Eigen/Core>

#include <vector>

namespace sphkern {

class RateGrid {
public:
    // `grid` points per reciprocal axis (0: the zone scan's first grid); the symmetries are
    // those of `dispersion`'s spectrum (zone_symmetry.hpp).
    RateGrid(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int grid);

    std::size_t size() const { return kappa_.size(); } // orbits
    const Eigen::Vector3d& kappa(std::size_t i) const { return kappa_[i]; }
    std::size_t points() const { return points_; } // grid points the orbits stand for

private:
    std::vector<Eigen::Vector3d> kappa_; // one folded wave vector per orbit, in grid order
    std::size_t points_ = 0;
};

} // namespace sphkern
