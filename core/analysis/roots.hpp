// Roots of eps_rho(k) and eps_gradP(k) in a k-interval, found piece by piece between
// the k where shells enter the support; sign changes across such a k, or across a
// singularity of the kernel, are jumps, never roots (share/docs/method.md section 4).
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <string>
#include <vector>

namespace sphkern {

inline constexpr double root_tolerance = 1e-10; // on k

struct Root {
    std::string function; // "rho" or "gradp"
    double k = 0;
    ErrorValues values;     // both errors at the root
    double support_radius;  // H / d = R k
};

struct Jump {
    std::string function; // "rho" or "gradp"
    std::string kind;     // "support" (a shell enters the support) or "singularity"
    double k = 0;
    double left = 0, right = 0;
};

struct RootScan {
    std::vector<Root> roots;
    std::vector<Jump> jumps;
};

RootScan find_roots(const HydrostaticErrors& errors, double k_min, double k_max, int samples = 200);

} // namespace sphkern
