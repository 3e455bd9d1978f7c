// One roots request, whichever front end built it (the command line's `roots`, Python's
// sphkern.roots): the k in a window where eps_rho or eps_gradP vanish, the jumps and
// condition (22) at every site; on request the stable k and a code's own setting.
#pragma once

#include "analysis/resolution_axis.hpp"
#include "analysis/site_roots.hpp"
#include "codes/code_table.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "requests/evaluation_inputs.hpp"
#include "stability/roots_stability.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <vector>

namespace sphkern {

struct RootsRequest {
    double window_min = 0.75, window_max = 1.25; // on `axis`
    Axis axis = Axis::k;
    double epsilon = 0.01; // the tolerance of condition (22), in (0, 1)
    bool lateral = false;  // the lateral gradient error counts in condition (22) too
    bool stability = false;
    RootsStabilityOptions model;       // checked whether or not `stability` asks for it
    const CodeProfile* code = nullptr; // a code's own setting beside k, with its own density
    EvaluationInputs evaluation;
};

// How the front end names each value in its errors.
struct RootsSources {
    ValueSource window; // the k window as one value: "--kmin/--kmax" or "kmin/kmax"
    ValueSource epsilon, gamma, horizon, steps;
    EvaluationSources evaluation;
    ValueSource threads = ValueSource::argument("threads");
};

// Every value that does not need the kernel or lattice; an Error naming its source.
void check_roots_request(const RootsRequest& request, const RootsSources& sources);

// The window's answers in a code's own setting (analysis/code_profiles), at the chosen site.
struct RootsInCode {
    double best = 0;                      // the best k of condition (22)
    std::vector<KInterval> accurate;      // where condition (22) holds
    std::optional<KInterval> recommended; // the recommended interval, if stability found one
    std::vector<KInterval> both;          // each interval both accurate and stable, with stability
    double recommended_value = 0;         // at the recommended k
};

struct RootsResult {
    double a_p = 0;
    double k_min = 0, k_max = 0; // the window in k
    RootsAnalysis analysis;
    RootsStability stability;           // empty unless the request asks for it
    std::optional<RootsInCode> in_code; // with a code
};

RootsResult run_roots(const RootsRequest& request, const RootsSources& sources, const Kernel& kernel,
                      const Lattice& lattice);

// The document of one kernel on one lattice, as `sphkern roots --json` lists them.
nlohmann::json roots_request_document(const RootsRequest& request, const RootsResult& result, const Kernel& kernel,
                                      const Lattice& lattice);
// The text `sphkern roots` prints for one kernel on one lattice, on the results file.
void print_roots(const RootsRequest& request, const RootsResult& result, const Kernel& kernel, const Lattice& lattice);

} // namespace sphkern
