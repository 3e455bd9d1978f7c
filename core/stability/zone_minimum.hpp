// The minimum of the lowest branch of omega^2 over the Brillouin zone to a stated
// tolerance: grids of growing size over the reciprocal cell (one point per orbit of the
// spectrum's symmetries), each refined locally from the grid minimum and from every grid
// valley, plus minima along the high-symmetry lines; the grid is doubled until the minimum
// changes by less than the tolerance between two grids.
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/zone_grid.hpp"

#include <Eigen/Core>

#include <optional>

namespace sphkern {

// Two successive grids agree when their minima differ by at most this, in c^2/d^2.
inline constexpr double zone_tolerance_absolute = 1e-10;
inline constexpr double zone_tolerance_relative = 1e-4; // of the minimum
// Valleys refined per grid, lowest first (symmetric copies count once).
inline constexpr int zone_valleys = 6;
// Grids per axis: the first by default (8 in 3D, 32 in 2D); they double up to four times that.
int zone_start_grid(int dimension);

struct ZoneMinimum {
    double omega2 = 0;                                  // the lowest omega^2 found
    Eigen::Vector3d fraction = Eigen::Vector3d::Zero(); // where, in fractions of the reciprocal vectors
    double floor = INFINITY;      // the lowest refined valley floor away from Γ (a margin of stability)
    int grid = 0;                 // points per axis of the last grid
    int levels = 0;               // grids used
    bool converged = false;       // the last two grids agreed within the tolerance
    double change = 0;            // how much the minimum moved between the last two grids
    std::optional<ZoneGrid> last; // the last grid, for the other branches
};

// `start_grid` points per axis at first (0: zone_start_grid).
ZoneMinimum lowest_branch_minimum(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int start_grid,
                                  int threads);

} // namespace sphkern
