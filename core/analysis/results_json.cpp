#include "analysis/results_json.hpp"

#include "support/error.hpp"
#include "support/value_checks.hpp"

#include <cmath>
#include <sstream>

namespace sphkern {

nlohmann::json root_json(const Root& r)
{
    return {{"function", function_name(r.function)},         {"k", r.k},
            {"eps_rho", r.values.eps_rho},    {"eps_gradp", r.values.eps_gradp},
            {"lateral", r.values.lateral},    {"neighbours", r.values.neighbours},
            {"support_radius", r.support_radius}};
}

nlohmann::json root_scan_json(const RootScan& scan)
{
    nlohmann::json roots = nlohmann::json::array(), jumps = nlohmann::json::array();
    for (const auto& r : scan.roots) roots.push_back(root_json(r));
    for (const auto& j : scan.jumps)
        jumps.push_back({{"function", function_name(j.function)}, {"kind", jump_kind_name(j.kind)}, {"k", j.k}, {"left", j.left}, {"right", j.right}});
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
            list.push_back({{"site", v.site}, {"eps_rho", v.eps_rho}, {"eps_gradp", v.eps_gradp},
                            {"neighbours", v.neighbours}});
        return list;
    };
    nlohmann::json layers = nlohmann::json::array();
    for (const auto& l : profile.layers)
        layers.push_back({{"n", l.n}, {"depth", l.depth}, {"eps_rho", l.eps_rho}, {"eps_gradp", l.eps_gradp},
                          {"neighbours", l.neighbours}, {"sites", sites_json(l.sites)}});
    nlohmann::json terminations = nlohmann::json::array();
    for (std::size_t t = 0; t < profile.planes.types.size(); ++t)
        terminations.push_back({{"index", t}, {"name", profile.planes.name(static_cast<int>(t))},
                                {"sites", profile.planes.types[t].sites}, {"offset", profile.planes.types[t].offset}});
    nlohmann::json first = nlohmann::json::array();
    for (const auto& m : profile.first_moments) first.push_back({m.x(), m.y(), m.z()});
    return {{"spacing", profile.spacing},
            {"termination", profile.termination},
            {"terminations", terminations},
            {"layers", layers},
            {"bulk", {{"eps_rho", profile.bulk.eps_rho}, {"eps_gradp", profile.bulk.eps_gradp},
                      {"neighbours", profile.bulk.neighbours}, {"sites", sites_json(profile.bulk.sites)}}},
            {"first_moments", first}};
}

void check_k_interval(double k_min, double k_max, const std::string& what)
{
    check_k_interval(k_min, k_max, ValueSource::argument(what));
}

nlohmann::json kernel_json(const KernelDefinition& p)
{
    nlohmann::json parameters = nlohmann::json::array();
    for (const auto& q : p.parameters)
        parameters.push_back({{"name", q.name}, {"description", q.description}, {"default", q.default_value},
                              {"min", q.min_value}, {"max", q.max_value}});
    return {{"name", p.name}, {"title", p.title}, {"support", p.support}, {"dimensions", p.dimensions},
            {"parameters", parameters}, {"breakpoints", p.breakpoints}, {"separate_derivative", p.separate_derivative},
            {"reference", p.reference}, {"file", p.source}};
}

nlohmann::json lattice_json(const Lattice& l)
{
    nlohmann::json coefficients = nlohmann::json::object();
    for (const auto& c : l.volume_coefficients) coefficients[c.name] = c.value;
    std::vector<double> gravity(l.gravity.data(), l.gravity.data() + l.dimension);
    return {{"name", l.name},   {"title", l.title},
            {"dimension", l.dimension}, {"sites", l.sites()},
            {"volume_coefficients", coefficients}, {"gravity", gravity}, {"file", l.file}};
}

nlohmann::json lattice_description_json(const Lattice& lattice, double radius)
{
    auto document = lattice_json(lattice);
    document["nearest_neighbour_distance"] = 1.0;
    document["nearest_neighbour_distance_in_file_units"] = lattice.file_nearest_distance;
    nlohmann::json sites = nlohmann::json::array();
    for (int s = 0; s < lattice.sites(); ++s) {
        const Eigen::Vector3d& m = lattice.motif[static_cast<std::size_t>(s)];
        const Eigen::Vector3d x = lattice.basis * m;
        sites.push_back({{"site", s},
                         {"fractional", std::vector<double>(m.data(), m.data() + lattice.dimension)},
                         {"position", std::vector<double>(x.data(), x.data() + lattice.dimension)},
                         {"shells", shells_json(lattice, s, radius, lattice.gravity)["shells"]}});
    }
    document["shells_radius"] = radius;
    document["site_details"] = sites;
    return document;
}

nlohmann::json shells_json(const Lattice& lattice, int site, double radius, const Eigen::Vector3d& e)
{
    auto shells = lattice_shells(lattice, site, radius);
    nlohmann::json list = nlohmann::json::array();
    int total = 0;
    for (const auto& s : shells) {
        total += s.count;
        list.push_back({{"radius", s.radius}, {"radius_squared", s.radius * s.radius}, {"count", s.count},
                        {"cumulative", total}, {"gravity_moment", s.directional_moment(e)}});
    }
    return {{"lattice", lattice.name}, {"site", site}, {"radius", radius}, {"shells", list}};
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
        solutions.push_back({{"k", s.k}, {"parameter", s.parameter}, {"eps_rho", s.values.eps_rho},
                             {"eps_gradp", s.values.eps_gradp}, {"neighbours", s.values.neighbours},
                             {"jacobian_condition", s.jacobian_condition},
                             {"ap_plus_1_percent", {{"k_shift", s.k_shift}, {"parameter_shift", s.parameter_shift}}},
                             {"non_negative", s.non_negative}, {"method", s.method}});
    return {{"kernel", kernel.name()}, {"lattice", problem.lattice->name}, {"a_p", problem.a_p},
            {"parameter", problem.parameter}, {"range", {problem.parameter_min, problem.parameter_max}},
            {"k_range", {problem.k_min, problem.k_max}}, {"solutions", solutions}, {"note", result.note}};
}

} // namespace sphkern
