// `sphkern roots`: the k where eps_rho or eps_gradP vanish, the jumps, condition (22).
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "analysis/acceptance.hpp"
#include "analysis/code_conventions.hpp"
#include "analysis/resolution_axis.hpp"
#include "analysis/results_json.hpp"
#include "analysis/roots.hpp"
#include "analysis/site_errors.hpp"
#include "analysis/site_roots.hpp"
#include "stability/dispersion.hpp"
#include "stability/recommended_k.hpp"
#include "stability/roots_convention.hpp"
#include "stability/roots_stability.hpp"
#include "stability/stability_over_k.hpp"
#include "stability/stability_scan.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <tuple>

namespace sphkern::cli {

namespace {

struct RootsOptions : CommonOptions {
    std::string kernel, lattice;
    double k_min = 0.75, k_max = 1.25, epsilon = 0.01;
    bool lateral = false;
    std::string axis = "k";
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
    bool stability = false;
    double gamma = 5.0 / 3.0, horizon = default_horizon;
    int steps = 100;
    std::string convention;
    std::string h_model = "fixed";
};

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
    fmt::print(results_file(), "{:<6} {:>14} {:>12} {:>12} {:>6} {:>10}\n", "zero", "k", "eps_rho", "eps_gradP", "N_H", "H/d");
    for (const auto& r : scan.roots)
        fmt::print(results_file(), "{:<6} {:>14.10f} {:>12.5f} {:>12.5f} {:>6} {:>10.6f}\n", function_name(r.function), r.k,
                   r.values.eps_rho, r.values.eps_gradp, r.values.neighbours, r.support_radius);
    if (scan.roots.empty()) fmt::print(results_file(), "(no root in the interval)\n");
    for (const auto& j : scan.jumps)
        fmt::print(results_file(), "jump of eps_{} at k = {:.10f} ({}): {:.6g} -> {:.6g}\n", function_name(j.function), j.k, jump_kind_name(j.kind),
                   j.left, j.right);
}

// Roots of one kernel on one lattice, for every site, with condition (22) along gravity
// and for every direction: printed, or appended to `collected` as JSON.
void print_roots_stability(const RootsOptions& options, const RootsStability& stability)
{
    if (!options.stability) return;
    if (stability.refused())
        fmt::print(results_file(), "stability (gamma = {:.6g}, {} h): not available: {}\n", options.gamma,
                   options.h_model, stability.json["refused"].get<std::string>());
    else
        fmt::print(results_file(), "stable (gamma = {:.6g}, {} h; no mode grows faster than {:g} d/c) for k in{}\n  "
                                   "accurate (condition (22), every site) and stable:{}\n  {}\n",
                   options.gamma, options.h_model, options.horizon, intervals_text(stability.stable),
                   intervals_text(stability.both), recommended_text(stability.recommended));
}

void print_roots_convention(const RootsOptions& options, const Kernel& kernel, int dimension, double a_p,
                            const Acceptance& all_along, const RecommendedK& recommended)
{
    if (options.convention.empty()) return;
    const auto& c = code_convention(options.convention, "--convention");
    if (const auto why = convention_undefined(c, kernel, dimension); !why.empty())
        return fmt::print(results_file(), "in {}'s convention ({}): {}\n", c.name, c.quantity, why);
    auto in = [&](double k) { return in_convention(c, kernel, dimension, a_p, k); };
    std::string s = fmt::format("in {}'s convention ({}): best k of condition (22) {} = {:.6g}", c.name, c.quantity,
                                c.quantity, in(all_along.best_k));
    for (const auto& i : all_along.intervals)
        s += fmt::format("; (22) holds for {} in [{:.6g}, {:.6g}]", c.quantity, in(i.from), in(i.to));
    if (recommended.found)
        s += fmt::format("; recommended {} = {:.6g} ([{:.6g}, {:.6g}])", c.quantity, in(recommended.k),
                         in(recommended.widest.from), in(recommended.widest.to));
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

void run_one(RootsOptions options, const Kernel& kernel, const Lattice& lattice, nlohmann::json* collected)
{
    double a_p = lattice.volume_coefficient(options.evaluation.ap);
    check_sites(lattice, {options.evaluation.site}, "--site");
    // The window in k for this kernel, lattice and a_p, from the axis it was given on.
    const Axis axis = parse_axis(options.axis, "--axis");
    const double window_min = options.k_min, window_max = options.k_max;
    std::tie(options.k_min, options.k_max) = k_window(axis, window_min, window_max, kernel, lattice,
                                                      options.evaluation.site, a_p, "--kmin/--kmax");
    auto sites = errors_per_site(kernel, lattice, every_site(lattice), a_p, gravity_of(lattice, options.evaluation),
                                 options.k_max, evaluation_mode(options.evaluation));
    std::vector<const HydrostaticErrors*> all;
    for (const auto& s : sites) all.push_back(s.get());
    const auto analysis = analyse_roots(all, options.k_min, options.k_max, options.epsilon, options.lateral);
    const auto& chosen = analysis.sites[static_cast<std::size_t>(options.evaluation.site)];
    // The stable k of the same window, and where condition (22) at every site holds there too.
    RootsStability stability;
    if (options.stability) {
        const RootsStabilityOptions model{options.gamma, options.horizon, options.steps,
                                          parse_h_model(options.h_model, "--h-model")};
        stability = roots_stability(kernel, lattice, options.k_min, options.k_max, model, analysis.all_along.intervals,
                                    *sites[static_cast<std::size_t>(options.evaluation.site)]);
    }
    const auto& recommended = stability.recommended;
    if (options.json) {
        auto document = roots_document(kernel, lattice, a_p, options.k_min, options.k_max, options.epsilon,
                                       options.lateral, options.evaluation.site, analysis, axis, window_min, window_max);
        if (options.stability) document["stability"] = stability.json;
        if (!options.convention.empty())
            document["convention"] = roots_convention_json(code_convention(options.convention, "--convention"), kernel,
                                                           lattice.dimension, a_p, analysis.all_along, recommended);
        collected->push_back(document);
        return;
    }
    auto print_tail = [&] {
        if (at_window_edge(analysis.all_along.best_k, options.k_min, options.k_max))
            fmt::print(results_file(), "best k of condition (22) = {:.6f}: {}\n", analysis.all_along.best_k,
                       window_edge_note);
        print_roots_stability(options, stability);
        print_roots_convention(options, kernel, lattice.dimension, a_p, analysis.all_along, recommended);
    };
    const std::string lateral = options.lateral ? ", lateral error included" : "";
    fmt::print(results_file(), "{} on {}, a_p = {:.10g}, k in [{}, {}]{}{}\n", kernel.label(), lattice.name, a_p,
               options.k_min, options.k_max,
               axis == Axis::k ? "" : fmt::format(" ({} in [{}, {}])", axis_name(axis), window_min, window_max),
               sites.size() > 1 ? fmt::format(", site {}", options.evaluation.site) : "");
    print_scan(chosen.scan);
    fmt::print(results_file(), "condition (22), epsilon = {}{}: {}\n", options.epsilon, lateral, acceptance_text(chosen.along));
    fmt::print(results_file(), "  for every direction (max |eigenvalue of E|): {}\n", acceptance_text(chosen.every));
    if (sites.size() == 1) return print_tail();
    print_other_sites(analysis, options.evaluation.site);
    fmt::print(results_file(), "every site at once{}: along gravity {}\n  for every direction: {}\n", lateral,
               acceptance_text(analysis.all_along), acceptance_text(analysis.all_every));
    print_tail();
}

} // namespace

Action add_roots_command(CLI::App& app)
{
    auto* command = app.add_subcommand("roots", "Roots in k of eps_rho and eps_gradP, jumps and condition (22)");
    auto options = std::make_shared<RootsOptions>();
    command->add_option("kernel", options->kernel, "Kernel name or plugin file, or all")->required();
    command->add_option("lattice", options->lattice, "Lattice name or file, or all (every shipped lattice)")->required();
    command->add_option("--kmin", options->k_min, "Smallest k")->capture_default_str();
    command->add_option("--kmax", options->k_max, "Largest k")->capture_default_str();
    command->add_option("--epsilon", options->epsilon, "Tolerance of condition (22)")->capture_default_str();
    command->add_flag("--lateral", options->lateral, "Count the lateral gradient error in condition (22) too");
    command->add_option("--axis", options->axis, "The scale of --kmin/--kmax: k (h/d), eta (h/V^(1/D)) or nh (neighbours)")
        ->capture_default_str();
    command->add_flag("--stability", options->stability, "Also the stable k intervals of the window (linear "
                                                        "stability) and where condition (22) holds there");
    command->add_option("--gamma", options->gamma, "With --stability: adiabatic index")->capture_default_str();
    command->add_option("--steps", options->steps, "With --stability: k intervals of the scan")->capture_default_str()
        ->check(CLI::Range(1, 2000));
    command->add_option("--convention", options->convention, "Also give k in a code's convention: pysph (hdx), "
                                                             "dualsphysics (coefh), swift (eta), gadget (N_ngb), "
                                                             "splishsplash (H/r_p)");
    command->add_option("--horizon", options->horizon, "With --stability: growth time in d/c; slower instabilities "
                                                       "count as stable (weak)")->capture_default_str();
    command->add_option("--h-model", options->h_model, "With --stability: fixed or adaptive h (h = eta (m/rho)^(1/D), "
                                                       "grad-h terms); k is the equilibrium h = k d in both")
        ->capture_default_str();
    add_evaluation_options(*command, options->evaluation);
    add_set_option(*command, options->sets);
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    return [options] {
        if (options->axis == "k") check_k_interval(options->k_min, options->k_max, ValueSource::argument("--kmin/--kmax"));
        if (!std::isfinite(options->epsilon) || options->epsilon <= 0 || options->epsilon >= 1)
            throw Error(ExitCode::usage, "--epsilon must be in (0, 1)");
        check_gamma(options->gamma, "--gamma");
        check_horizon(options->horizon, "--horizon");
        parse_h_model(options->h_model, "--h-model");
        if (!options->convention.empty()) code_convention(options->convention, "--convention");
        auto registry = discover_kernels(*options);
        std::vector<Lattice> lattices;
        if (options->lattice == "all")
            for (const auto& name : shipped_lattice_names()) lattices.push_back(load_lattice(name));
        else
            lattices.push_back(load_lattice(options->lattice));
        std::vector<Kernel> kernels;
        if (options->kernel == "all")
            for (const auto& p : registry.plugins()) kernels.emplace_back(p, parse_sets(options->sets));
        else
            kernels.push_back(make_kernel(registry, options->kernel, options->sets));
        const bool many = kernels.size() > 1 || lattices.size() > 1;
        nlohmann::json all = nlohmann::json::array();
        for (const auto& lattice : lattices)
            for (const auto& kernel : kernels) {
                if (many && !kernel.supports(lattice.dimension)) continue; // "all": the pairs that exist
                run_one(*options, kernel, lattice, &all);
            }
        // One shape for one pair and for many: an array of documents.
        if (options->json) print_json(all);
        return 0;
    };
}

} // namespace sphkern::cli
