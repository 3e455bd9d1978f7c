// Stability of a lattice at one k: the minimum of every branch of omega^2 over the first
// Brillouin zone (a grid over the reciprocal cell, each branch's lowest grid point refined
// by coordinate-wise Brent minimisation), and the long-wave sound speed per direction.
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/mode_kind.hpp"

#include <cmath>
#include <string>

#include <vector>

namespace sphkern {

// omega^2 below -unstable_threshold (in c^2/d^2) anywhere means unstable.
inline constexpr double unstable_threshold = 1e-9;

struct BranchMinimum {
    int branch = 0; // 0 = lowest eigenvalue
    double omega2 = 0;
    Eigen::Vector3d kappa;   // in the first Brillouin zone
    double longitudinal = 0; // of the mode there (1 longitudinal, 0 transverse), at the folded kappa
};

// The long-wave limit: the lowest omega^2 / kappa^2 of the acoustic branches as kappa -> 0
// over every direction (in c^2). A negative value is an instability however small the grid
// cannot see it: near its onset the unstable region shrinks onto Γ.
struct LongWaveMinimum {
    double omega2_over_kappa2 = 0;
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};
LongWaveMinimum long_wave_minimum(const Dispersion& dispersion);

// The answer at one k: stable; weak (some mode grows, but more slowly than the horizon: its
// growth time 1/sqrt(-omega^2) exceeds it, or only long waves grow); unstable.
enum class Verdict { stable, weak, unstable };
std::string verdict_name(Verdict verdict);
// The growth time, in d/c, that separates weak from unstable unless told otherwise.
inline constexpr double default_horizon = 100;
// Throws Error(usage) naming `what` unless 0 < horizon <= 1e12.
void check_horizon(double horizon, const std::string& what);

struct StabilityScan {
    std::vector<BranchMinimum> minima; // one per branch, lowest first
    LongWaveMinimum long_wave;
    bool stable = true;  // no omega^2 and no long-wave omega^2 / kappa^2 below -unstable_threshold
    int grid_points = 0; // points of the last grid
    int grid = 0;        // points per axis of the last grid
    int levels = 0;      // grids used
    bool converged = false;
    double change = 0;       // of the minimum between the last two grids
    double floor = INFINITY; // the lowest valley floor of the lowest branch away from Γ
    ModeCharacter mode;      // of the lowest branch at its minimum, judged at its unfolded wave vector
    const BranchMinimum& lowest() const { return minima.front(); }
    // 1 / sqrt(-omega^2) in d/c of the fastest growing mode; infinite when none grows at a finite kappa.
    double growth_time() const;
    Verdict verdict(double horizon) const;
};

// The scan at one k. The lowest branch (the verdict) by lowest_branch_minimum from
// `start_grid` points per axis (0: the default, 8 in 3D, 32 in 2D); `refine_all` also
// refines the other branches from their minima on the last grid.
StabilityScan scan_brillouin_zone(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int start_grid,
                                  int threads = 1, bool refine_all = true);

// The first grid per axis in D dimensions: 32 (2D), 8 (3D).
int default_grid(int dimension);

// Long waves along a unit direction n: omega / (c kappa) of the acoustic branches (the
// lowest D), from omega^2 / kappa^2 at kappa = 1e-3 and 2e-3 extrapolated to kappa -> 0.
struct SoundSpeed {
    Eigen::Vector3d direction;
    std::vector<double> speeds; // ascending, in units of c; negative: omega^2 < 0 (its square root, signed)
    double longitudinal = 0;    // the speed of the most longitudinal acoustic mode
};
SoundSpeed long_wave_sound_speed(const Dispersion& dispersion, const Eigen::Vector3d& direction);

} // namespace sphkern
