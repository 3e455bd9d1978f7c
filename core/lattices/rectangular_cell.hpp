// A lattice's rectangular cell: the smallest lattice translations along each axis as its
// edges, and every site inside it as its motif. fcc as shipped (close-packed layers along z)
// has a cell of 1 x sqrt(3) x sqrt(6) with 6 sites, hcp 1 x sqrt(3) x sqrt(8/3) with 4, the
// triangular lattice 1 x sqrt(3) with 2. A block cut from it is a rectangular periodic box,
// which the codes' initial conditions (SWIFT's BoxSize) and CSV's --box can hold.
#pragma once

#include "lattices/lattice.hpp"

namespace sphkern {

// The same lattice on a rectangular cell (basis diagonal, motif in [0, 1) of it). Throws
// Error(input) where some axis has no lattice translation within 12 primitive cells.
Lattice rectangular_cell(const Lattice& lattice);

} // namespace sphkern
