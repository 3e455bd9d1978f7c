// One stability request, whichever front end built it (the command line's `stability`,
// Python's sphkern.stability): validated once, run by one dispatch on its mode.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/h_model.hpp"
#include "stability/stability_scan.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace sphkern {

enum class StabilityMode {
    zone_scan,  // the Brillouin-zone scan and long-wave sound speeds at one k
    wavevector, // the modes at one wave vector
    path,       // dispersion curves along the high-symmetry path
    over_k,     // stability against k: stable intervals over [k_min, k_max]
};

struct StabilityRequest {
    StabilityMode mode = StabilityMode::zone_scan;
    double k = 0;                   // every mode but over_k
    double k_min = 0, k_max = 0;    // over_k
    int steps = 50;                 // over_k: intervals of the k scan
    std::vector<double> wavevector; // wavevector: Cartesian components in 1/d, as many as the lattice's dimension
    int path_points = 0;            // path
    double gamma = 5.0 / 3.0;
    double horizon = default_horizon; // d/c: slower growth is weak
    HModel h_model = HModel::fixed;
    int grid = 0;    // 0: the default zone grid
    int threads = 0; // 0: every core
};

// How the front end names each value in its errors ("--k" or "k").
struct StabilitySources {
    ValueSource k, k_min, k_max, gamma, horizon, wavevector;
    std::string k_hint; // said after a k out of range, e.g. " (or give --kmin and --kmax)"
};

// Every value that does not need the kernel or lattice; an Error naming its source.
void check_stability_request(const StabilityRequest& request, const StabilitySources& sources);

// The document `sphkern stability --json` prints for the request's mode.
nlohmann::json run_stability(const StabilityRequest& request, const StabilitySources& sources, const Kernel& kernel,
                             const Lattice& lattice);

} // namespace sphkern
