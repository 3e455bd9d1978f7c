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

} // namespace sphkern
