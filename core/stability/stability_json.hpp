// The JSON documents of `sphkern stability` (and the Python module): the modes at one
// wave vector, the Brillouin-zone scan with the long-wave sound speeds, stability against k
// and the dispersion curves along the high-symmetry path.
#pragma once

#include "kernels/kernel.hpp"
#include "stability/dispersion_path.hpp"
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

// omega^2 of every branch along the high-symmetry path, about `points` samples.
nlohmann::json dispersion_path_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int points);
nlohmann::json dispersion_path_json(const DispersionPath& path);

} // namespace sphkern
