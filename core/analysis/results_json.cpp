#include "analysis/results_json.hpp"

#include "support/error.hpp"

#include <cmath>
#include <sstream>

namespace sphkern {

nlohmann::json root_json(const Root& r)
{
    return {{"function", r.function},         {"k", r.k},
            {"eps_rho", r.values.eps_rho},    {"eps_gradp", r.values.eps_gradp},
            {"lateral", r.values.lateral},    {"neighbours", r.values.neighbours},
            {"support_radius", r.support_radius}};
}

nlohmann::json root_scan_json(const RootScan& scan)
{
    nlohmann::json roots = nlohmann::json::array(), jumps = nlohmann::json::array();
    for (const auto& r : scan.roots) roots.push_back(root_json(r));
    for (const auto& j : scan.jumps)
        jumps.push_back({{"function", j.function}, {"kind", j.kind}, {"k", j.k}, {"left", j.left}, {"right", j.right}});
    return {{"roots", roots}, {"jumps", jumps}};
}

nlohmann::json acceptance_json(const Acceptance& a, double epsilon)
{
    nlohmann::json intervals = nlohmann::json::array();
    for (const auto& i : a.intervals) intervals.push_back({i.from, i.to});
    return {{"epsilon", epsilon},
            {"verdict", a.passes() ? "pass" : "fail"},
            {"intervals", intervals},
            {"best_k", a.best_k},
            {"best_max_error", a.best_error}};
}

nlohmann::json surface_json(const SurfaceProfile& profile)
{
    nlohmann::json layers = nlohmann::json::array();
    for (const auto& l : profile.layers)
        layers.push_back({{"n", l.n}, {"depth", l.depth}, {"eps_rho", l.eps_rho}, {"eps_gradp", l.eps_gradp},
                          {"neighbours", l.neighbours}});
    return {{"spacing", profile.spacing},
            {"layers", layers},
            {"bulk", {{"eps_rho", profile.bulk.eps_rho}, {"eps_gradp", profile.bulk.eps_gradp},
                      {"neighbours", profile.bulk.neighbours}}}};
}

void check_k_interval(double k_min, double k_max, const std::string& what)
{
    if (!std::isfinite(k_min) || !std::isfinite(k_max) || k_min <= 0 || k_max > 100 || k_min >= k_max) {
        std::ostringstream s;
        s << what << ": [" << k_min << ", " << k_max << "] is not allowed, expected 0 < min < max <= 100";
        throw Error(ExitCode::input, s.str());
    }
}

} // namespace sphkern
