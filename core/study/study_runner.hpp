// Runs a study: every input resolved and checked first (study_inputs.hpp), then each
// section in turn (bulk cases, surface, sweeps, stability, particles) and the comparison
// with a reference table.
#pragma once

#include "kernels/kernel_registry.hpp"
#include "study/study.hpp"
#include "study/study_results.hpp"

namespace sphkern {

StudyResults run_study(const Study& study, KernelRegistry& registry);

} // namespace sphkern
