// The paper's acceptance condition (22): the k where both |eps_rho| and |eps_gradP|
// are at most epsilon, and the best k for a kernel on a lattice.
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <vector>

namespace sphkern {

struct KInterval {
    double from, to;
};

struct Acceptance {
    std::vector<KInterval> intervals; // where condition (22) holds
    double best_k = 0;                // k minimising max(|eps_rho|, |eps_gradP|)
    double best_error = 0;            // that minimum
    bool passes() const { return !intervals.empty(); }
};

Acceptance evaluate_acceptance(const HydrostaticErrors& errors, double k_min, double k_max, double epsilon,
                               int samples = 400);

} // namespace sphkern
