// Runs a study: its kernels and lattices loaded once, then each section in turn (bulk
// cases, surface, sweeps, stability) and the comparison with a reference table.
#pragma once

#include "kernels/kernel_registry.hpp"
#include "study/study.hpp"
#include "study/study_results.hpp"

namespace sphkern {

StudyResults run_study(const Study& study, KernelRegistry& registry);

} // namespace sphkern
