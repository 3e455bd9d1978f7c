// The bulk cases of a study, the part every study has: a particle on a lattice site, every
// kernel x lattice x a_p x mode (curves, roots, jumps, condition (22), explanations). The
// optional sections run after it and find its cases by CaseKey.
#pragma once

#include "study/study.hpp"
#include "study/study_inputs.hpp"
#include "study/study_results.hpp"

namespace sphkern {

void run_bulk_section(const Study& study, const StudyInputs& inputs, StudyResults& results);

} // namespace sphkern
