// A study's kernels and lattices, loaded and checked once for every section.
#pragma once

#include "analysis/hydrostatic_errors.hpp"
#include "kernels/kernel_registry.hpp"
#include "lattices/lattice.hpp"
#include "study/study.hpp"

#include <utility>
#include <vector>

namespace sphkern {

struct StudyInputs {
    std::vector<Kernel> kernels;   // in the study's order
    std::vector<Lattice> lattices;
};

// Errors name the study file and the JSON path of the entry at fault.
StudyInputs load_study_inputs(const Study& study, KernelRegistry& registry);

// The evaluation a study mode asks of a kernel (its shell list for the kernel's support).
EvaluationMode evaluation_mode(const Study& study, const StudyMode& mode, const Kernel& kernel);

// The study's window in k for a kernel, lattice, site and a_p.
std::pair<double, double> study_window(const Study& study, const Kernel& kernel, const Lattice& lattice, int site,
                                       double a_p);

// A lattice's a_p for the study's volume coefficient `index` (errors name /volume_coefficients/index).
double study_volume_coefficient(const Study& study, const Lattice& lattice, std::size_t index);

} // namespace sphkern
