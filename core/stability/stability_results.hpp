// What `sphkern stability` computes in each of its modes, as values: the modes at one wave
// vector, the Brillouin-zone scan with the long-wave sound speeds, stability against k and
// the dispersion curves along the high-symmetry path. Their JSON is stability_json.hpp's.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/dispersion_path.hpp"
#include "stability/h_model.hpp"
#include "stability/stability_over_k.hpp"
#include "stability/stability_scan.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// What every mode was computed for; with adaptive h, eta of h = eta (m / rho)^(1/D) and the
// grad-h factor at k.
struct StabilitySetting {
    std::string kernel, lattice;
    int dimension = 3;
    double k = 0, gamma = 0;
    HModel h_model = HModel::fixed;
    bool plugin_second_derivative = false; // else W'' is taken numerically
    std::optional<double> eta, grad_h_factor;
};

struct WavevectorModes {
    StabilitySetting setting;
    Eigen::Vector3d kappa;
    DispersionModes modes;
    int longitudinal_mode = 0; // the most longitudinal branch
};
// `h_model`: fixed or adaptive h (the equilibrium h is k d in both).
WavevectorModes modes_at(const Kernel& kernel, const Lattice& lattice, double k, double gamma,
                         const Eigen::Vector3d& kappa, HModel h_model = HModel::fixed);

// The long-wave speed along a high-symmetry direction and, for one site at fixed h, how it
// follows from the hydrostatic errors: eps_rho, n . E n and the pressure and stiffness terms.
struct DirectionSpeed {
    std::string direction; // "Γ-X", ...
    Eigen::Vector3d unit;  // along it
    SoundSpeed speed;
    struct Terms {
        double eps_rho, eps_gradp, pressure_term, stiffness_term;
    };
    std::optional<Terms> terms;
};

struct ZoneScan {
    StabilitySetting setting;
    ReciprocalLattice reciprocal;
    StabilityScan scan;
    double horizon = default_horizon;
    std::vector<DirectionSpeed> speeds;
};
// `grid`: the first zone grid per axis (0: the default); `horizon` in d/c.
ZoneScan zone_scan(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int grid, int threads,
                   double horizon, HModel h_model = HModel::fixed);

struct StabilityAgainstK {
    StabilitySetting setting; // its k is k_min
    double k_max = 0;
    StabilityOverK scan;
};
// The verdict at `steps` + 1 k in [k_min, k_max] (and where the scan looked between them),
// the stable k intervals and those stable at the horizon (each edge bisected to 1e-6).
StabilityAgainstK stability_against_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                                      int steps, double gamma, int grid, int threads, double horizon,
                                      HModel h_model = HModel::fixed);

struct PathDispersion {
    StabilitySetting setting;
    std::string bravais;
    DispersionPath path;
};
// omega^2 of every branch along the high-symmetry path, about `points` samples.
PathDispersion path_dispersion(const Kernel& kernel, const Lattice& lattice, double k, double gamma, int points,
                               HModel h_model = HModel::fixed);

} // namespace sphkern
