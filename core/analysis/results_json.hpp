// The JSON form of analysis results, shared by the commands and the study runner.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/design.hpp"
#include "analysis/roots.hpp"
#include "analysis/surface_profile.hpp"

#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json root_json(const Root& root);
nlohmann::json root_scan_json(const RootScan& scan); // {"roots": [...], "jumps": [...]}
nlohmann::json acceptance_json(const Acceptance& acceptance, double epsilon);
// [[from, to], ...]
nlohmann::json intervals_json(const std::vector<KInterval>& intervals);
nlohmann::json surface_json(const SurfaceProfile& profile); // {"spacing", "layers": [...], "bulk"}

// The documents `kernels --json`, `lattices --json`, `shells --json`, `roots --json`,
// `surface --json` and `design --json` print; the Python module returns the same.
nlohmann::json kernel_json(const KernelDefinition& kernel);
nlohmann::json lattice_json(const Lattice& lattice);
// A lattice in full, as `lattices NAME|FILE --json` prints it: lattice_json plus every
// site (fractional and Cartesian, in d) with its shells up to `radius`.
nlohmann::json lattice_description_json(const Lattice& lattice, double radius);
nlohmann::json shells_json(const Lattice& lattice, int site, double radius, const Eigen::Vector3d& gravity);
nlohmann::json roots_json(const Kernel& kernel, const Lattice& lattice, double a_p, double k_min, double k_max,
                          const RootScan& scan, const Acceptance& acceptance, double epsilon);
nlohmann::json surface_document(const Kernel& kernel, const Lattice& lattice, double k, double a_p, GradientForm form,
                                const SurfaceProfile& profile);
nlohmann::json design_json(const Kernel& kernel, const DesignProblem& problem, const DesignResult& result);

// Throws Error(usage-or-input) unless 0 < k_min < k_max <= 100.
void check_k_interval(double k_min, double k_max, const std::string& what);

} // namespace sphkern
