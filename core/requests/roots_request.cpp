#include "requests/roots_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "analysis/site_errors.hpp"
#include "stability/dispersion.hpp"
#include "stability/recommended_k.hpp"
#include "stability/stability_scan.hpp"
#include "support/error.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <tuple>

namespace sphkern {

void check_roots_request(const RootsRequest& r, const RootsSources& sources)
{
    if (r.axis == Axis::k) check_k_interval(r.window_min, r.window_max, sources.window);
    if (!std::isfinite(r.epsilon) || r.epsilon <= 0 || r.epsilon >= 1)
        throw Error(sources.epsilon.code, sources.epsilon.name + " must be in (0, 1)");
    check_gamma(r.model.gamma, sources.gamma.name);
    check_horizon(r.model.horizon, sources.horizon.name);
    check_setting(settings_of("roots")["steps"], r.model.steps, sources.steps);
    check_setting(settings_of("roots")["threads"], r.model.threads, sources.threads);
    check_evaluation(r.evaluation, sources.evaluation);
}

namespace {

// Each k of the answer as the code's setting, with the lattice's density at the chosen site.
RootsInCode in_code(const CodeProfile& profile, const RootsResult& result, const Kernel& kernel, int dimension,
                    const HydrostaticErrors& site)
{
    require_code_kernel(profile, kernel, dimension);
    require_lattice_volume(profile, "a window of k at the lattice's a_p");
    auto value = [&](double k) {
        return code_parameter(profile, kernel, dimension, result.a_p, k, site.at(k).eps_rho);
    };
    RootsInCode c;
    c.best = value(result.analysis.all_along.best_k);
    for (const auto& i : result.analysis.all_along.intervals) c.accurate.push_back({value(i.from), value(i.to)});
    for (const auto& i : result.stability.both) c.both.push_back({value(i.from), value(i.to)});
    if (const auto& r = result.stability.recommended; r.found) {
        c.recommended = KInterval{value(r.widest.from), value(r.widest.to)};
        c.recommended_value = value(r.k);
    }
    return c;
}

} // namespace

RootsResult run_roots(const RootsRequest& r, const RootsSources& sources, const Kernel& kernel, const Lattice& lattice)
{
    const auto evaluation = resolve_evaluation(r.evaluation, sources.evaluation, lattice);
    RootsResult result;
    result.a_p = evaluation.a_p;
    // The window in k for this kernel, lattice and a_p, from the axis it was given on.
    std::tie(result.k_min, result.k_max) = k_window(r.axis, r.window_min, r.window_max, kernel, lattice,
                                                    evaluation.site, evaluation.a_p, sources.window.name);
    auto sites = errors_per_site(kernel, lattice, every_site(lattice), evaluation.a_p, evaluation.gravity, result.k_max,
                                 evaluation.mode);
    std::vector<const HydrostaticErrors*> all;
    for (const auto& s : sites) all.push_back(s.get());
    result.analysis = analyse_roots(all, result.k_min, result.k_max, r.epsilon, r.lateral);
    // The stable k of the same window, and where condition (22) at every site holds there too.
    if (r.stability)
        result.stability =
            roots_stability(kernel, lattice, result.k_min, result.k_max, r.model, result.analysis.all_along.intervals,
                            *sites[static_cast<std::size_t>(evaluation.site)]);
    if (r.code)
        result.in_code =
            in_code(*r.code, result, kernel, lattice.dimension, *sites[static_cast<std::size_t>(evaluation.site)]);
    return result;
}

nlohmann::json roots_request_document(const RootsRequest& r, const RootsResult& result, const Kernel& kernel,
                                      const Lattice& lattice)
{
    auto document = roots_document(kernel, lattice, result.a_p, result.k_min, result.k_max, r.epsilon, r.lateral,
                                   r.evaluation.site, result.analysis, r.axis, r.window_min, r.window_max);
    if (r.stability) document["stability"] = result.stability.json;
    if (const auto& c = result.in_code) {
        nlohmann::json accurate = nlohmann::json::array();
        for (const auto& i : c->accurate) accurate.push_back({i.from, i.to});
        document["code"] = {{"name", r.code->name},
                            {"parameter", r.code->parameter},
                            {"best_k", c->best},
                            {"accurate", accurate}};
        if (c->recommended)
            document["code"].update({{"recommended", c->recommended_value},
                                     {"recommended_interval", {c->recommended->from, c->recommended->to}}});
    }
    return document;
}

namespace {

std::string intervals_text(const std::vector<KInterval>& intervals)
{
    std::string s;
    for (const auto& i : intervals) s += fmt::format(" [{:.6f}, {:.6f}]", i.from, i.to);
    return s.empty() ? " none" : s;
}

std::string acceptance_text(const Acceptance& a)
{
    std::string s = a.passes() ? "passes for k in" : "fails";
    for (const auto& i : a.intervals) s += fmt::format(" [{:.6f}, {:.6f}]", i.from, i.to);
    return s + fmt::format("; best k = {:.6f} with max |eps| = {:.3g}", a.best_k, a.best_error);
}

void print_scan(const RootScan& scan)
{
    fmt::print(results_file(), "{:<6} {:>14} {:>12} {:>12} {:>6} {:>10}\n", "zero", "k", "eps_rho", "eps_gradP", "N_H",
               "H/d");
    for (const auto& r : scan.roots)
        fmt::print(results_file(), "{:<6} {:>14.10f} {:>12.5f} {:>12.5f} {:>6} {:>10.6f}\n", function_name(r.function),
                   r.k, r.values.eps_rho, r.values.eps_gradp, r.values.neighbours, r.support_radius);
    if (scan.roots.empty()) fmt::print(results_file(), "(no root in the interval)\n");
    for (const auto& j : scan.jumps)
        fmt::print(results_file(), "jump of eps_{} at k = {:.10f} ({}): {:.6g} -> {:.6g}\n", function_name(j.function),
                   j.k, jump_kind_name(j.kind), j.left, j.right);
}

void print_roots_stability(const RootsRequest& r, const RootsStability& stability)
{
    if (!r.stability) return;
    const auto& m = r.model;
    if (stability.refused())
        fmt::print(results_file(), "stability (gamma = {:.6g}, {} h): not available: {}\n", m.gamma,
                   h_model_name(m.h_model), stability.json["refused"].get<std::string>());
    else
        fmt::print(results_file(),
                   "stable (gamma = {:.6g}, {} h; no mode grows faster than {:g} d/c) for k in{}\n  "
                   "accurate (condition (22), every site) and stable:{}\n  {}\n",
                   m.gamma, h_model_name(m.h_model), m.horizon, intervals_text(stability.stable),
                   intervals_text(stability.both), recommended_text(stability.recommended));
}

void print_roots_in_code(const RootsRequest& r, const RootsResult& result)
{
    if (!result.in_code) return;
    const auto& c = *result.in_code;
    const std::string& p = r.code->parameter;
    std::string s = fmt::format("in {}'s own setting ({}{}): best k of condition (22) {} = {:.6g}", r.code->name, p,
                                r.code->from_sph_density ? ", with its SPH density" : "", p, c.best);
    for (const auto& i : c.accurate) s += fmt::format("; (22) holds for {} in [{:.6g}, {:.6g}]", p, i.from, i.to);
    if (c.recommended)
        s += fmt::format("; recommended {} = {:.6g} ([{:.6g}, {:.6g}])", p, c.recommended_value, c.recommended->from,
                         c.recommended->to);
    fmt::print(results_file(), "{}\n", s);
}

// Every site but the chosen one, after it.
void print_other_sites(const RootsAnalysis& analysis, int chosen)
{
    for (const auto& s : analysis.sites) {
        if (s.site == chosen) continue;
        fmt::print(results_file(), "site {}:\n", s.site);
        print_scan(s.scan);
        fmt::print(results_file(), "condition (22): {}\n  for every direction: {}\n", acceptance_text(s.along),
                   acceptance_text(s.every));
    }
}

// What follows the sites: the best k at the window's edge, stability, the code's setting.
void print_roots_tail(const RootsRequest& r, const RootsResult& result)
{
    if (at_window_edge(result.analysis.all_along.best_k, result.k_min, result.k_max))
        fmt::print(results_file(), "best k of condition (22) = {:.6f}: {}\n", result.analysis.all_along.best_k,
                   window_edge_note);
    print_roots_stability(r, result.stability);
    print_roots_in_code(r, result);
}

} // namespace

void print_roots(const RootsRequest& r, const RootsResult& result, const Kernel& kernel, const Lattice& lattice)
{
    const auto& analysis = result.analysis;
    const int site = r.evaluation.site;
    const auto& chosen = analysis.sites[static_cast<std::size_t>(site)];
    const bool many_sites = analysis.sites.size() > 1;
    const std::string lateral = r.lateral ? ", lateral error included" : "";
    fmt::print(results_file(), "{} on {}, a_p = {:.10g}, k in [{}, {}]{}{}\n", kernel.label(), lattice.name, result.a_p,
               result.k_min, result.k_max,
               r.axis == Axis::k ? "" : fmt::format(" ({} in [{}, {}])", axis_name(r.axis), r.window_min, r.window_max),
               many_sites ? fmt::format(", site {}", site) : "");
    print_scan(chosen.scan);
    fmt::print(results_file(), "condition (22), epsilon = {}{}: {}\n", r.epsilon, lateral,
               acceptance_text(chosen.along));
    fmt::print(results_file(), "  for every direction (max |eigenvalue of E|): {}\n", acceptance_text(chosen.every));
    if (many_sites) {
        print_other_sites(analysis, site);
        fmt::print(results_file(), "every site at once{}: along gravity {}\n  for every direction: {}\n", lateral,
                   acceptance_text(analysis.all_along), acceptance_text(analysis.all_every));
    }
    print_roots_tail(r, result);
}

} // namespace sphkern
