// The reciprocal lattice of a lattice's Bravais basis, the first Brillouin zone (as the
// shortest image of a wave vector) and the high-symmetry path through it: Γ-X-M-Γ-R (sc),
// Γ-X-W-L-Γ-K (fcc), Γ-H-N-Γ-P (bcc), Γ-M-K-Γ-A-L-H-A (hexagonal), Γ-X-M-Γ (square),
// Γ-M-K-Γ (triangular); other bases get Γ and the midpoints of their reciprocal vectors.
#pragma once

#include "lattices/lattice.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace sphkern {

struct ReciprocalLattice {
    int dimension = 0;
    Eigen::Matrix3d vectors; // columns b_i with a_i . b_j = 2 pi delta_ij (the first D are used)
    std::string bravais;     // "sc", "fcc", "bcc", "hexagonal", "square", "triangular" or "general"
};

ReciprocalLattice reciprocal_lattice(const Lattice& lattice);

// The image of kappa in the first Brillouin zone (the shortest kappa + G).
Eigen::Vector3d fold_to_first_zone(const ReciprocalLattice& reciprocal, const Eigen::Vector3d& kappa);

struct SymmetryPoint {
    std::string label; // "Γ", "X", ...
    Eigen::Vector3d kappa;
};

std::vector<SymmetryPoint> high_symmetry_path(const ReciprocalLattice& reciprocal);

} // namespace sphkern
