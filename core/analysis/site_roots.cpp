#include "analysis/site_roots.hpp"

#include "analysis/results_json.hpp"

#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json site_roots_json(const SiteRoots& s, double epsilon)
{
    auto entry = root_scan_json(s.scan);
    entry["site"] = s.site;
    entry["acceptance"] = acceptance_json(s.along, epsilon);
    entry["acceptance_every_direction"] = acceptance_json(s.every, epsilon);
    return entry;
}

RootsAnalysis analyse_roots(const std::vector<const HydrostaticErrors*>& sites, double k_min, double k_max,
                            double epsilon, bool lateral)
{
    const AcceptanceRule along{epsilon, Direction::gravity, lateral}, every{epsilon, Direction::every, lateral};
    RootsAnalysis a;
    for (const auto* s : sites)
        a.sites.push_back({s->site(), find_roots(*s, k_min, k_max), evaluate_acceptance({s}, k_min, k_max, along),
                           evaluate_acceptance({s}, k_min, k_max, every)});
    a.all_along = evaluate_acceptance(sites, k_min, k_max, along);
    a.all_every = evaluate_acceptance(sites, k_min, k_max, every);
    return a;
}

nlohmann::json roots_document(const Kernel& kernel, const Lattice& lattice, double a_p, double k_min, double k_max,
                              double epsilon, bool lateral, int site, const RootsAnalysis& a, Axis axis,
                              double window_min, double window_max)
{
    const auto& chosen = a.sites.at(static_cast<std::size_t>(site));
    auto document = roots_json(kernel, lattice, a_p, k_min, k_max, chosen.scan, chosen.along, epsilon);
    document["site"] = site;
    document["acceptance_every_direction"] = acceptance_json(chosen.every, epsilon);
    document["lateral_in_verdict"] = lateral;
    document["axis"] = axis_name(axis);
    document["window"] = {window_min, window_max};
    document["h_over_l_range"] = {eta_of_k(k_min, a_p, lattice.dimension), eta_of_k(k_max, a_p, lattice.dimension)};
    nlohmann::json list = nlohmann::json::array();
    for (const auto& s : a.sites) list.push_back(site_roots_json(s, epsilon));
    document["sites"] = list;
    document["all_sites"] = {{"acceptance", acceptance_json(a.all_along, epsilon)},
                             {"acceptance_every_direction", acceptance_json(a.all_every, epsilon)}};
    document["best_k_at_window_edge"] = at_window_edge(a.all_along.best_k, k_min, k_max);
    if (document["best_k_at_window_edge"]) document["best_k_note"] = window_edge_note;
    return document;
}

} // namespace sphkern
