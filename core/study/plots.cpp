#include "study/plots.hpp"

#include "study/gnuplot.hpp"
#include "study/particles_outputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

// One datablock per curve; a blank line where a shell enters the support breaks the line at the jump.
std::string datablock(const std::string& name, const StudyCase& c, bool rho)
{
    std::string s = "$" + name + " << EOD\n";
    int previous = -1;
    for (const auto& [k, v] : c.curve) {
        double y = rho ? v.eps_rho : v.eps_gradp;
        if (previous >= 0 && v.neighbours != previous) s += "\n";
        previous = v.neighbours;
        s += std::isfinite(y) ? fmt::format("{:.8f} {:.10g}\n", k, y) : fmt::format("{:.8f} NaN\n", k);
    }
    return s + "EOD\n";
}

std::vector<std::string> draw_bulk_figures(const Study& study, const StudyResults& results, const fs::path& folder, const fs::path& gnuplot)
{
    std::vector<std::string> written;
    // Group the cases by figure (lattice, mode), then by panel (kernel).
    std::map<std::pair<std::string, std::string>, std::vector<const StudyCase*>> figures;
    std::vector<std::pair<std::string, std::string>> order;
    for (const auto& c : results.cases) {
        auto key = std::make_pair(c.lattice, c.mode);
        if (!figures.count(key)) order.push_back(key);
        figures[key].push_back(&c);
    }
    for (const auto& key : order) {
        const auto& cases = figures[key];
        std::vector<std::string> kernels;
        for (const auto* c : cases)
            if (std::find(kernels.begin(), kernels.end(), c->kernel_label) == kernels.end())
                kernels.push_back(c->kernel_label);
        int columns = std::min<int>(3, static_cast<int>(kernels.size()));
        int rows = (static_cast<int>(kernels.size()) + columns - 1) / columns;
        std::string name = key.first + "-" + key.second;
        double x_min = INFINITY, x_max = -INFINITY; // the windows of the figure's cases, in k
        for (const auto* c : cases) {
            x_min = std::min(x_min, c->k_min);
            x_max = std::max(x_max, c->k_max);
        }
        std::string script = fmt::format(
            "set encoding utf8\nset terminal svg size {},{} dynamic enhanced font 'sans,11' background '#ffffff'\n"
            "set output '{}'\nset multiplot layout {},{} title '{} on {}, mode {}: ε_ρ solid, "
            "ε_{{∇P}} dashed'\n"
            "set grid\nset xrange [{}:{}]\nset yrange [-0.1:0.1]\nset xlabel 'k'\nset key bottom right font ',9'\n",
            420 * columns, 340 * rows, name + ".svg", rows, columns,
            study.name, key.first, key.second, x_min, x_max);
        int block = 0;
        for (const auto& kernel : kernels) {
            std::string plot = fmt::format("set title '{}' noenhanced\nplot {} with filledcurves y1=-{} lc rgb '#e8e8e8' notitle",
                                           kernel, study.epsilon, study.epsilon);
            int colour = 0;
            for (const auto* c : cases) {
                if (c->kernel_label != kernel) continue;
                std::string rho = fmt::format("rho{}", block), gradp = fmt::format("gradp{}", block++);
                script += datablock(rho, *c, true) + datablock(gradp, *c, false);
                const char* rgb = colours[colour++ % 6];
                plot += fmt::format(", ${} using 1:2 with lines lw 2 dt 1 lc rgb '{}' title 'a_p = {} (rho)' noenhanced"
                                    ", ${} using 1:2 with lines lw 2 dt 2 lc rgb '{}' title 'a_p = {} (gradP)' noenhanced",
                                    rho, rgb, c->ap_name, gradp, rgb, c->ap_name);
            }
            script += plot + "\nunset key\n"; // the legend of the first panel serves all
        }
        script += "unset multiplot\n";
        run_gnuplot(folder, name, script, gnuplot);
        written.push_back(folder.filename().string() + "/" + name + ".svg");
    }
    return written;
}

std::vector<std::string> draw_surface_figures(const StudyResults& results, const fs::path& folder, const fs::path& gnuplot)
{
    std::vector<std::string> written;
    // Free-surface profiles: a figure per lattice, a panel per kernel, a curve per form.
    std::vector<std::string> surface_lattices;
    for (const auto& c : results.surface)
        if (std::find(surface_lattices.begin(), surface_lattices.end(), c.lattice) == surface_lattices.end())
            surface_lattices.push_back(c.lattice);
    for (const auto& lattice : surface_lattices) {
        std::vector<std::string> kernels;
        for (const auto& c : results.surface)
            if (c.lattice == lattice && std::find(kernels.begin(), kernels.end(), c.kernel_label) == kernels.end())
                kernels.push_back(c.kernel_label);
        int columns = std::min<int>(3, static_cast<int>(kernels.size()));
        int rows = (static_cast<int>(kernels.size()) + columns - 1) / columns;
        std::string name = lattice + "-surface";
        std::string script = fmt::format(
            "set encoding utf8\nset terminal svg size {},{} dynamic enhanced font 'sans,11' background '#ffffff'\n"
            "set output '{}.svg'\nset multiplot layout {},{} title '{}: free-surface profiles, ε_ρ solid, ε_{{∇P}} dashed'\n"
            "set grid\nset xtics 1\nset xlabel 'layer n (0 = top)'\nset key bottom right font ',9'\nset yrange [-1:0.5]\n",
            420 * columns, 340 * rows, name, rows, columns, lattice);
        int block = 0;
        for (const auto& kernel : kernels) {
            std::string plot;
            int colour = 0;
            for (const auto& c : results.surface) {
                if (c.lattice != lattice || c.kernel_label != kernel) continue;
                std::string id = fmt::format("s{}", block++);
                script += "$" + id + " << EOD\n";
                for (const auto& l : c.profile.layers) script += fmt::format("{} {:.10g} {:.10g}\n", l.n, l.eps_rho, l.eps_gradp);
                script += "EOD\n";
                const char* rgb = colours[colour++ % 6];
                plot += fmt::format("{}${} using 1:2 with linespoints lw 2 dt 1 lc rgb '{}' title '{} (rho)' noenhanced, "
                                    "${} using 1:3 with linespoints lw 2 dt 2 lc rgb '{}' title '{} (gradP)' noenhanced",
                                    plot.empty() ? "" : ", ", id, rgb, c.form, id, rgb, c.form);
            }
            script += fmt::format("set title '{} (k = {:.4f})' noenhanced\nplot {}\nunset key\n", kernel,
                                  [&] {
                                      for (const auto& c : results.surface)
                                          if (c.lattice == lattice && c.kernel_label == kernel) return c.k;
                                      return 0.0;
                                  }(),
                                  plot);
        }
        script += "unset multiplot\n";
        run_gnuplot(folder, name, script, gnuplot);
        written.push_back(folder.filename().string() + "/" + name + ".svg");
    }
    return written;
}

std::vector<std::string> draw_sweep_figures(const StudyResults& results, const fs::path& folder, const fs::path& gnuplot)
{
    std::vector<std::string> written;
    // Parameter sweeps: heat maps of both errors over (k, parameter) with both zero contours.
    for (const auto& c : results.sweeps) {
        std::string name = c.lattice + "-" + c.kernel + "-" + c.parameter + "-map";
        std::string grid_rho = "$rho << EOD\n", grid_gradp = "$gradp << EOD\n";
        for (std::size_t i = 0; i < c.values.size(); ++i) {
            for (std::size_t j = 0; j < c.ks.size(); ++j) {
                grid_rho += fmt::format("{:.8f} {:.10g} {:.10g}\n", c.ks[j], c.values[i], c.rho[i][j]);
                grid_gradp += fmt::format("{:.8f} {:.10g} {:.10g}\n", c.ks[j], c.values[i], c.gradp[i][j]);
            }
            grid_rho += "\n";
            grid_gradp += "\n";
        }
        std::string script = fmt::format(
            "set encoding utf8\nset terminal svg size 1200,520 dynamic enhanced font 'sans,11' background '#ffffff'\n"
            "set output '{}.svg'\n{}EOD\n{}EOD\n"
            // The zero contours of both errors, as lines to draw over each map.
            "set contour base\nset cntrparam levels discrete 0\nunset surface\nset table $rho0\nsplot $rho\n"
            "unset table\nset table $gradp0\nsplot $gradp\nunset table\nunset contour\nset surface\n"
            "set multiplot layout 1,2 title '{} on {} (a_p = {}): black ε_ρ = 0, white ε_{{∇P}} = 0' noenhanced\n"
            "set view map\nset xlabel 'k'\nset ylabel '{}' noenhanced\nset cbrange [-0.05:0.05]\n"
            "set palette defined (-0.05 '#2166ac', 0 '#f7f7f7', 0.05 '#b2182b')\nunset key\n"
            "set xrange [{}:{}]\nset yrange [{}:{}]\n"
            "set title 'ε_ρ'\nplot $rho using 1:2:3 with image, $rho0 using 1:2 with lines lw 2 lc rgb 'black', "
            "$gradp0 using 1:2 with lines lw 2 lc rgb 'white'\n"
            "set title 'ε_{{∇P}}'\nplot $gradp using 1:2:3 with image, $rho0 using 1:2 with lines lw 2 lc rgb 'black', "
            "$gradp0 using 1:2 with lines lw 2 lc rgb 'white'\nunset multiplot\n",
            name, grid_rho, grid_gradp, c.kernel, c.lattice, c.ap_name, c.parameter, c.ks.front(), c.ks.back(),
            c.values.front(), c.values.back());
        run_gnuplot(folder, name, script, gnuplot);
        written.push_back(folder.filename().string() + "/" + name + ".svg");
    }
    return written;
}

// Stability: per lattice, a panel per kernel of min omega^2 against k, and one of the
// dispersion curves along the high-symmetry path.
std::vector<std::string> draw_stability_figures(const StudyResults& results, const fs::path& folder,
                                                const fs::path& gnuplot)
{
    std::vector<std::string> written, lattices;
    for (const auto& c : results.stability)
        if (c.refused.empty() && std::find(lattices.begin(), lattices.end(), c.lattice) == lattices.end())
            lattices.push_back(c.lattice);
    for (const auto& lattice : lattices) {
        std::vector<const StabilityCase*> cases;
        for (const auto& c : results.stability)
            if (c.lattice == lattice && c.refused.empty()) cases.push_back(&c);
        const int columns = std::min<int>(3, static_cast<int>(cases.size()));
        const int rows = (static_cast<int>(cases.size()) + columns - 1) / columns;
        const std::string head = fmt::format(
            "set encoding utf8\nset terminal svg size {},{} dynamic enhanced font 'sans,11' background '#ffffff'\n",
            420 * columns, 340 * rows);
        // min omega^2 against k.
        std::string name = lattice + "-stability", script = head;
        script += fmt::format("set output '{}.svg'\nset multiplot layout {},{} title '{}: min ω² of each branch "
                              "over the Brillouin zone (c²/d²); green: condition (22) at a_p = {}, blue: stable'\n"
                              "set grid\nset xlabel 'k'\nunset key\nset yrange [*<-0.001:0.001<*]\n",
                              name, rows, columns, lattice,
                              cases.front()->overlap.empty() ? "-" : cases.front()->overlap.front().ap_name);
        int block = 0;
        for (const auto* c : cases) {
            const std::string id = fmt::format("m{}", block++);
            script += "$" + id + " << EOD\n";
            for (const auto& s : c->over_k.samples) {
                script += fmt::format("{:.8f}", s.k);
                for (double w : s.branch_minima) script += fmt::format(" {:.10g}", w);
                script += "\n";
            }
            script += "EOD\nunset object\n";
            int object = 1;
            for (const auto& o : c->overlap)
                if (&o == &c->overlap.front())
                    for (const auto& i : o.accurate)
                        script += fmt::format("set object {} rect from {},graph 0 to {},graph 1 fc rgb '#d9f0d3' "
                                              "fs solid noborder behind\n", object++, i.from, i.to);
            for (const auto& i : c->over_k.stable)
                script += fmt::format("set object {} rect from {},graph 0 to {},graph 0.04 fc rgb '#4575b4' "
                                      "fs solid noborder front\n", object++, i.from, i.to);
            std::string plot;
            const std::size_t branches = c->over_k.samples.front().branch_minima.size();
            for (std::size_t b = 0; b < branches; ++b)
                plot += fmt::format("{}${} using 1:{} with lines lw 2 lc rgb '{}'", b ? ", " : "", id, b + 2,
                                    colours[b % 6]);
            script += fmt::format("set title '{}' noenhanced\nplot {}\n", c->kernel_label, plot);
        }
        script += "unset multiplot\n";
        run_gnuplot(folder, name, script, gnuplot);
        written.push_back(folder.filename().string() + "/" + name + ".svg");
        // Dispersion curves.
        name = lattice + "-dispersion";
        script = head + fmt::format("set output '{}.svg'\nset multiplot layout {},{} title '{}: ω² along the "
                                    "high-symmetry path (c²/d²)'\nset grid xtics\nunset key\n",
                                    name, rows, columns, lattice);
        for (const auto* c : cases) {
            const std::string id = fmt::format("p{}", block++);
            script += "$" + id + " << EOD\n";
            for (std::size_t i = 0; i < c->path.position.size(); ++i) {
                script += fmt::format("{:.8f}", c->path.position[i]);
                for (double w : c->path.omega2[i]) script += fmt::format(" {:.10g}", w);
                script += "\n";
            }
            std::string tics;
            for (std::size_t i = 0; i < c->path.labels.size(); ++i)
                tics += fmt::format("{}'{}' {}", i ? ", " : "", c->path.labels[i], c->path.label_positions[i]);
            std::string plot;
            const std::size_t branches = c->path.omega2.front().size();
            for (std::size_t b = 0; b < branches; ++b)
                plot += fmt::format("{}${} using 1:{} with lines lw 2 lc rgb '{}'", b ? ", " : "", id, b + 2,
                                    colours[b % 6]);
            script += fmt::format("EOD\nset xtics ({})\nset xrange [0:{}]\nset title '{} (k = {:.4f})' noenhanced\n"
                                  "set yrange [*<-0.001:0.001<*]\nplot {}, 0 with lines lc rgb 'black' dt 2\n",
                                  tics, c->path.label_positions.back(), c->kernel_label, c->path_k, plot);
        }
        script += "unset multiplot\n";
        run_gnuplot(folder, name, script, gnuplot);
        written.push_back(folder.filename().string() + "/" + name + ".svg");
    }
    return written;
}

} // namespace

std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results, const fs::path& folder,
                                          const fs::path& gnuplot)
{
    fs::create_directories(folder);
    std::vector<std::string> written;
    for (auto part : {draw_bulk_figures(study, results, folder, gnuplot), draw_surface_figures(results, folder, gnuplot),
                      draw_sweep_figures(results, folder, gnuplot), draw_stability_figures(results, folder, gnuplot),
                      draw_particles_figures(results, folder, gnuplot)})
        written.insert(written.end(), part.begin(), part.end());
    return written;
}

} // namespace sphkern
