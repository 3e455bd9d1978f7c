#include "requests/eps_request.hpp"

#include "support/error.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace sphkern {

void check_eps_request(const EpsRequest& r, const EpsSources& sources)
{
    if (r.code) {
        check_code_setting(*r.code, {sources.code, sources.code_value});
        return check_evaluation(r.evaluation, sources.evaluation);
    }
    if (r.k.empty()) sources.k.fail("an empty array");
    for (double k : r.k) check_k(k, sources.k);
    // Refused as input (exit 3) since the axis is valid, only not here.
    if (r.axis == Axis::nh)
        fail_input(fmt::format("{} nh names a window, not one value: give {} on the k or h_over_l axis",
                               sources.axis.name, sources.k.name));
    check_evaluation(r.evaluation, sources.evaluation);
}

EpsAtK run_eps_at_k(const EpsRequest& r, const EpsSources& sources, const Kernel& kernel, const Lattice& lattice)
{
    auto evaluation = resolve_evaluation(r.evaluation, sources.evaluation, lattice);
    EpsAtK result;
    result.kernel = kernel.label();
    result.lattice = lattice.name;
    result.dimension = lattice.dimension;
    result.axis = r.axis;
    result.a_p = evaluation.a_p;
    result.site = evaluation.site;
    if (r.code) {
        result.code = k_of_code_setting(*r.code, {sources.code, sources.code_value}, kernel, lattice, evaluation);
        result.k = result.code->k;
        if (result.code->a_p) evaluation.a_p = result.a_p = *result.code->a_p; // the code's volume, not the lattice's
    } else {
        const double given = r.k.at(0);
        result.k = r.axis == Axis::eta ? k_of_eta(given, evaluation.a_p, lattice.dimension) : given;
        // Refused as input (exit 3): the k is the conversion's, not a value given.
        check_k(result.k, ValueSource::argument("k"),
                fmt::format(" ({} on the h_over_l axis)", sources.k.about(given)));
    }
    result.eta = eta_of_k(result.k, evaluation.a_p, lattice.dimension);
    result.support_radius = kernel.support() * result.k;
    // Every site: the top-level values describe the chosen one.
    auto sites = errors_per_site(kernel, lattice, every_site(lattice), evaluation.a_p, evaluation.gravity, result.k,
                                 evaluation.mode);
    for (const auto& s : sites) result.sites.push_back(site_report(*s, result.k));
    result.worst = worst_site(result.sites);
    return result;
}

std::vector<ErrorValues> run_eps_series(const EpsRequest& r, const EpsSources& sources, const Kernel& kernel,
                                        const Lattice& lattice)
{
    const auto evaluation = resolve_evaluation(r.evaluation, sources.evaluation, lattice);
    // Each value on the request's axis, as k (h_over_l: k = h_over_l a_p^(1/D)).
    std::vector<double> k = r.k;
    if (r.axis == Axis::eta)
        for (double& value : k) {
            const double given = value;
            value = k_of_eta(given, evaluation.a_p, lattice.dimension);
            check_k(value, ValueSource::argument("k"),
                    fmt::format(" ({} on the h_over_l axis)", sources.k.about(given)));
        }
    const double k_max = *std::max_element(k.begin(), k.end());
    HydrostaticErrors errors(kernel, lattice, evaluation.site, evaluation.a_p, evaluation.gravity, k_max,
                             evaluation.mode);
    std::vector<ErrorValues> values;
    values.reserve(k.size());
    for (double one : k) values.push_back(errors.at(one));
    return values;
}

nlohmann::json eps_document(const EpsAtK& r)
{
    nlohmann::json per_site = nlohmann::json::array();
    for (const auto& s : r.sites) per_site.push_back(site_report_json(s, r.dimension));
    const auto& v = r.chosen();
    nlohmann::json document = {{"kernel", r.kernel},
                               {"lattice", r.lattice},
                               {"k", r.k},
                               {"a_p", r.a_p},
                               {"h_over_l", r.eta},
                               {"site", r.site},
                               {"eps_rho", v.eps_rho},
                               {"eps_gradp", v.eps_gradp},
                               {"lateral", v.lateral},
                               {"neighbours", v.neighbours},
                               {"support_radius", r.support_radius},
                               {"sites", per_site},
                               {"worst_site", r.sites[r.worst].site}};
    if (r.code) document["code"] = code_k_json(*r.code);
    return document;
}

namespace {

// Every site's values, when the lattice has more than one.
void print_every_site(const EpsAtK& r)
{
    if (r.sites.size() <= 1) return;
    fmt::print(results_file(), "every site (the values above are site {}; worst site {}):\n", r.site,
               r.sites[r.worst].site);
    fmt::print(results_file(), "  {:>4} {:>14} {:>14} {:>10} {:>5}  {:<34} {}\n", "site", "eps_rho", "eps_gradP",
               "lateral", "N_H", "eigenvalues of E", "|first moment|");
    for (const auto& s : r.sites) {
        std::string eigen;
        for (double e : s.gradient.eigenvalues) eigen += fmt::format("{}{:+.6f}", eigen.empty() ? "" : " ", e);
        fmt::print(results_file(), "  {:>4} {:>14.8f} {:>14.8f} {:>10.3g} {:>5}  {:<34} {:.3g}\n", s.site,
                   s.values.eps_rho, s.values.eps_gradp, s.values.lateral, s.values.neighbours, eigen,
                   s.gradient.first_moment.norm());
    }
}

} // namespace

void print_eps(const EpsAtK& r)
{
    const auto& v = r.chosen();
    const std::string given =
        r.code ? fmt::format(" ({} {} = {:.10g})", r.code->setting.code, r.code->parameter, r.code->setting.value)
        : r.axis == Axis::eta ? fmt::format(" (h/l = {:.10g})", r.eta)
                              : "";
    fmt::print(results_file(), "{} on {} at k = {}, a_p = {:.10g}{}\n", r.kernel, r.lattice, r.k, r.a_p, given);
    fmt::print(
        results_file(),
        "  eps_rho    {:.12g}\n  eps_gradP  {:.12g}\n  lateral    {:.3g}\n  N_H        {}\n  H/d        {:.10g}\n",
        v.eps_rho, v.eps_gradp, v.lateral, v.neighbours, r.support_radius);
    print_every_site(r);
}

} // namespace sphkern
