// The symmetries of a lattice's spectrum: integer matrices N acting on wave vectors in
// fractional coordinates of the reciprocal vectors (kappa = B f -> B N f) that leave every
// omega^2 unchanged. They let a grid over the reciprocal cell be evaluated on one point per
// orbit (the irreducible part of the zone) and filled in by symmetry.
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"

#include <Eigen/Core>

#include <vector>

namespace sphkern {

// The orthogonal maps of the reciprocal lattice with entries -1, 0, 1 in its basis (the
// point group of the Bravais lattice, inversion included), each kept only if the eigenvalues
// agree at two generic wave vectors: a motif that breaks a symmetry of its Bravais lattice
// loses it. The identity is always first.
std::vector<Eigen::Matrix3i> zone_symmetries(const Dispersion& dispersion, const ReciprocalLattice& reciprocal);

} // namespace sphkern
