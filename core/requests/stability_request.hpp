// One stability request, whichever front end built it (the command line's `stability`,
// Python's sphkern.stability): validated once, run by one dispatch on its mode.
#pragma once

#include "analysis/acceptance.hpp"
#include "codes/code_table.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/h_model.hpp"
#include "stability/stability_results.hpp"
#include "stability/stability_scan.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace sphkern {

enum class StabilityMode {
    zone_scan,  // the Brillouin-zone scan and long-wave sound speeds at one k
    wavevector, // the modes at one wave vector
    path,       // dispersion curves along the high-symmetry path
    over_k,     // stability against k: stable intervals over [k_min, k_max]
};

// The values as given: which of them are given chooses the mode (stability_mode).
struct StabilityRequest {
    std::optional<double> k;                       // every mode but over_k
    std::optional<double> k_min, k_max;            // over_k: both
    int steps = 50;                                // over_k: intervals of the k scan, 1 to 2000
    std::optional<std::vector<double>> wavevector; // wavevector: Cartesian components in 1/d
    std::optional<int> path_points;                // path: about this many points, 2 to 100000
    double gamma = 5.0 / 3.0;
    double horizon = default_horizon; // d/c: slower growth is weak
    HModel h_model = HModel::fixed;
    std::optional<int> grid;           // the first zone grid, 2 to 400; none: the default
    int threads = 0;                   // 0: every core
    const CodeProfile* code = nullptr; // over_k: the intervals in a code's own setting too
};

// over_k when a k range is given, else wavevector, path or the zone scan.
StabilityMode stability_mode(const StabilityRequest& request);

// How the front end names each value in its errors ("--k" or "k").
struct StabilitySources {
    ValueSource k, k_min, k_max, gamma, horizon, wavevector, steps, grid, path;
    std::string k_hint; // said after a k out of range, e.g. " (or give --kmin and --kmax)"
    ValueSource threads = ValueSource::argument("threads");
};

// Every value that does not need the kernel or lattice, and which of them go together;
// an Error naming its source.
void check_stability_request(const StabilityRequest& request, const StabilitySources& sources);

// A code's stable intervals (over_k with a code): the same intervals in the code's own setting.
struct CodeIntervals {
    std::string name, parameter;
    std::vector<KInterval> stable, usable; // of the code's parameter
};

// What run_stability computed for the request's mode, and the code's intervals where asked.
struct StabilityResult {
    std::variant<ZoneScan, WavevectorModes, PathDispersion, StabilityAgainstK> result;
    std::optional<CodeIntervals> code;
};

StabilityResult run_stability(const StabilityRequest& request, const StabilitySources& sources, const Kernel& kernel,
                              const Lattice& lattice);

// The document `sphkern stability --json` prints (requests/stability_report.hpp prints the text).
nlohmann::json stability_json(const StabilityResult& result);

} // namespace sphkern
