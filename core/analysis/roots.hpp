// Roots of eps_rho(k) and eps_gradP(k) in a k-interval, found piece by piece between
// the k where shells enter the support; sign changes across such a k, or across a
// singularity of the kernel, are jumps, never roots (share/docs/method.md section 4).
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <string>
#include <vector>

namespace sphkern {

inline constexpr double root_tolerance = 1e-10; // on k

// Which error vanishes or jumps.
enum class ErrorFunction { rho, gradp };
const char* function_name(ErrorFunction f);             // "rho" or "gradp", as in results.json
double value_of(const ErrorValues& v, ErrorFunction f); // eps_rho or eps_gradp

enum class JumpKind { support, singularity }; // a shell enters the support; a pole of the kernel
const char* jump_kind_name(JumpKind kind);    // "support" or "singularity"

struct Root {
    ErrorFunction function;
    double k = 0;
    ErrorValues values;    // both errors at the root
    double support_radius; // H / d = R k
};

struct Jump {
    ErrorFunction function;
    JumpKind kind;
    double k = 0;
    double left = 0, right = 0;
};

struct RootScan {
    std::vector<Root> roots;
    std::vector<Jump> jumps;
};

RootScan find_roots(const HydrostaticErrors& errors, double k_min, double k_max, int samples = 200);

} // namespace sphkern
