// SVG figures of a study drawn with gnuplot, like the paper's Figs. 4 to 6.
#pragma once

#include "study/study.hpp"
#include "study/study_results.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// Writes the figures into `folder`: per lattice and mode the errors against k (a panel
// per kernel, a curve per a_p), then the surface, sweep and stability figures; returns
// the file names written, relative to `folder`'s parent.
std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results,
                                          const std::filesystem::path& folder, const std::filesystem::path& gnuplot);

} // namespace sphkern
