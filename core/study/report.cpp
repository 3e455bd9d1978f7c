#include "study/report.hpp"

#include "analysis/resolution_axis.hpp"
#include "codes/swift/swift_gamma.hpp"
#include "study/report_text.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/provenance.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace sphkern {

namespace {

std::string number(const nlohmann::json& v, int decimals = 5)
{
    if (v.is_number()) return fmt::format("{:.{}f}", v.get<double>(), decimals);
    if (v.is_string()) return v.get<std::string>();
    return "-";
}

std::string fixed(double v, int decimals = 5)
{
    if (std::abs(v) >= 1e3) return fmt::format("{:.3g}", v);
    if (std::abs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0; // no "-0.00000"
    return fmt::format("{:.{}f}", v, decimals);
}

// The value of k on the study's axis, for the tables: "" on the k axis (nh is the N_H column).
std::string on_axis(const Study& study, double k, const StudyCase& c)
{
    if (study.axis != Axis::eta) return "";
    return fmt::format(" (h/l {:.4f})", eta_of_k(k, c.a_p, c.dimension));
}

std::string intervals_on_axis(const Study& study, const std::vector<KInterval>& intervals, const StudyCase& c)
{
    if (study.axis != Axis::eta || intervals.empty()) return "";
    std::string s;
    for (const auto& i : intervals)
        s += fmt::format("{}[{:.4f}, {:.4f}]", s.empty() ? "" : " ", eta_of_k(i.from, c.a_p, c.dimension),
                         eta_of_k(i.to, c.a_p, c.dimension));
    return " = h/l " + s;
}

std::string eps_name(ErrorFunction function) { return function == ErrorFunction::rho ? "eps_rho" : "eps_gradP"; }

// The cases grouped by lattice, mode and a_p, in the order they first appear.
std::vector<std::vector<const StudyCase*>> grouped(const StudyResults& results)
{
    std::vector<std::vector<const StudyCase*>> groups;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::size_t> index;
    for (const auto& c : results.cases) {
        auto key = std::make_tuple(c.key.lattice, c.key.mode, c.key.volume_coefficient);
        auto [it, added] = index.emplace(key, groups.size());
        if (added) groups.emplace_back();
        groups[it->second].push_back(&c);
    }
    return groups;
}

// "erratum: eps_gradP differs": the status and what made it.
std::string status_text(const ComparisonRow& r)
{
    std::string s = status_name(r.status);
    if (r.differing.empty()) return s;
    std::string what;
    for (const auto& d : r.differing)
        what += (what.empty() ? "" : ", ") + (d == "eps_gradp" ? std::string("eps_gradP") : d);
    return s + ": " + what + " differ" + (r.differing.size() == 1 ? "s" : "");
}

} // namespace

std::string replication_markdown(const StudyResults& results)
{
    if (results.comparison.empty()) return {};
    const auto& ref = results.reference;
    std::string s = fmt::format(
        "## Replication of the reference table\n\n{}: lattice {}, a_p = {}, mode \"{}\". A row is reproduced only "
        "when k and every error value the reference prints agree within {}; otherwise its status names what differs "
        "(an erratum: the reference itself is in error there, see the note).\n\n",
        ref.value("source", "reference"), ref.value("lattice", "?"), ref.value("volume_coefficient", "?"),
        ref.value("mode", "?"), results.tolerance);
    s += "| kernel | zero of | k (paper) | k (sphkern) | Δk | eps_rho (paper) | eps_rho (sphkern) | eps_gradP (paper) "
         "| eps_gradP (sphkern) | status | note |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    int reproduced = 0, errata = 0;
    for (const auto& r : results.comparison) {
        reproduced += r.status == ComparisonStatus::reproduced;
        errata += r.status == ComparisonStatus::erratum;
        const auto& p = r.reference;
        if (!r.function) {
            s += fmt::format("| {} | - | no root | {} | | | | | | {} | {} |\n", r.kernel,
                             r.status == ComparisonStatus::reproduced ? "no root" : "roots found", status_text(r),
                             r.note);
            continue;
        }
        std::string gradp_paper = p.contains("printed_eps_gradp") ? p["printed_eps_gradp"].get<std::string>()
                                                                  : number(p.value("eps_gradp", nlohmann::json()));
        if (r.computed)
            s += fmt::format("| {} | {} | {} | {:.5f} | {:+.1e} | {} | {} | {} | {} | {} | {} |\n", r.kernel,
                             eps_name(*r.function), number(p["k"]), r.computed->k, r.computed->k - p["k"].get<double>(),
                             number(p["eps_rho"]), fixed(r.computed->values.eps_rho), gradp_paper,
                             fixed(r.computed->values.eps_gradp), status_text(r), r.note);
        else
            s += fmt::format("| {} | {} | {} | - | | {} | | {} | | {} | {} |\n", r.kernel, eps_name(*r.function),
                             number(p["k"]), number(p["eps_rho"]), gradp_paper, status_text(r), r.note);
    }
    s += fmt::format("\n{} of {} rows reproduced; {} row(s) differ where the reference is in error (errata); {} differ "
                     "otherwise.\n\n",
                     reproduced, results.comparison.size(), errata, results.comparison.size() - reproduced - errata);
    return s;
}

namespace {

using CaseGroup = std::vector<const StudyCase*>;

std::string verdicts_intro(const Study& study)
{
    std::string s = fmt::format(
        "## Condition (22): |eps_rho| <= {:.6g} and |eps_gradP| <= {:.6g} for some {} in [{:.6g}, {:.6g}]\n\n",
        study.epsilon, study.epsilon, axis_name(study.axis), study.k_min, study.k_max);
    if (study.axis != Axis::k)
        s += fmt::format("The window is given on the {} axis ({}); each table below names the k interval it is for "
                         "its kernel, lattice and a_p.\n\n",
                         axis_name(study.axis),
                         study.axis == Axis::eta ? "h_over_l = h / l, l = V^(1/D), V = a_p d^D the particle volume"
                                                 : "nh = the number of neighbours inside the support");
    s += fmt::format(
        "The verdict shown is the paper's: eps_gradP along the lattice's gravity{}, at every site studied at "
        "once ({}). The same condition for every direction (the largest |eigenvalue| of the "
        "gradient-error tensor in place of |eps_gradP|) is in the column \"every direction\" of the "
        "tables below.\n\n",
        study.lateral ? ", the lateral error included" : "",
        study.sites ? "the sites listed in the study" : "every site of each lattice");
    return s;
}

// A summary matrix: kernels down, lattice / mode / a_p across.
std::string verdicts_matrix(const Study& study, const StudyResults& results, const std::vector<CaseGroup>& groups)
{
    std::vector<std::string> kernels;
    for (const auto& c : results.cases)
        if (std::find(kernels.begin(), kernels.end(), c.kernel_label) == kernels.end())
            kernels.push_back(c.kernel_label);
    std::string s = "| kernel |";
    std::string rule = "|---|";
    for (const auto& g : groups) {
        s += fmt::format(" {} {}{} |", g[0]->lattice, g[0]->ap_name,
                         study.modes.size() > 1 ? " (" + g[0]->mode + ")" : "");
        rule += "---|";
    }
    s += "\n" + rule + "\n";
    for (const auto& kernel : kernels) {
        s += "| " + kernel + " |";
        for (const auto& g : groups) {
            auto it = std::find_if(g.begin(), g.end(), [&](const StudyCase* c) { return c->kernel_label == kernel; });
            s += it == g.end()                ? " |"
                 : (*it)->acceptance.passes() ? fmt::format(" **pass** k={:.3f}{} |", (*it)->acceptance.best_k,
                                                            on_axis(study, (*it)->acceptance.best_k, **it))
                                              : fmt::format(" fail ({:.2g}) |", (*it)->acceptance.best_error);
        }
        s += "\n";
    }
    return s + "\npass: the best k (smallest max(|eps_rho|, |eps_gradP|)); fail: that smallest maximum.\n\n";
}

// "; k in [a, b] for every kernel", or each kernel's, when the window is not on the k axis.
std::string group_windows(const Study& study, const CaseGroup& g)
{
    std::string windows;
    if (study.axis == Axis::k) return windows;
    const bool same = std::all_of(g.begin(), g.end(), [&](const StudyCase* c) {
        return std::abs(c->k_min - g[0]->k_min) < 5e-5 && std::abs(c->k_max - g[0]->k_max) < 5e-5;
    });
    if (same) return fmt::format("; k in [{:.4f}, {:.4f}] for every kernel", g[0]->k_min, g[0]->k_max);
    for (const auto* c : g)
        windows += fmt::format("{}{} k in [{:.4f}, {:.4f}]", windows.empty() ? "; " : ", ", c->kernel_label, c->k_min,
                               c->k_max);
    return windows;
}

// Several sites: each on its own, so that a site that fails is seen.
std::string per_site_table(const CaseGroup& g)
{
    if (g[0]->per_site.empty()) return {};
    std::string s = "Each site on its own (along gravity / every direction):\n\n| kernel |";
    std::string rule = "|---|";
    for (const auto& p : g[0]->per_site) {
        s += fmt::format(" site {} |", p.site);
        rule += "---|";
    }
    s += "\n" + rule + "\n";
    for (const auto* c : g) {
        s += "| " + c->kernel_label + " |";
        for (const auto& p : c->per_site)
            s += fmt::format(" {} / {} (best k {:.3f}) |", p.along.passes() ? "pass" : "fail",
                             p.every.passes() ? "pass" : "fail", p.along.best_k);
        s += "\n";
    }
    return s + "\n";
}

std::string group_verdicts(const Study& study, const CaseGroup& g)
{
    std::string s = fmt::format("### {} ({}D), mode {}, a_p = {} = {:.6f}{}\n\n", g[0]->lattice, g[0]->dimension,
                                g[0]->mode, g[0]->ap_name, g[0]->a_p, group_windows(study, g)) +
                    "| kernel | verdict | k where (22) holds | best k | max(\\|eps_rho\\|, \\|eps_gradP\\|) at best k "
                    "| every direction |\n"
                    "|---|---|---|---|---|---|\n";
    for (const auto* c : g)
        s += fmt::format("| {} | {} | {}{} | {:.4f}{} | {:.2e} | {} {} |\n", c->kernel_label,
                         c->acceptance.passes() ? "**pass**" : "fail", intervals_text(c->acceptance),
                         intervals_on_axis(study, c->acceptance.intervals, *c), c->acceptance.best_k,
                         on_axis(study, c->acceptance.best_k, *c), c->acceptance.best_error,
                         c->acceptance_every.passes() ? "pass" : "fail", intervals_text(c->acceptance_every));
    return s + "\n" + per_site_table(g);
}

} // namespace

std::string verdicts_markdown(const Study& study, const StudyResults& results)
{
    const auto groups = grouped(results);
    std::string s = verdicts_intro(study) + verdicts_matrix(study, results, groups);
    for (const auto& g : groups) s += group_verdicts(study, g);
    return s;
}

namespace {

std::string header_markdown(const Study& study, const nlohmann::json& inputs)
{
    const std::string sha = inputs.value("study", nlohmann::json::object()).value("sha256", std::string());
    std::string s = fmt::format("# {}\n\n{}; study `{}`{}: {} in [{:.6g}, {:.6g}], {} samples per curve, epsilon = "
                                "{:.6g}. results.json records the inputs in full and how they were run.\n"
                                "Errors are the bulk relative errors of {} section 2 (a particle on a lattice "
                                "site, gravity along the lattice's default direction).\n\n",
                                study.title, version_text(), std::filesystem::path(study.file).filename().string(),
                                sha.empty() ? "" : " (SHA-256 " + sha.substr(0, 16) + "…)", axis_name(study.axis),
                                study.k_min, study.k_max, study.samples, study.epsilon, method_document());
    s += "Modes: ";
    for (const auto& m : study.modes) {
        s += fmt::format("**{}** ", m.name);
        if (m.is_automatic()) {
            s += "(every shell inside the support, kernel truncated at R; what a correct SPH code computes); ";
        } else {
            s += "(fixed shell lists by R:";
            for (const auto& [R, radii] : m.shells_by_support) {
                s += fmt::format(" R = {}: {{", R);
                for (std::size_t i = 0; i < radii.size(); ++i) s += fmt::format("{}{:.4f}", i ? ", " : "", radii[i]);
                s += "}";
            }
            if (m.continue_all) s += "; every kernel's formula continued past R";
            else if (!m.continue_kernels.empty()) {
                s += "; formula continued past R for";
                for (const auto& k : m.continue_kernels) s += " " + k;
            }
            s += "); ";
        }
    }
    s += "\n\n";
    return s;
}

std::string explanations_markdown(const StudyResults& results)
{
    std::string s;
    // Why the non-automatic modes differ from the default, root by root.
    bool any = false;
    for (const auto& c : results.cases) {
        if (c.automatic || c.explanations.empty()) continue;
        if (!any) {
            s += "## Why the modes differ\n\nFor every root of a fixed-shell mode: the same error in the default "
                 "evaluation at that k, the nearest default root, and each term that differs (its contribution to "
                 "the error that vanished).\n\n"
                 "| lattice | a_p | mode | kernel | zero of | k | default value at k | nearest default root | cause |\n"
                 "|---|---|---|---|---|---|---|---|---|\n";
            any = true;
        }
        for (const auto& e : c.explanations) {
            std::string causes;
            for (const auto& d : e.differences)
                causes += fmt::format("{}shell r = {:.4f} d ({}) {} at q = {:.3f}: {:+.5f}", causes.empty() ? "" : "; ",
                                      d.radius, d.count, d.reason, d.q, d.contribution);
            if (causes.empty()) causes = "none: identical terms";
            s += fmt::format("| {} | {} | {} | {} | {} | {:.5f} | {} | {} | {} |\n", c.lattice, c.ap_name, c.mode,
                             c.kernel_label, eps_name(e.root.function), e.root.k, fixed(e.default_value),
                             e.default_root_k ? fmt::format("{:.5f}", *e.default_root_k) : std::string("none"), causes);
        }
    }
    if (any) s += "\n";

    return s;
}

std::string roots_markdown(const Study& study, const StudyResults& results)
{
    std::string s;
    s += "## Roots and jumps\n\n";
    for (const auto& g : grouped(results)) {
        s +=
            fmt::format("### {}, mode {}, a_p = {} = {:.6f}\n\n", g[0]->lattice, g[0]->mode, g[0]->ap_name, g[0]->a_p) +
            "| kernel | zero of | k | eps_rho | eps_gradP | N_H | H/d |\n|---|---|---|---|---|---|---|\n";
        for (const auto* c : g) {
            if (c->scan.roots.empty()) s += fmt::format("| {} | no root | | | | | |\n", c->kernel_label);
            for (const auto& r : c->scan.roots)
                s += fmt::format("| {} | {} | {:.5f}{} | {} | {} | {} | {:.4f} |\n", c->kernel_label,
                                 eps_name(r.function), r.k, on_axis(study, r.k, *c), fixed(r.values.eps_rho),
                                 fixed(r.values.eps_gradp), r.values.neighbours, r.support_radius);
            for (const auto& j : c->scan.jumps)
                s += fmt::format("| {} | jump of {} ({}) | {:.5f} | {} -> {} | | | |\n", c->kernel_label,
                                 eps_name(j.function), jump_kind_name(j.kind), j.k, fixed(j.left), fixed(j.right));
        }
        s += "\n";
    }
    return s;
}

std::string figures_markdown(const std::vector<std::string>& figures)
{
    std::string s;
    if (!figures.empty()) {
        s += "## Figures\n\nErrors against k: the density error solid, the pressure-gradient error dashed, one "
             "colour per a_p, the band |error| <= epsilon shaded (as the paper's Figs. 4 to 6), on a symmetric "
             "logarithmic axis (linear within epsilon / 10 of zero, logarithmic beyond), so that every curve stays "
             "in its panel. Stability: min omega^2 of each branch against k on a symmetric logarithmic axis "
             "(linear within 1e-5), the k where condition (22) holds shaded green, the stable k as a blue bar at the "
             "bottom with a red mark on every unstable sample; dispersion curves: omega^2 of each branch along the "
             "high-symmetry path at the k named in the panel (linear within 1e-3). Each panel has its own legend.\n\n";
        for (const auto& f : figures) s += fmt::format("![{}]({})\n\n", f, f);
    }
    return s;
}

// Each optional section's part, in the table's order.
std::string sections_markdown(const Study& study, const StudyResults& results)
{
    std::string s;
    for (const auto& section : results.sections)
        if (section) s += section->markdown(study);
    return s;
}

// The terms the tables use, in the report itself so that it reads on its own.
std::string glossary_markdown()
{
    return "## Glossary\n\n"
           "| term | meaning |\n|---|---|\n"
           "| d | the nearest-neighbour distance of the lattice, the unit of length |\n"
           "| h, k | the smoothing length and the smoothing coefficient k = h / d |\n"
           "| R, H | the kernel's support in units of h, and the support radius H = R h; H/d = R k |\n"
           "| a_p | the volume coefficient: a particle's volume is V = a_p d^D (voronoi: the volume per site; ball: "
           "the inscribed ball; cube: d^D; or a number) |\n"
           "| h/l (h_over_l) | h / V^(1/D), sphkern's own: the resolution on a scale common to every lattice and a_p "
           "(SWIFT's eta divides SWIFT's h, H / gamma, not H / R) |\n"
           "| N_H (nh) | the number of neighbours inside the support radius H, the particle itself excluded |\n"
           "| eps_rho, eps_gradP | the relative errors of the SPH density and of the hydrostatic pressure gradient "
           "along gravity for a particle at rest on a lattice site (method.md section 2) |\n"
           "| condition (22) | \\|eps_rho\\| <= epsilon and \\|eps_gradP\\| <= epsilon: the paper's test of a kernel, "
           "lattice and a_p |\n"
           "| every direction | condition (22) with the largest \\|eigenvalue\\| of the gradient-error tensor in place "
           "of \\|eps_gradP\\| |\n"
           "| mode | how the sums are formed: default, every shell inside the support with the kernel cut at R; a "
           "fixed-shell mode (the paper's), listed shells only, some formulas continued past R |\n"
           "| root, jump | a k where an error crosses zero continuously; a k where it changes sign by a step (a "
           "shell entering the support) or across a pole |\n"
           "| omega^2, branch | the squared frequency of a plane wave in (c/d)^2 (negative: it grows, the lattice "
           "is unstable), one per polarisation |\n\n";
}

} // namespace

std::string report_markdown(const Study& study, const StudyResults& results, const std::vector<std::string>& figures)
{
    return header_markdown(study, results.inputs) + glossary_markdown() + replication_markdown(results) +
           explanations_markdown(results) + roots_markdown(study, results) + verdicts_markdown(study, results) +
           sections_markdown(study, results) + figures_markdown(figures);
}

} // namespace sphkern
