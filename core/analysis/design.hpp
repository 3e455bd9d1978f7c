// Kernel design: every (k, parameter) where eps_rho and eps_gradP vanish together.
// Blends use the linearity of both errors in alpha; any other parameter is solved
// by bracketing along the parameter and Newton refinement in (k, parameter).
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct DesignProblem {
    const Lattice* lattice = nullptr;
    int site = 0;
    double a_p = 1;
    Eigen::Vector3d gravity;
    double k_min = 0.75, k_max = 1.25;
    std::string parameter;
    double parameter_min = 0, parameter_max = 1;
    int threads = 1; // of the scan along the parameter; the answer is the same on any number
};

// The parameter range when none is given: [-1, 2] for a blend's alpha, else the declared range.
std::pair<double, double> default_parameter_range(const Kernel& kernel, const std::string& parameter);

struct DesignSolution {
    double k = 0;
    double parameter = 0;
    ErrorValues values;            // both errors at the solution, evaluated with the designed kernel
    double jacobian_condition = 0; // of d(eps_rho, eps_gradP) / d(k, parameter)
    double k_shift = 0;            // how far k moves when a_p grows by 1% (first order)
    double parameter_shift = 0;    // how far the parameter moves then
    bool non_negative = true;      // W >= 0 on [0, R] in the lattice's dimension
    std::string method;            // "blend" or "newton"
};

struct DesignResult {
    std::vector<DesignSolution> solutions;
    std::string note; // why there is none, if there is none
};

// Throws Error(input) for an unknown parameter or a range outside the declared one.
DesignResult design_kernel(const Kernel& kernel, const DesignProblem& problem);

// Refuses (Error(input)) a parameter the kernel does not declare, or a range outside its
// declared one; design_kernel checks this first.
void check_design_parameter(const Kernel& kernel, const std::string& parameter, double min, double max);

} // namespace sphkern
