#include "analysis/results_json.hpp"

#include "support/error.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace sphkern {

nlohmann::json root_json(const Root& r)
{
    return {{"function", function_name(r.function)}, {"k", r.k},
            {"eps_rho", r.values.eps_rho},           {"eps_gradp", r.values.eps_gradp},
            {"lateral", r.values.lateral},           {"neighbours", r.values.neighbours},
            {"support_radius", r.support_radius}};
}

nlohmann::json root_scan_json(const RootScan& scan)
{
    nlohmann::json roots = nlohmann::json::array(), jumps = nlohmann::json::array();
    for (const auto& r : scan.roots) roots.push_back(root_json(r));
    for (const auto& j : scan.jumps)
        jumps.push_back({{"function", function_name(j.function)},
                         {"kind", jump_kind_name(j.kind)},
                         {"k", j.k},
                         {"left", j.left},
                         {"right", j.right}});
    return {{"roots", roots}, {"jumps", jumps}};
}

nlohmann::json intervals_json(const std::vector<KInterval>& intervals)
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& i : intervals) list.push_back({i.from, i.to});
    return list;
}

nlohmann::json acceptance_json(const Acceptance& a, double epsilon)
{
    return {{"epsilon", epsilon},
            {"verdict", a.passes() ? "pass" : "fail"},
            {"intervals", intervals_json(a.intervals)},
            {"best_k", a.best_k},
            {"best_max_error", a.best_error}};
}

nlohmann::json surface_json(const SurfaceProfile& profile)
{
    auto sites_json = [](const std::vector<SiteLayerErrors>& sites) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& v : sites)
            list.push_back(
                {{"site", v.site}, {"eps_rho", v.eps_rho}, {"eps_gradp", v.eps_gradp}, {"neighbours", v.neighbours}});
        return list;
    };
    nlohmann::json layers = nlohmann::json::array();
    for (const auto& l : profile.layers)
        layers.push_back({{"n", l.n},
                          {"depth", l.depth},
                          {"eps_rho", l.eps_rho},
                          {"eps_gradp", l.eps_gradp},
                          {"neighbours", l.neighbours},
                          {"sites", sites_json(l.sites)}});
    nlohmann::json terminations = nlohmann::json::array();
    for (std::size_t t = 0; t < profile.planes.types.size(); ++t)
        terminations.push_back({{"index", t},
                                {"name", profile.planes.name(static_cast<int>(t))},
                                {"sites", profile.planes.types[t].sites},
                                {"offset", profile.planes.types[t].offset}});
    nlohmann::json first = nlohmann::json::array();
    for (const auto& m : profile.first_moments) first.push_back({m.x(), m.y(), m.z()});
    return {{"spacing", profile.spacing},
            {"termination", profile.termination},
            {"terminations", terminations},
            {"layers", layers},
            {"bulk",
             {{"eps_rho", profile.bulk.eps_rho},
              {"eps_gradp", profile.bulk.eps_gradp},
              {"neighbours", profile.bulk.neighbours},
              {"sites", sites_json(profile.bulk.sites)}}},
            {"first_moments", first}};
}

nlohmann::json roots_json(const Kernel& kernel, const Lattice& lattice, double a_p, double k_min, double k_max,
                          const RootScan& scan, const Acceptance& acceptance, double epsilon)
{
    auto document = root_scan_json(scan);
    document["kernel"] = kernel.label();
    document["lattice"] = lattice.name;
    document["a_p"] = a_p;
    document["k_range"] = {k_min, k_max};
    document["acceptance"] = acceptance_json(acceptance, epsilon);
    return document;
}

nlohmann::json surface_document(const Kernel& kernel, const Lattice& lattice, double k, double a_p, GradientForm form,
                                const SurfaceProfile& profile)
{
    auto document = surface_json(profile);
    document["kernel"] = kernel.label();
    document["lattice"] = lattice.name;
    document["k"] = k;
    document["a_p"] = a_p;
    document["form"] = gradient_form_name(form);
    return document;
}

nlohmann::json design_json(const Kernel& kernel, const DesignProblem& problem, const DesignResult& result)
{
    nlohmann::json solutions = nlohmann::json::array();
    for (const auto& s : result.solutions)
        solutions.push_back({{"k", s.k},
                             {"parameter", s.parameter},
                             {"eps_rho", s.values.eps_rho},
                             {"eps_gradp", s.values.eps_gradp},
                             {"neighbours", s.values.neighbours},
                             {"jacobian_condition", s.jacobian_condition},
                             {"ap_plus_1_percent", {{"k_shift", s.k_shift}, {"parameter_shift", s.parameter_shift}}},
                             {"non_negative", s.non_negative},
                             {"method", s.method}});
    return {{"kernel", kernel.name()},
            {"lattice", problem.lattice->name},
            {"a_p", problem.a_p},
            {"parameter", problem.parameter},
            {"range", {problem.parameter_min, problem.parameter_max}},
            {"k_range", {problem.k_min, problem.k_max}},
            {"solutions", solutions},
            {"note", result.note}};
}

} // namespace sphkern
