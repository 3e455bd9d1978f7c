// The comparison of a study's roots with a reference table (share/reference): row by
// row, reproduced, different, or an erratum of the publication.
#pragma once

#include "study/reference_table.hpp"
#include "study/study_results.hpp"

namespace sphkern {

// Compares each row of a resolved table with its bulk case; fills results.comparison,
// results.reference and results.tolerance.
void compare_with_reference(const ReferenceTable& table, StudyResults& results);

} // namespace sphkern
