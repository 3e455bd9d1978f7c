// The last step of the zone scan where the lattice is unstable: the depth of the lowest
// valley to the zone tolerance. Coordinate sweeps stall in a valley that runs diagonally to
// the axes; Powell's remedy is to also search along the net move of each sweep, which
// follows the valley floor.
#pragma once

#include "stability/dispersion.hpp"

#include <Eigen/Core>

#include <utility>

namespace sphkern {

// From fractions f with the lowest branch at `value`: rounds of one coordinate sweep and a
// Brent search along that sweep's move (within `reach`), until a round improves the value by
// at most `tolerance` (c^2/d^2) or after `rounds`; returns the fractions and the value.
std::pair<Eigen::Vector3d, double> polish_minimum(const Dispersion& dispersion,
                                                  const Eigen::Matrix3d& reciprocal_vectors, Eigen::Vector3d f,
                                                  double value, double reach, double (*tolerance)(double), int rounds);

} // namespace sphkern
