// Runs a study: every input resolved and checked first (study_inputs.hpp), then the bulk
// cases, each optional section in the table's order, and the comparison with a reference table.
#pragma once

#include "kernels/kernel_registry.hpp"
#include "study/study.hpp"
#include "study/study_results.hpp"

namespace sphkern {

StudyResults run_study(const Study& study, KernelRegistry& registry);

} // namespace sphkern
