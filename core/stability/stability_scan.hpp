// Stability of a lattice at one k: the minimum of every branch of omega^2 over the first
// Brillouin zone (a grid over the reciprocal cell, each branch's lowest grid point refined
// by coordinate-wise Brent minimisation), and the long-wave sound speed per direction.
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"

#include <vector>

namespace sphkern {

// omega^2 below -unstable_threshold (in c^2/d^2) anywhere means unstable.
inline constexpr double unstable_threshold = 1e-9;

struct BranchMinimum {
    int branch = 0;          // 0 = lowest eigenvalue
    double omega2 = 0;
    Eigen::Vector3d kappa;   // in the first Brillouin zone
    double longitudinal = 0; // of the mode there (1 longitudinal, 0 transverse)
};

// The long-wave limit: the lowest omega^2 / kappa^2 as kappa -> 0 over every direction
// (in c^2). A negative value is an instability however small the grid cannot see it:
// near its onset the unstable region shrinks onto Γ.
struct LongWaveMinimum {
    double omega2_over_kappa2 = 0;
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};
LongWaveMinimum long_wave_minimum(const Dispersion& dispersion);

struct StabilityScan {
    std::vector<BranchMinimum> minima; // one per branch
    LongWaveMinimum long_wave;
    bool stable = true; // no omega^2 and no long-wave omega^2 / kappa^2 below -unstable_threshold
    int grid_points = 0;
    const BranchMinimum& lowest() const { return minima.front(); }
};

// `per_axis` grid points along each reciprocal vector (even, so that Γ and the zone
// boundary are on the grid).
// `refine_all` false refines only the lowest branch (the stability verdict); the others keep
// their grid minima.
StabilityScan scan_brillouin_zone(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int per_axis,
                                  int threads = 1, bool refine_all = true);

// The grid the command line uses in D dimensions: 96 (2D), 24 (3D) points per axis.
int default_grid(int dimension);

// Long waves along a unit direction n: omega / (c kappa) of the acoustic branches (the
// lowest D), from omega^2 / kappa^2 at kappa = 1e-3 and 2e-3 extrapolated to kappa -> 0.
struct SoundSpeed {
    Eigen::Vector3d direction;
    std::vector<double> speeds;  // ascending, in units of c; negative: omega^2 < 0 (its square root, signed)
    double longitudinal = 0;     // the speed of the most longitudinal acoustic mode
};
SoundSpeed long_wave_sound_speed(const Dispersion& dispersion, const Eigen::Vector3d& direction);

} // namespace sphkern
