// What a study's "particles" section writes: a report table per source, a figure per source
// (RMS e0 and eps_gradp against N_H, log-log, a curve per kernel, the Poisson limit for
// reference) and its entries of results.json.
#pragma once

#include "study/study_results.hpp"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>

namespace sphkern {

std::string particles_markdown(const StudyResults& results);
// Hands each figure to `draw` as a gnuplot body without terminal and output (name, width, height).
using DrawFigure = std::function<void(const std::string& name, int width, int height, const std::string& body)>;
void draw_particles_figures(const StudyResults& results, const DrawFigure& draw);
nlohmann::json particles_results_json(const StudyResults& results);

} // namespace sphkern
