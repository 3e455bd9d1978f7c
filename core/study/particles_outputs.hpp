// What a study's "particles" section writes: a report table per source, a figure per source
// (RMS e0 and eps_gradp against N_H, log-log, a curve per kernel, the Poisson limit for
// reference) and its entries of results.json.
#pragma once

#include "study/study_results.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

std::string particles_markdown(const StudyResults& results);
std::vector<std::string> draw_particles_figures(const StudyResults& results, const std::filesystem::path& folder,
                                                const std::filesystem::path& gnuplot);
nlohmann::json particles_results_json(const StudyResults& results);

} // namespace sphkern
