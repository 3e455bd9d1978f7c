// The JSON documents of `sphkern stability` (and the Python module): the modes at one
// wave vector, and the Brillouin-zone scan with the long-wave sound speeds.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json dispersion_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                                   const Eigen::Vector3d& kappa);

nlohmann::json stability_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int grid,
                                  int threads);

// min omega^2 over the Brillouin zone at `steps` + 1 k in [k_min, k_max] and the
// stable k intervals (from grid to grid point; each edge refined by bisection to 1e-6).
nlohmann::json stability_over_k_document(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                                         int steps, double gamma, int grid, int threads);

} // namespace sphkern
