#include "study/sections/particles/particles_section.hpp"

#include "study/canvas.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

namespace sphkern {

namespace {

// The sources in the order of the study, each with its cases.
std::vector<std::pair<std::string, std::vector<const ParticlesCase*>>> by_source(
    const std::vector<ParticlesCase>& cases)
{
    std::vector<std::pair<std::string, std::vector<const ParticlesCase*>>> groups;
    for (const auto& c : cases) {
        if (groups.empty() || groups.back().first != c.source) groups.push_back({c.source, {}});
        groups.back().second.push_back(&c);
    }
    return groups;
}

// A figure's name from its source's: a file by its own name without its folders and particle
// extension ("../files/dam-break-2d-0.hdf5" is particles-dam-break-2d-0), each once (-2, -3, ...
// where two sources would share one).
std::string file_name(const std::string& label, std::set<std::string>& taken)
{
    std::string base = label.substr(label.find_last_of('/') == std::string::npos ? 0 : label.find_last_of('/') + 1);
    for (const char* ext : {".hdf5", ".h5", ".csv", ".vtk"})
        if (base.size() > std::strlen(ext) && base.ends_with(ext)) base.resize(base.size() - std::strlen(ext));
    std::string name = "particles-";
    for (char c : base) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.';
        if (keep) name += c;
        else if (name.back() != '-') name += '-';
    }
    while (name.back() == '-') name.pop_back();
    std::string unique = name;
    for (int k = 2; !taken.insert(unique).second; ++k) unique = fmt::format("{}-{}", name, k);
    return unique;
}

// gnuplot labels a logarithmic axis at its decades only: a sweep within two decades is labelled
// at its own values instead.
std::string neighbour_tics(const std::vector<const ParticlesCase*>& group, double lo, double hi)
{
    if (!(hi < 100 * lo)) return {};
    std::set<double> values;
    for (const auto* c : group)
        for (const auto& p : c->points) values.insert(std::stod(fmt::format("{:.3g}", p.nh)));
    std::string tics;
    for (double v : values) tics += fmt::format("{}'{:g}' {:.10g}", tics.empty() ? "" : ", ", v, v);
    return "set xtics (" + tics + ")\n";
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
        s += fmt::format(
            "### {} ({} particles, {}D, volumes {})\n\n{}| kernel | N_H | h/l | neighbours | mean e0 | RMS e0 | "
            "RMS e0 of a Poisson set | RMS eps_gradp | RMS eps_gradp_sum | RMS abs(e1) "
            "|\n|---|---|---|---|---|---|---|---|---|---|\n",
            source, group.front()->particles, group.front()->dimension, volume_model_name(group.front()->volume),
            group.front()->code.empty() ? "" : "At " + group.front()->code + ".\n\n");
        for (const auto* c : group)
            for (std::size_t j = 0; j < c->points.size(); ++j) {
                const auto& p = c->points[j];
                s += fmt::format(
                    "| {} | {:.1f} | {:.4f} | {:.2f} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |\n",
                    c->kernel_label, p.nh, p.eta, p.mean_neighbours, p.statistic("e0").mean, p.statistic("e0").rms,
                    c->poisson_rms_e0[j], p.statistic("eps_gradp").rms, p.statistic("eps_gradp_sum").rms,
                    p.statistic("|e1|").rms);
            }
        s += "\n";
    }
    return s;
}

void ParticlesResults::draw(const Study&, Canvas& canvas) const
{
    static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                    "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
    std::set<std::string> taken;
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
            const std::string style =
                fmt::format("with linespoints lw 2 pt 7 ps 0.5 lc rgb '{}' title '{}'", colour, group[i]->kernel_label);
            e0_plot += fmt::format("{}$c{} using 1:2 {}, $c{} using 1:4 with lines dt 2 lw 1 lc rgb '{}' notitle",
                                   i ? ", " : "", i, style, i, colour);
            gradp_plot += fmt::format("{}$c{} using 1:3 {}", i ? ", " : "", i, style);
        }
        double lo = INFINITY, hi = 0;
        for (const auto* c : group)
            for (const auto& p : c->points) lo = std::min(lo, p.nh), hi = std::max(hi, p.nh);
        const std::string body = fmt::format(
            "{}set multiplot layout 1,2 title 'Consistency errors on {}, against the neighbour number' noenhanced\n"
            "set logscale xy\nset grid\nset xrange [{:.6g}:{:.6g}]\n{}set xlabel 'neighbour number N_H "
            "(dimensionless)'\n"
            "set key outside right top noenhanced\n"
            "set title 'density of a constant field (dashed: a Poisson set of as many particles)'\n"
            "set ylabel 'RMS of e0 (relative)'\nplot {}\n"
            "unset key\n" // one legend for the figure: the kernels are the same in both panels
            "set title 'hydrostatic pressure gradient'\nset ylabel 'RMS of eps_gradp (relative)' noenhanced\nplot {}\n"
            "unset multiplot\n",
            data, source, lo / 1.1, hi * 1.1, neighbour_tics(group, lo, hi), e0_plot, gradp_plot);
        canvas.draw(file_name(source, taken), 1400, 560, body);
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
            points.push_back({{"nh", p.nh},
                              {"h_over_l", p.eta},
                              {"mean_neighbours", p.mean_neighbours},
                              {"poisson_rms_e0", c.poisson_rms_e0[j]},
                              {"statistics", statistics}});
        }
        list.push_back({{"source", c.source},
                        {"kernel", c.kernel_label},
                        {"dimension", c.dimension},
                        {"particles", c.particles},
                        {"volume", volume_model_name(c.volume)},
                        {"points", points}});
        if (!c.code.empty()) list.back()["code"] = c.code;
    }
    return list;
}

} // namespace sphkern
