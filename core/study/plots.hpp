// The figures of a study drawn with gnuplot (SVG, PNG or PDF), like the paper's Figs. 4 to 6.
#pragma once

#include "study/study.hpp"
#include "study/study_results.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// Writes the figures into `folder`: per lattice and mode the errors against k (a panel
// per kernel, a curve per a_p), then the surface, sweep and stability figures; returns
// one file name per figure (svg if asked for, else png, else pdf), relative to `folder`'s
// parent. Every panel has axis labels and its own legend beside it; errors and omega^2 are
// on symmetric logarithmic axes (linear near zero), so that no curve leaves its panel.
std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results,
                                          const std::filesystem::path& folder, const std::filesystem::path& gnuplot,
                                          const std::vector<std::string>& formats);

} // namespace sphkern
