// The JSON form of analysis results, shared by the commands and the study runner.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/roots.hpp"
#include "analysis/surface_profile.hpp"

#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json root_json(const Root& root);
nlohmann::json root_scan_json(const RootScan& scan); // {"roots": [...], "jumps": [...]}
nlohmann::json acceptance_json(const Acceptance& acceptance, double epsilon);
nlohmann::json surface_json(const SurfaceProfile& profile); // {"spacing", "layers": [...], "bulk"}

// Throws Error(usage-or-input) unless 0 < k_min < k_max <= 100.
void check_k_interval(double k_min, double k_max, const std::string& what);

} // namespace sphkern
