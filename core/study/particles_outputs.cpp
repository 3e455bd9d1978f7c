#include "study/particles_outputs.hpp"

#include "study/gnuplot.hpp"

#include <fmt/format.h>

#include <map>

namespace sphkern {

namespace {

const Summary& statistic(const ParticlePoint& p, const std::string& name)
{
    for (const auto& [key, s] : p.statistics)
        if (key == name) return s;
    throw std::logic_error("no statistic " + name);
}

// The sources in the order of the study, each with its cases.
std::vector<std::pair<std::string, std::vector<const ParticlesCase*>>> by_source(const StudyResults& results)
{
    std::vector<std::pair<std::string, std::vector<const ParticlesCase*>>> groups;
    for (const auto& c : results.particles) {
        if (groups.empty() || groups.back().first != c.source) groups.push_back({c.source, {}});
        groups.back().second.push_back(&c);
    }
    return groups;
}

std::string file_name(const std::string& label)
{
    std::string name = "particles";
    for (char c : label) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.';
        if (keep) name += c;
        else if (name.back() != '-') name += '-';
    }
    while (name.back() == '-') name.pop_back();
    return name;
}

} // namespace

std::string particles_markdown(const StudyResults& results)
{
    if (results.particles.empty()) return {};
    std::string s =
        "## Particle sets\n\nThe consistency errors of each kernel on particles that are no lattice (method document, "
        "section 11): e0 = sum_j V_j W_ij - 1, eps_gradp = g.E.g (the difference form) and eps_gradp_sum, the paper's "
        "sum form one h below the surface, as RMS over the set, against the neighbour number "
        "N_H = c_D (R h)^D / V (Dehnen & Aly 2012).\n\n";
    for (const auto& [source, cases] : by_source(results)) {
        s += fmt::format("### {} ({} particles, {}D, volumes {})\n\n| kernel | N_H | eta | neighbours | mean e0 | RMS e0 | "
                         "RMS eps_gradp | RMS eps_gradp_sum | RMS abs(e1) |\n|---|---|---|---|---|---|---|---|---|\n",
                         source, cases.front()->particles, cases.front()->dimension, volume_model_name(cases.front()->volume));
        for (const auto* c : cases)
            for (const auto& p : c->points)
                s += fmt::format("| {} | {:.1f} | {:.4f} | {:.2f} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |\n",
                                 c->kernel_label, p.nh, p.eta, p.mean_neighbours, statistic(p, "e0").mean,
                                 statistic(p, "e0").rms, statistic(p, "eps_gradp").rms, statistic(p, "eps_gradp_sum").rms,
                                 statistic(p, "|e1|").rms);
        s += "\n";
    }
    return s;
}

std::vector<std::string> draw_particles_figures(const StudyResults& results, const std::filesystem::path& folder,
                                                const std::filesystem::path& gnuplot)
{
    static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
    std::vector<std::string> written;
    for (const auto& [source, cases] : by_source(results)) {
        const std::string name = file_name(source);
        std::string data, e0_plot, gradp_plot;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            data += fmt::format("$c{} << EOD\n", i);
            for (const auto& p : cases[i]->points)
                data += fmt::format("{:.10g} {:.10g} {:.10g}\n", p.nh, statistic(p, "e0").rms, statistic(p, "eps_gradp").rms);
            data += "EOD\n";
            const char* colour = colours[i % 8];
            e0_plot += fmt::format("{}$c{} using 1:2 with linespoints lw 2 pt 7 ps 0.5 lc rgb '{}' title '{}'", i ? ", " : "",
                                   i, colour, cases[i]->kernel_label);
            gradp_plot += fmt::format("{}$c{} using 1:3 with linespoints lw 2 pt 7 ps 0.5 lc rgb '{}' title '{}'",
                                      i ? ", " : "", i, colour, cases[i]->kernel_label);
        }
        const std::string script = fmt::format(
            "set encoding utf8\nset terminal svg size 1200,520 dynamic enhanced font 'sans,11' background '#ffffff'\n"
            "set output '{}.svg'\n{}"
            "set multiplot layout 1,2 title '{}' noenhanced\nset logscale xy\nset grid\nset xlabel 'N_H'\n"
            "set key outside right top noenhanced\n"
            "set ylabel 'RMS e0'\nplot {}\nset ylabel 'RMS eps_gradp' noenhanced\nplot {}\nunset multiplot\n",
            name, data, source, e0_plot, gradp_plot);
        run_gnuplot(folder, name, script, gnuplot);
        written.push_back(folder.filename().string() + "/" + name + ".svg");
    }
    return written;
}

nlohmann::json particles_results_json(const StudyResults& results)
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& c : results.particles) {
        nlohmann::json points = nlohmann::json::array();
        for (const auto& p : c.points) {
            nlohmann::json statistics = nlohmann::json::object();
            for (const auto& [key, s] : p.statistics)
                statistics[key] = {{"mean", s.mean}, {"std", s.std}, {"rms", s.rms}, {"min", s.min},
                                   {"max", s.max},   {"p1", s.p1},   {"p50", s.p50}, {"p99", s.p99}};
            points.push_back({{"nh", p.nh}, {"eta", p.eta}, {"mean_neighbours", p.mean_neighbours}, {"statistics", statistics}});
        }
        list.push_back({{"source", c.source}, {"kernel", c.kernel_label}, {"dimension", c.dimension},
                        {"particles", c.particles}, {"volume", volume_model_name(c.volume)}, {"points", points}});
    }
    return list;
}

} // namespace sphkern
