// results.json of a study: every section, the curves streamed number by number.
#pragma once

#include "study/study.hpp"
#include "study/study_results.hpp"

#include <ostream>

namespace sphkern {

void write_study_results_json(std::ostream& out, const Study& study, const StudyResults& results);

} // namespace sphkern
