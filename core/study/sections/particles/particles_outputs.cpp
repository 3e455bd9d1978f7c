#include "study/sections/particles/particles_section.hpp"

#include "study/canvas.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace sphkern {

namespace {

// The sources in the order of the study, each with its cases.
std::vector<std::pair<std::string, std::vector<const ParticlesCase*>>> by_source(const std::vector<ParticlesCase>& cases)
{
    std::vector<std::pair<std::string, std::vector<const ParticlesCase*>>> groups;
    for (const auto& c : cases) {
        if (groups.empty() || groups.back().first != c.source) groups.push_back({c.source, {}});
        groups.back().second.push_back(&c);
    }
    return groups;
}

std::string file_name(const std::string& label)
{
    std::string name = "particles-";
    for (char c : label) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.';
        if (keep) name += c;
        else if (name.back() != '-') name += '-';
    }
    while (name.back() == '-') name.pop_back();
    return name;
}

} // namespace

std::string ParticlesResults::markdown(const Study&) const
{
    if (cases.empty()) return {};
    std::string s =
        "## Particle sets\n\nThe consistency errors of each kernel on particles that are no lattice (method document, "
        "section 11): e0 = sum_j V_j W_ij - 1, eps_gradp = g.E.g (the difference form) and eps_gradp_sum, the paper's "
        "sum form one h below the surface, as RMS over the set, against the neighbour number "
        "N_H = c_D (R h)^D / V (Dehnen & Aly 2012).\n\n";
    for (const auto& [source, group] : by_source(cases)) {
        s += fmt::format("### {} ({} particles, {}D, volumes {})\n\n{}| kernel | N_H | h/l | neighbours | mean e0 | RMS e0 | "
                         "RMS e0 of a Poisson set | RMS eps_gradp | RMS eps_gradp_sum | RMS abs(e1) |\n|---|---|---|---|---|---|---|---|---|---|\n",
                         source, group.front()->particles, group.front()->dimension, volume_model_name(group.front()->volume),
                         group.front()->code.empty() ? "" : "At " + group.front()->code + ".\n\n");
        for (const auto* c : group)
            for (std::size_t j = 0; j < c->points.size(); ++j) {
                const auto& p = c->points[j];
                s += fmt::format("| {} | {:.1f} | {:.4f} | {:.2f} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |\n",
                                 c->kernel_label, p.nh, p.eta, p.mean_neighbours, p.statistic("e0").mean,
                                 p.statistic("e0").rms, c->poisson_rms_e0[j], p.statistic("eps_gradp").rms,
                                 p.statistic("eps_gradp_sum").rms, p.statistic("|e1|").rms);
            }
        s += "\n";
    }
    return s;
}

void ParticlesResults::draw(const Study&, Canvas& canvas) const
{
    static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
    for (const auto& [source, group] : by_source(cases)) {
        std::string data, e0_plot, gradp_plot;
        for (std::size_t i = 0; i < group.size(); ++i) {
            data += fmt::format("$c{} << EOD\n", i);
            for (std::size_t j = 0; j < group[i]->points.size(); ++j) {
                const auto& p = group[i]->points[j];
                data += fmt::format("{:.10g} {:.10g} {:.10g} {:.10g}\n", p.nh, p.statistic("e0").rms,
                                    p.statistic("eps_gradp").rms, group[i]->poisson_rms_e0[j]);
            }
            data += "EOD\n";
            const char* colour = colours[i % 8];
            const std::string style = fmt::format("with linespoints lw 2 pt 7 ps 0.5 lc rgb '{}' title '{}'", colour,
                                                  group[i]->kernel_label);
            e0_plot += fmt::format("{}$c{} using 1:2 {}, $c{} using 1:4 with lines dt 2 lw 1 lc rgb '{}' notitle", i ? ", " : "",
                                   i, style, i, colour);
            gradp_plot += fmt::format("{}$c{} using 1:3 {}", i ? ", " : "", i, style);
        }
        double lo = INFINITY, hi = 0;
        for (const auto* c : group)
            for (const auto& p : c->points) lo = std::min(lo, p.nh), hi = std::max(hi, p.nh);
        const std::string body = fmt::format(
            "{}set multiplot layout 1,2 title 'Consistency errors on {}, against the neighbour number' noenhanced\n"
            "set logscale xy\nset grid\nset xrange [{:.6g}:{:.6g}]\nset xlabel 'neighbour number N_H (dimensionless)'\n"
            "set key outside right top noenhanced\n"
            "set title 'density of a constant field (dashed: a Poisson set of as many particles)'\n"
            "set ylabel 'RMS of e0 (relative)'\nplot {}\n"
            "set title 'hydrostatic pressure gradient'\nset ylabel 'RMS of eps_gradp (relative)' noenhanced\nplot {}\n"
            "unset multiplot\n",
            data, source, lo / 1.1, hi * 1.1, e0_plot, gradp_plot);
        canvas.draw(file_name(source), 1400, 560, body);
    }
}

nlohmann::json ParticlesResults::json(const Study&) const
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& c : cases) {
        nlohmann::json points = nlohmann::json::array();
        for (std::size_t j = 0; j < c.points.size(); ++j) {
            const auto& p = c.points[j];
            nlohmann::json statistics = nlohmann::json::object();
            for (const auto& [key, s] : p.statistics)
                statistics[key] = {{"mean", s.mean}, {"std", s.std}, {"rms", s.rms}, {"min", s.min},
                                   {"max", s.max},   {"p1", s.p1},   {"p50", s.p50}, {"p99", s.p99}};
            points.push_back({{"nh", p.nh}, {"h_over_l", p.eta}, {"mean_neighbours", p.mean_neighbours},
                              {"poisson_rms_e0", c.poisson_rms_e0[j]}, {"statistics", statistics}});
        }
        list.push_back({{"source", c.source}, {"kernel", c.kernel_label}, {"dimension", c.dimension},
                        {"particles", c.particles}, {"volume", volume_model_name(c.volume)}, {"points", points}});
        if (!c.code.empty()) list.back()["code"] = c.code;
    }
    return list;
}

} // namespace sphkern
