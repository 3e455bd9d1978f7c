// The Markdown report of a study, and the parts of it printed on stdout.
#pragma once

#include "study/study.hpp"
#include "study/study_results.hpp"

#include <string>
#include <vector>

namespace sphkern {

// The reference table beside the computed values, row by row.
std::string replication_markdown(const StudyResults& results);

// Condition (22) verdicts per lattice, mode and a_p.
std::string verdicts_markdown(const Study& study, const StudyResults& results);

// The whole report; `figures` are paths relative to the report.
std::string report_markdown(const Study& study, const StudyResults& results, const std::vector<std::string>& figures);

} // namespace sphkern
