#include "study/plots.hpp"

#include "support/error.hpp"
#include "support/child_process.hpp"
#include "support/interruption.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

fs::path find_gnuplot()
{
    const char* path = std::getenv("PATH");
    std::stringstream list(path ? path : "/usr/bin:/bin");
    std::string folder;
    std::error_code ec;
    while (std::getline(list, folder, ':')) {
        fs::path candidate = fs::path(folder) / "gnuplot";
        // Absolute folders only: gnuplot runs from the staging folder, where "." means something else.
        if (fs::path(folder).is_absolute() && fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return {};
}

namespace {

constexpr double gnuplot_timeout_seconds = 120;

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

// Keeps the script beside the figure and runs gnuplot inside the folder (no shell: an
// argument vector), so that the script names its output relatively.
void run_gnuplot(const fs::path& folder, const std::string& name, const std::string& script, const fs::path& gnuplot)
{
    throw_if_interrupted();
    fs::path script_file = folder / (name + ".gp");
    {
        std::ofstream out(script_file);
        out << script;
        if (!out) throw Error(ExitCode::output, script_file.string() + ": cannot write (disk full?)");
    }
    auto run = run_program({gnuplot.string(), name + ".gp"}, folder, gnuplot_timeout_seconds);
    if (run.timed_out)
        throw Error(ExitCode::output, fmt::format("gnuplot did not finish {} within {} s", script_file.string(),
                                                  gnuplot_timeout_seconds));
    if (run.exit_status != 0) {
        std::string reason = run.signal ? fmt::format("killed by signal {}", run.signal)
                                        : run.output.substr(0, run.output.find('\n'));
        throw Error(ExitCode::output, "gnuplot failed on " + script_file.string() + ": " + reason);
    }
}

} // namespace

std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results, const fs::path& folder,
                                          const fs::path& gnuplot)
{
    fs::create_directories(folder);
    // Group the cases by figure (lattice, mode), then by panel (kernel).
    std::map<std::pair<std::string, std::string>, std::vector<const StudyCase*>> figures;
    std::vector<std::pair<std::string, std::string>> order;
    for (const auto& c : results.cases) {
        auto key = std::make_pair(c.lattice, c.mode);
        if (!figures.count(key)) order.push_back(key);
        figures[key].push_back(&c);
    }
    std::vector<std::string> written;
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

} // namespace sphkern
