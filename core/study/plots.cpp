#include "study/plots.hpp"

#include "study/canvas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

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

// Errors against k: a figure per lattice and mode, a panel per kernel, a curve per a_p.
void draw_bulk_figures(const Study& study, const StudyResults& results, Canvas& canvas)
{
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
        const auto [rows, columns] = layout(kernels.size());
        double x_min = INFINITY, x_max = -INFINITY; // the windows of the figure's cases, in k
        for (const auto* c : cases) x_min = std::min(x_min, c->k_min), x_max = std::max(x_max, c->k_max);
        std::string script = fmt::format(
            "set multiplot layout {},{} title '{} on {}, mode {}: relative errors against k; density solid, pressure "
            "gradient dashed; grey band: |error| <= {:g}' noenhanced\n"
            "set grid\nset xrange [{}:{}]\nset xlabel 'k = h / d'\n"
            "set ylabel 'relative error (symmetric log scale)'\n{}",
            rows, columns, study.name, key.first, key.second, study.epsilon, x_min, x_max, key_setup);
        int block = 0;
        for (const auto& kernel : kernels) {
            SymLog axis{study.epsilon / 10};
            axis.add(study.epsilon), axis.add(-study.epsilon); // the band is always in view
            for (const auto* c : cases)
                if (c->kernel_label == kernel)
                    for (const auto& point : c->curve) axis.add(point.second.eps_rho), axis.add(point.second.eps_gradp);
            std::string plot =
                fmt::format("plot {0} with filledcurves y1=-{0} lc rgb '#e8e8e8' notitle", std::asinh(10.0));
            int colour = 0;
            for (const auto* c : cases) {
                if (c->kernel_label != kernel) continue;
                std::string rho = fmt::format("rho{}", block), gradp = fmt::format("gradp{}", block++);
                script += datablock(rho, *c, true) + datablock(gradp, *c, false);
                const char* rgb = curve_colours[colour++ % 6];
                plot += fmt::format(", ${} using 1:{} with lines lw 2 dt 1 lc rgb '{}' title 'density, a_p = {}'"
                                    ", ${} using 1:{} with lines lw 2 dt 2 lc rgb '{}' title 'gradient, a_p = {}'",
                                    rho, axis.using_column(2), rgb, c->ap_name, gradp, axis.using_column(2), rgb,
                                    c->ap_name);
            }
            script += axis.tics() + fmt::format("set title '{}' noenhanced\n", kernel) + plot + "\n";
        }
        script += "unset multiplot\n";
        canvas.draw(key.first + "-" + key.second, panel_width * columns, panel_height * rows, script);
    }
}

} // namespace

std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results, const fs::path& folder,
                                          const fs::path& gnuplot, const std::vector<std::string>& formats)
{
    fs::create_directories(folder);
    Canvas canvas{folder, formats, gnuplot, {}};
    draw_bulk_figures(study, results, canvas);
    for (const auto& section : results.sections)
        if (section) section->draw(study, canvas);
    return canvas.written;
}

} // namespace sphkern
