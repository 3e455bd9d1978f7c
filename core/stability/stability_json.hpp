// The JSON documents of `sphkern stability` (and the Python module): the modes at one
// wave vector, the Brillouin-zone scan with the long-wave sound speeds, stability against k
// and the dispersion curves along the high-symmetry path.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/dispersion_path.hpp"
#include "stability/stability_over_k.hpp"

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// `h_model`: fixed or adaptive h (the equilibrium h is k d in both).
nlohmann::json dispersion_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                                   const Eigen::Vector3d& kappa, HModel h_model = HModel::fixed);

// `grid`: the first zone grid per axis (0: the default); `horizon` in d/c.
nlohmann::json stability_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int grid,
                                  int threads, double horizon, HModel h_model = HModel::fixed);

// The verdict at `steps` + 1 k in [k_min, k_max] (and where the scan looked between them),
// the stable k intervals and those stable at the horizon (each edge bisected to 1e-6).
nlohmann::json stability_over_k_document(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                                         int steps, double gamma, int grid, int threads, double horizon,
                                         HModel h_model = HModel::fixed);

// One k of a scan over k; a mode's kind.
nlohmann::json stability_sample_json(const StabilitySample& sample, int dim);
nlohmann::json mode_json(const ModeCharacter& mode, int dim);

// omega^2 of every branch along the high-symmetry path, about `points` samples.
nlohmann::json dispersion_path_document(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                                        int points, HModel h_model = HModel::fixed);
nlohmann::json dispersion_path_json(const DispersionPath& path);

} // namespace sphkern
