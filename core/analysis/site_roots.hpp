// Roots, jumps and condition (22) for every site of a lattice: each site on its own,
// along gravity and for every direction, and all sites at once (the verdict).
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/resolution_axis.hpp"
#include "analysis/roots.hpp"

#include <nlohmann/json_fwd.hpp>

#include <vector>

namespace sphkern {

struct SiteRoots {
    int site;
    RootScan scan;
    Acceptance along, every;
};

struct RootsAnalysis {
    std::vector<SiteRoots> sites;
    Acceptance all_along, all_every;
};

// {"site", "roots", "jumps", "acceptance", "acceptance_every_direction"}.
nlohmann::json site_roots_json(const SiteRoots& site, double epsilon);

// `sites`: one HydrostaticErrors per site of the lattice, in site order.
RootsAnalysis analyse_roots(const std::vector<const HydrostaticErrors*>& sites, double k_min, double k_max,
                            double epsilon, bool lateral);

// The document `roots --json` prints: the top level as for one site (`site`), then
// "acceptance_every_direction", "sites" and "all_sites".
// `axis` and [window_min, window_max]: the window as it was given (k_min, k_max: in k).
nlohmann::json roots_document(const Kernel& kernel, const Lattice& lattice, double a_p, double k_min, double k_max,
                              double epsilon, bool lateral, int site, const RootsAnalysis& analysis, Axis axis,
                              double window_min, double window_max);

} // namespace sphkern
