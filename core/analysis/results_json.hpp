// The JSON form of analysis results (roots, acceptance, surface profiles, designs), shared by
// the commands, the study runner and the Python module.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/design.hpp"
#include "analysis/roots.hpp"
#include "analysis/surface_profile.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

nlohmann::json root_json(const Root& root);
nlohmann::json root_scan_json(const RootScan& scan); // {"roots": [...], "jumps": [...]}
nlohmann::json acceptance_json(const Acceptance& acceptance, double epsilon);
// [[from, to], ...]
nlohmann::json intervals_json(const std::vector<KInterval>& intervals);
nlohmann::json surface_json(const SurfaceProfile& profile); // {"spacing", "layers": [...], "bulk"}

// The documents `roots --json`, `surface --json` and `design --json` print; the Python
// module returns the same.
nlohmann::json roots_json(const Kernel& kernel, const Lattice& lattice, double a_p, double k_min, double k_max,
                          const RootScan& scan, const Acceptance& acceptance, double epsilon);
nlohmann::json surface_document(const Kernel& kernel, const Lattice& lattice, double k, double a_p, GradientForm form,
                                const SurfaceProfile& profile);
nlohmann::json design_json(const Kernel& kernel, const DesignProblem& problem, const DesignResult& result);

} // namespace sphkern
