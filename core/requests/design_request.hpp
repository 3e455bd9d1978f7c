// One design request, whichever front end built it (the command line's `design`, Python's
// sphkern.design): every (k, parameter) of a kernel family where both bulk errors vanish.
#pragma once

#include "analysis/design.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "requests/evaluation_inputs.hpp"
#include "support/text/value_checks.hpp"

#include <optional>
#include <string>
#include <utility>

namespace sphkern {

struct DesignRequest {
    std::string parameter;                          // the one to vary ("alpha" for a blend)
    std::optional<std::pair<double, double>> range; // none: the kernel's default range
    double k_min = 0.75, k_max = 1.25;
    EvaluationInputs evaluation; // a_p, gravity and the site (every shell)
    int threads = 0;             // of the scan along the parameter (0: every core)
};

// How the front end names each value in its errors.
struct DesignSources {
    ValueSource window; // the k window as one value: "--kmin/--kmax" or "kmin/kmax"
    EvaluationSources evaluation;
    ValueSource threads = ValueSource::argument("threads");
};

// Every value that does not need the kernel or lattice; an Error naming its source.
void check_design_request(const DesignRequest& request, const DesignSources& sources);

struct DesignOutcome {
    DesignProblem problem; // points at the lattice it ran on
    DesignResult result;
};

DesignOutcome run_design(const DesignRequest& request, const DesignSources& sources, const Kernel& kernel,
                         const Lattice& lattice);

// The text `sphkern design` prints, on the results file (the document is design_json's).
void print_design(const DesignOutcome& outcome, const Kernel& kernel);

} // namespace sphkern
