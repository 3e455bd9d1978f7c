// What a study's results folder holds: results.json, curves.csv (every curve's samples, one
// row each), report.md and a copy of the method document that the report links, so that the
// folder reads on its own.
#pragma once

#include "study/study.hpp"
#include "study/study_results.hpp"
#include "support/io/output_folder.hpp"

#include <string>
#include <vector>

namespace sphkern {

// Writes the files into the staged folder; `figures` are those drawn into it already.
void write_results_folder(OutputFolder& output, const Study& study, const StudyResults& results,
                          const std::vector<std::string>& figures);

} // namespace sphkern
