// The paper's acceptance condition (22): the k where |eps_rho| and the gradient error
// are at most epsilon, and the best k for a kernel on a lattice. The gradient error is
// |eps_gradP| along gravity (the paper's condition), or, for "every direction", the
// largest |eigenvalue| of the gradient-error tensor; the lateral error may be added.
// With several sites, the condition must hold at every one of them.
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct KInterval {
    double from, to;
};

// A best k, a root or an interval's end on the edge of the window may go on outside it. The
// same words in every front end, whose documents agree (the window is --kmin/--kmax on the
// command line, kmin/kmax in Python, "k" in a study).
inline constexpr const char* window_edge_note = "at the window edge; widen the k window";
// Whether k is at the edge of [window_min, window_max] (to 1e-9 of its width).
bool at_window_edge(double k, double window_min, double window_max);

struct Acceptance {
    std::vector<KInterval> intervals; // where condition (22) holds
    double best_k = 0;                // k minimising the largest error
    double best_error = 0;            // that minimum
    bool passes() const { return !intervals.empty(); }
};

enum class Direction { gravity, every };

struct AcceptanceRule {
    double epsilon = 0.01;
    Direction direction = Direction::gravity;
    bool lateral = false; // the lateral error counts too (along gravity, or its maximum over directions)
};

// The largest error the rule looks at, for one site at k.
double acceptance_error(const HydrostaticErrors& site, double k, const AcceptanceRule& rule);

// Condition (22) over every site in `sites` at once.
Acceptance evaluate_acceptance(const std::vector<const HydrostaticErrors*>& sites, double k_min, double k_max,
                               const AcceptanceRule& rule, int samples = 400);

// One site, along gravity, no lateral error: the paper's condition.
Acceptance evaluate_acceptance(const HydrostaticErrors& errors, double k_min, double k_max, double epsilon,
                               int samples = 400);

} // namespace sphkern
