// The k where the dispersion matrix jumps: a shell of neighbours crosses a cut of the
// kernel (its support R, or the support of a blend's part) where W, W' or W'' is not
// continuous (the truncated super-Gaussian; the composite kernel's derivative). No bound on
// dM/dk reaches across them, so the scan over k keeps them as ends of its cells.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"

#include <vector>

namespace sphkern {

// Ascending, inside (k_min, k_max); empty for a kernel that goes to its cuts smoothly.
std::vector<double> dispersion_jumps(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max);

} // namespace sphkern
