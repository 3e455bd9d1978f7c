#include "stability/recommended_k.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace sphkern {

RecommendedK recommend_k(const std::vector<KInterval>& both, double window_min, double window_max,
                         const HydrostaticErrors& errors)
{
    RecommendedK r;
    for (const auto& i : both)
        if (!r.found || i.to - i.from > r.widest.to - r.widest.from) r.widest = i, r.found = true;
    if (!r.found) return r;
    r.k = 0.5 * (r.widest.from + r.widest.to);
    r.margin = 0.5 * (r.widest.to - r.widest.from);
    r.neighbours = errors.at(r.k).neighbours;
    r.neighbours_from = errors.at(r.widest.from).neighbours;
    r.neighbours_to = errors.at(r.widest.to).neighbours;
    r.at_window_edge =
        at_window_edge(r.widest.from, window_min, window_max) || at_window_edge(r.widest.to, window_min, window_max);
    return r;
}

nlohmann::json recommended_json(const RecommendedK& r)
{
    if (!r.found) return {{"found", false}, {"note", "no k of the window is both accurate and stable"}};
    nlohmann::json j = {{"found", true},
                        {"k", r.k},
                        {"margin", r.margin},
                        {"interval", {r.widest.from, r.widest.to}},
                        {"neighbours", r.neighbours},
                        {"neighbours_range", {r.neighbours_from, r.neighbours_to}},
                        {"at_window_edge", r.at_window_edge}};
    if (r.at_window_edge) j["note"] = window_edge_note;
    return j;
}

std::string recommended_text(const RecommendedK& r)
{
    if (!r.found) return "recommended k: none (no k of the window is both accurate and stable)";
    return fmt::format("recommended k = {:.6f} +- {:.6f} (the centre of [{:.6f}, {:.6f}]), N_H = {} ({} to {}){}", r.k,
                       r.margin, r.widest.from, r.widest.to, r.neighbours, r.neighbours_from, r.neighbours_to,
                       r.at_window_edge ? fmt::format(": {}", window_edge_note) : "");
}

} // namespace sphkern
