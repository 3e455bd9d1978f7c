// The comparison of a study's roots with a reference table (share/reference): row by
// row, reproduced, different, or an erratum of the publication.
#pragma once

#include "study/study.hpp"
#include "study/study_results.hpp"

namespace sphkern {

// Reads study.compare_with and fills results.comparison, results.reference and results.tolerance.
void compare_with_reference(const Study& study, StudyResults& results);

} // namespace sphkern
