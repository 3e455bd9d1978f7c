// SVG figures of a study drawn with gnuplot, like the paper's Figs. 4 to 6.
#pragma once

#include "study/study_runner.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// The gnuplot executable on PATH, or empty.
std::filesystem::path find_gnuplot();

// Writes one figure per lattice and mode into `folder` (a panel per kernel, a curve
// per a_p) and returns the file names written, relative to `folder`'s parent.
std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results,
                                          const std::filesystem::path& folder, const std::filesystem::path& gnuplot);

} // namespace sphkern
