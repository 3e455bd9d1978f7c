#include "study/sections/stability/stability_section.hpp"

#include "analysis/results_json.hpp"
#include "codes/code_table.hpp"
#include "stability/stability_json.hpp"
#include "study/canvas.hpp"
#include "study/report_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

nlohmann::json stability_json(const StabilityCase& c)
{
    nlohmann::json entry = {{"lattice", c.lattice},
                            {"kernel", c.kernel_label},
                            {"gamma", c.gamma},
                            {"h_model", c.h_model}};
    if (c.refused) {
        entry["refused"] = *c.refused;
        return entry;
    }
    nlohmann::json ks = nlohmann::json::array(), minima = nlohmann::json::array(), stable = nlohmann::json::array(),
                   verdicts = nlohmann::json::array(), growth = nlohmann::json::array(),
                   kinds = nlohmann::json::array(), overlap = nlohmann::json::array();
    for (const auto& s : c.over_k.samples) {
        ks.push_back(s.k);
        minima.push_back(s.branch_minima);
        stable.push_back(s.stable);
        verdicts.push_back(verdict_name(s.verdict));
        const bool grows = std::isfinite(s.growth_time);
        growth.push_back(grows ? nlohmann::json(s.growth_time) : nlohmann::json());
        kinds.push_back(grows ? nlohmann::json(mode_kind_name(s.mode.kind)) : nlohmann::json());
    }
    for (const auto& o : c.overlap) {
        auto recommended = recommended_json(o.recommended);
        for (std::size_t i = 0; i < o.in_codes.size(); ++i) // a code that does not ship the kernel is left out
            if (std::isfinite(o.in_codes[i])) recommended["codes"][study_codes()[i]->name] = o.in_codes[i];
        overlap.push_back({{"volume_coefficient", o.ap_name},
                           {"accurate", intervals_json(o.accurate)},
                           {"accurate_and_stable", intervals_json(o.both)},
                           {"recommended", recommended}});
    }
    entry.update({{"bravais", c.over_k.bravais},
                  {"k", ks},
                  {"branch_minima", minima},
                  {"stable", stable},
                  {"horizon", c.over_k.horizon},
                  {"verdict", verdicts},
                  {"growth_time", growth},
                  {"mode", kinds},
                  {"stable_intervals", intervals_json(c.over_k.stable)},
                  {"stable_at_horizon", intervals_json(c.over_k.usable)},
                  {"overlap", overlap},
                  {"dispersion", {{"k", c.path_k}, {"path", dispersion_path_json(c.path)}}}});
    return entry;
}

// One recommended k per kernel, lattice and a_p, and the same resolution in each code's own setting.
std::string recommended_markdown(const std::vector<StabilityCase>& cases)
{
    std::string s =
        "### Recommended k\n\nThe centre of the widest interval where condition (22) holds and no mode grows "
        "faster than the horizon, with its margin in k and N_H, and the same resolution in each code's own "
        "setting, with the lattice's SPH density where the code solves for h with it (" +
        method_document() +
        " section 9; blank where the code does not ship the kernel).\n\n| lattice | kernel | a_p | k | N_H |";
    for (const CodeProfile* c : study_codes()) s += fmt::format(" {} {} |", c->name, c->parameter);
    s += "\n|---|---|---|---|---|";
    for (std::size_t i = 0; i < study_codes().size(); ++i) s += "---|";
    s += "\n";
    for (const auto& c : cases)
        for (const auto& o : c.overlap) {
            const auto& r = o.recommended;
            if (!r.found) {
                s += fmt::format("| {} | {} | {} | none: no k is both accurate and stable | |", c.lattice,
                                 c.kernel_label, o.ap_name);
                for (std::size_t i = 0; i < study_codes().size(); ++i) s += " |";
                s += "\n";
                continue;
            }
            s += fmt::format("| {} | {} | {} | {:.4f} ± {:.4f}{} | {} ({} to {}) |", c.lattice, c.kernel_label,
                             o.ap_name, r.k, r.margin, r.at_window_edge ? fmt::format(" ({})", window_edge_note) : "",
                             r.neighbours, r.neighbours_from, r.neighbours_to);
            for (double v : o.in_codes) s += std::isfinite(v) ? fmt::format(" {:.4g} |", v) : " |";
            s += "\n";
        }
    return s + "\n";
}

// Legend entries for the shaded bands and bars of the stability panels.
const char* stability_legend =
    "keyentry with boxes fs solid 1.0 noborder lc rgb '#d9f0d3' title 'condition (22) holds', "
    "keyentry with boxes fs solid 1.0 noborder lc rgb '#4575b4' title 'stable k', "
    "keyentry with boxes fs solid 1.0 noborder lc rgb '#d73027' title 'unstable sample'";

// One stability panel: min omega^2 of each branch against k (symmetric log), the accurate
// k shaded, the stable intervals as a blue bar with a red mark on every unstable sample.
std::string stability_panel(const StabilityCase& c, const std::string& id)
{
    std::string script = "$" + id + " << EOD\n";
    SymLog axis{1e-5};
    for (const auto& s : c.over_k.samples) {
        script += fmt::format("{:.8f}", s.k);
        for (double w : s.branch_minima) script += fmt::format(" {:.10g}", w), axis.add(w);
        script += "\n";
    }
    script += "EOD\nunset object\n";
    int object = 1;
    if (!c.overlap.empty())
        for (const auto& i : c.overlap.front().accurate)
            script += fmt::format("set object {} rect from {},graph 0 to {},graph 1 fc rgb '#d9f0d3' fs solid noborder "
                                  "behind\n",
                                  object++, i.from, i.to);
    for (const auto& i : c.over_k.stable)
        script += fmt::format("set object {} rect from {},graph 0 to {},graph 0.04 fc rgb '#4575b4' fs solid noborder "
                              "front\n",
                              object++, i.from, i.to);
    const auto& samples = c.over_k.samples;
    const double half =
        samples.size() > 1 ? (samples.back().k - samples.front().k) / double(samples.size() - 1) / 2 : 0.005;
    for (const auto& s : samples)
        if (!s.stable)
            script += fmt::format("set object {} rect from {},graph 0 to {},graph 0.06 fc rgb '#d73027' fs solid "
                                  "noborder front\n",
                                  object++, s.k - half, s.k + half);
    std::string plot;
    for (std::size_t b = 0; b < samples.front().branch_minima.size(); ++b)
        plot += fmt::format("${} using 1:{} with lines lw 2 lc rgb '{}' title 'branch {}{}', ", id,
                            axis.using_column(static_cast<int>(b) + 2), branch_colours[b % 6], b + 1,
                            b == 0 ? " (lowest)" : "");
    return script + axis.tics() +
           fmt::format("set xrange [{}:{}]\nset title '{}' noenhanced\nplot {}{}\n", samples.front().k,
                       samples.back().k, c.kernel_label, plot, stability_legend);
}

// One dispersion panel: omega^2 of every branch along the high-symmetry path.
std::string dispersion_panel(const StabilityCase& c, const std::string& id)
{
    std::string script = "$" + id + " << EOD\n";
    SymLog axis{1e-3};
    for (std::size_t i = 0; i < c.path.position.size(); ++i) {
        script += fmt::format("{:.8f}", c.path.position[i]);
        for (double w : c.path.omega2[i]) script += fmt::format(" {:.10g}", w), axis.add(w);
        script += "\n";
    }
    std::string tics;
    for (std::size_t i = 0; i < c.path.labels.size(); ++i)
        tics += fmt::format("{}'{}' {}", i ? ", " : "", c.path.labels[i], c.path.label_positions[i]);
    std::string plot;
    for (std::size_t b = 0; b < c.path.omega2.front().size(); ++b)
        plot += fmt::format("${} using 1:{} with lines lw 2 lc rgb '{}' title 'branch {}', ", id,
                            axis.using_column(static_cast<int>(b) + 2), branch_colours[b % 6], b + 1);
    return script + "EOD\n" + axis.tics() +
           fmt::format("set xtics ({})\nset xrange [0:{}]\nset title '{} (k = {:.4f})' noenhanced\n"
                       "plot {}0 with lines lc rgb 'black' dt 2 notitle\n",
                       tics, c.path.label_positions.back(), c.kernel_label, c.path_k, plot);
}

} // namespace

nlohmann::json StabilityResults::json(const Study&) const
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& c : cases) list.push_back(stability_json(c));
    return list;
}

std::string StabilityResults::markdown(const Study&) const
{
    if (cases.empty()) return {};
    std::string s = fmt::format(
        "## Linear stability\n\nThe lattice at rest is stable at k when no plane wave grows: omega^2 >= -1e-9 (c/d)^2 "
        "over the whole Brillouin zone and omega^2 / kappa^2 >= -1e-9 c^2 for long waves in every direction "
        "(standard SPH, summation density, {} h, P = rho c^2 / gamma with gamma = {:.6g}; {} section 10; "
        "with adaptive h, h = eta (m/rho)^(1/D) with the grad-h terms, and k is its value h = k d at rest). "
        "A mode that grows more slowly than the horizon ({:g} d/c: growth time 1 / sqrt(-omega^2)) is weak: such k are "
        "not in the stable k, but count as stable where they meet condition (22). "
        "Accurate: condition (22) holds (first automatic mode, each a_p). The stable k do not depend on a_p.\n\n",
        cases.front().h_model, cases.front().gamma, method_document(), cases.front().over_k.horizon);
    std::string lattice;
    for (const auto& c : cases) {
        if (c.lattice != lattice) {
            s += lattice.empty() ? "" : "\n";
            lattice = c.lattice;
            s += fmt::format("### {}\n\n| kernel | k scanned | stable k | accurate and stable (at the horizon) k | "
                             "dispersion curves at k |\n"
                             "|---|---|---|---|---|\n",
                             lattice);
        }
        if (c.refused) {
            s += fmt::format("| {} | | not available: {} | | |\n", c.kernel_label, *c.refused);
            continue;
        }
        std::string both;
        for (const auto& o : c.overlap)
            both += fmt::format("{}{}: {}", both.empty() ? "" : "; ", o.ap_name,
                                intervals_text(o.both, o.accurate.empty() ? "none (condition (22) fails)"
                                                                          : "none: every accurate k is unstable"));
        s += fmt::format("| {} | [{:.4f}, {:.4f}] | {} | {} | {:.4f} |\n", c.kernel_label, c.over_k.samples.front().k,
                         c.over_k.samples.back().k, intervals_text(c.over_k.stable, "none"), both, c.path_k);
    }
    return s + "\n" + recommended_markdown(cases);
}

// Stability: per lattice, a panel per kernel of min omega^2 against k, and one of the
// dispersion curves along the high-symmetry path.
void StabilityResults::draw(const Study&, Canvas& canvas) const
{
    std::vector<std::string> lattices;
    for (const auto& c : cases)
        if (!c.refused && std::find(lattices.begin(), lattices.end(), c.lattice) == lattices.end())
            lattices.push_back(c.lattice);
    int block = 0;
    for (const auto& lattice : lattices) {
        std::vector<const StabilityCase*> panels;
        for (const auto& c : cases)
            if (c.lattice == lattice && !c.refused) panels.push_back(&c);
        const auto [rows, columns] = layout(panels.size());
        std::string script = fmt::format(
            "set multiplot layout {},{} title '{}: the lowest squared frequency of each branch over the Brillouin "
            "zone against k (below zero: unstable); condition (22) at a_p = {}' noenhanced\n"
            "set grid\nset xlabel 'k = h / d'\nset ylabel 'min ω² [c²/d²] (symmetric log scale)'\n{}",
            rows, columns, lattice, panels.front()->overlap.empty() ? "-" : panels.front()->overlap.front().ap_name,
            key_setup);
        for (const auto* c : panels) script += stability_panel(*c, fmt::format("m{}", block++));
        canvas.draw(lattice + "-stability", panel_width * columns, panel_height * rows, script + "unset multiplot\n");
        script = fmt::format("set multiplot layout {},{} title '{}: squared frequency of each branch along the "
                             "high-symmetry path' noenhanced\nset grid xtics\nset xlabel 'wave vector along the path'\n"
                             "set ylabel 'ω² [c²/d²] (symmetric log scale)'\n{}",
                             rows, columns, lattice, key_setup);
        for (const auto* c : panels) script += dispersion_panel(*c, fmt::format("p{}", block++));
        canvas.draw(lattice + "-dispersion", panel_width * columns, panel_height * rows, script + "unset multiplot\n");
    }
}

} // namespace sphkern
