// Every site of a lattice, analysed alike (sites need not be equivalent: kagome, Lieb,
// user lattices): the errors along gravity, the gradient-error tensor and the first
// moment of each, and which site is worst.
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <string>
#include <vector>

namespace sphkern {

struct SiteReport {
    int site = 0;
    ErrorValues values;      // along gravity
    GradientTensor gradient; // every direction
};

// Site indices 0 .. sites-1.
std::vector<int> every_site(const Lattice& lattice);

// Checks a list of site indices against the lattice (none, or one out of range, is an
// Error(input) naming `what` and the valid range).
void check_sites(const Lattice& lattice, const std::vector<int>& sites, const std::string& what);

// One HydrostaticErrors per site, in the order given.
std::vector<std::unique_ptr<HydrostaticErrors>> errors_per_site(const Kernel& kernel, const Lattice& lattice,
                                                                const std::vector<int>& sites, double a_p,
                                                                const Eigen::Vector3d& gravity, double k_max,
                                                                const EvaluationMode& mode = {});

SiteReport site_report(const HydrostaticErrors& errors, double k);

// The site with the largest max(|eps_rho|, |eps_gradP|) along gravity (an index into `reports`).
std::size_t worst_site(const std::vector<SiteReport>& reports);

// {"site", "eps_rho", "eps_gradp", "eps_lateral", "gradp_tensor_eigenvalues", "first_moment"}.
nlohmann::json site_report_json(const SiteReport& report, int dimension);

} // namespace sphkern
