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
// Branches in colours apart from the blue and red of the stable and unstable marks.
const char* branch_colours[] = {"#000000", "#ff7f0e", "#9467bd", "#8c564b", "#17becf", "#7f7f7f"};
const char* key_setup = "set key outside right top vertical Left reverse samplen 1.5 width -2 font ',8' noenhanced\n";
constexpr int panel_width = 520, panel_height = 380;

// Where the figures go and in which formats; `written` collects one file per figure for
// the report (the first of svg, png, pdf asked for).
struct Canvas {
    fs::path folder;
    std::vector<std::string> formats;
    fs::path gnuplot;
    std::vector<std::string> written;

    void draw(const std::string& name, int width, int height, const std::string& body)
    {
        render_figure(folder, name, width, height, body, formats, gnuplot);
        std::string shown = formats.front();
        for (const char* f : {"pdf", "png", "svg"})
            if (std::find(formats.begin(), formats.end(), f) != formats.end()) shown = f;
        written.push_back(folder.filename().string() + "/" + name + "." + shown);
    }
};

// A symmetric logarithmic axis: y is drawn at asinh(y / scale), linear within +-scale and
// logarithmic beyond, so that values near zero (which decide a verdict) and values far
// from it fit in one panel. The range reaches the data on each side (at least +-scale),
// with ticks at 0 and at each decade (every other one when there are many).
struct SymLog {
    double scale;
    double below = 0, above = 0; // the largest |y| of the negative and of the positive values

    void add(double y)
    {
        if (!std::isfinite(y)) return;
        if (y < 0) below = std::max(below, -y);
        else above = std::max(above, y);
    }
    std::string using_column(int column) const { return fmt::format("(asinh(${}/{:g}))", column, scale); }
    std::string decades(double largest, int sign) const
    {
        const int first = static_cast<int>(std::ceil(std::log10(scale) - 1e-9));
        const int last = std::max(first, static_cast<int>(std::ceil(std::log10(std::max(largest, scale)) - 1e-9)));
        const int stride = last - first >= 7 ? 2 : 1;
        std::string s;
        // The decade at the scale itself sits next to 0; left out when others follow.
        for (int j = last - first >= 2 ? first + 1 : first; j <= last; j += stride) {
            const double v = std::pow(10.0, j);
            s += fmt::format(", '{}{:g}' {:.6f}", sign < 0 ? "-" : "", v, sign * std::asinh(v / scale));
        }
        return s;
    }
    std::string tics() const
    {
        const double bottom = std::asinh(std::max(below, scale) / scale) * 1.05,
                     top = std::asinh(std::max(above, scale) / scale) * 1.05;
        return "set ytics ('0' 0" + decades(below, -1) + decades(above, 1) +
               fmt::format(")\nset yrange [{:.6f}:{:.6f}]\n", -bottom, top);
    }
};

// "rows,columns" of a multiplot of n panels, at most three across.
std::pair<int, int> layout(std::size_t n)
{
    const int columns = std::min<int>(3, static_cast<int>(n));
    return {(static_cast<int>(n) + columns - 1) / columns, columns};
}

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
            std::string plot = fmt::format("plot {0} with filledcurves y1=-{0} lc rgb '#e8e8e8' notitle",
                                           std::asinh(10.0));
            int colour = 0;
            for (const auto* c : cases) {
                if (c->kernel_label != kernel) continue;
                std::string rho = fmt::format("rho{}", block), gradp = fmt::format("gradp{}", block++);
                script += datablock(rho, *c, true) + datablock(gradp, *c, false);
                const char* rgb = colours[colour++ % 6];
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

// Free-surface profiles: a figure per lattice, a panel per kernel, a curve per form; the
// range follows the data.
void draw_surface_figures(const StudyResults& results, Canvas& canvas)
{
    std::vector<std::string> surface_lattices;
    for (const auto& c : results.surface)
        if (std::find(surface_lattices.begin(), surface_lattices.end(), c.lattice) == surface_lattices.end())
            surface_lattices.push_back(c.lattice);
    for (const auto& lattice : surface_lattices) {
        std::vector<std::string> kernels;
        for (const auto& c : results.surface)
            if (c.lattice == lattice && std::find(kernels.begin(), kernels.end(), c.kernel_label) == kernels.end())
                kernels.push_back(c.kernel_label);
        const auto [rows, columns] = layout(kernels.size());
        std::string script = fmt::format(
            "set multiplot layout {},{} title '{}: relative errors on each layer below a free surface; density solid, "
            "pressure gradient dashed' noenhanced\n"
            "set grid\nset xtics 1\nset xlabel 'layer n below the surface (0 = top)'\nset ylabel 'relative error'\n"
            "{}set autoscale y\n",
            rows, columns, lattice, key_setup);
        int block = 0;
        for (const auto& kernel : kernels) {
            std::string plot;
            int colour = 0;
            double k = 0;
            for (const auto& c : results.surface) {
                if (c.lattice != lattice || c.kernel_label != kernel) continue;
                k = c.k;
                std::string id = fmt::format("s{}", block++);
                script += "$" + id + " << EOD\n";
                for (const auto& l : c.profile.layers) script += fmt::format("{} {:.10g} {:.10g}\n", l.n, l.eps_rho, l.eps_gradp);
                script += "EOD\n";
                const char* rgb = colours[colour++ % 6];
                plot += fmt::format("{}${} using 1:2 with linespoints lw 2 dt 1 lc rgb '{}' title 'density, {} form', "
                                    "${} using 1:3 with linespoints lw 2 dt 2 lc rgb '{}' title 'gradient, {} form'",
                                    plot.empty() ? "" : ", ", id, rgb, c.form, id, rgb, c.form);
            }
            script += fmt::format("set title '{} (k = {:.4f})' noenhanced\nplot {}\n", kernel, k, plot);
        }
        script += "unset multiplot\n";
        canvas.draw(lattice + "-surface", panel_width * columns, panel_height * rows, script);
    }
}

// Parameter sweeps: maps of both errors over (k, parameter) with both zero contours. The
// ranges reach half a cell past the outer samples, so that the image stays in its frame.
void draw_sweep_figures(const StudyResults& results, Canvas& canvas)
{
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
        const double dk = c.ks.size() > 1 ? (c.ks.back() - c.ks.front()) / double(c.ks.size() - 1) / 2 : 0;
        const double dv = c.values.size() > 1 ? (c.values.back() - c.values.front()) / double(c.values.size() - 1) / 2 : 0;
        std::string script = fmt::format(
            "{}EOD\n{}EOD\n"
            // The zero contours of both errors, as lines to draw over each map.
            "set contour base\nset cntrparam levels discrete 0\nunset surface\nset table $rho0\nsplot $rho\n"
            "unset table\nset table $gradp0\nsplot $gradp\nunset table\nunset contour\nset surface\n"
            "set multiplot layout 1,2 title '{} on {} (a_p = {}): black line, density error = 0; white line, "
            "pressure-gradient error = 0' noenhanced\n"
            "set view map\nset xlabel 'k = h / d'\nset ylabel '{}' noenhanced\nset cbrange [-0.05:0.05]\n"
            "set cblabel 'relative error (colours saturate beyond ±0.05)'\n"
            "set palette defined (-0.05 '#2166ac', 0 '#f7f7f7', 0.05 '#b2182b')\nunset key\n"
            "set xrange [{}:{}]\nset yrange [{}:{}]\n"
            "set title 'density error'\nplot $rho using 1:2:3 with image, $rho0 using 1:2 with lines lw 2 lc rgb "
            "'black', $gradp0 using 1:2 with lines lw 2 lc rgb 'white'\n"
            "set title 'pressure-gradient error'\nplot $gradp using 1:2:3 with image, $rho0 using 1:2 with lines lw 2 "
            "lc rgb 'black', $gradp0 using 1:2 with lines lw 2 lc rgb 'white'\nunset multiplot\n",
            grid_rho, grid_gradp, c.kernel, c.lattice, c.ap_name, c.parameter, c.ks.front() - dk, c.ks.back() + dk,
            c.values.front() - dv, c.values.back() + dv);
        canvas.draw(name, 1300, 560, script);
    }
}

// Legend entries for the shaded bands and bars of the stability panels.
const char* stability_legend = "keyentry with boxes fs solid 1.0 noborder lc rgb '#d9f0d3' title 'condition (22) holds', "
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
                                  "behind\n", object++, i.from, i.to);
    for (const auto& i : c.over_k.stable)
        script += fmt::format("set object {} rect from {},graph 0 to {},graph 0.04 fc rgb '#4575b4' fs solid noborder "
                              "front\n", object++, i.from, i.to);
    const auto& samples = c.over_k.samples;
    const double half = samples.size() > 1 ? (samples.back().k - samples.front().k) / double(samples.size() - 1) / 2 : 0.005;
    for (const auto& s : samples)
        if (!s.stable)
            script += fmt::format("set object {} rect from {},graph 0 to {},graph 0.06 fc rgb '#d73027' fs solid "
                                  "noborder front\n", object++, s.k - half, s.k + half);
    std::string plot;
    for (std::size_t b = 0; b < samples.front().branch_minima.size(); ++b)
        plot += fmt::format("${} using 1:{} with lines lw 2 lc rgb '{}' title 'branch {}{}', ", id,
                            axis.using_column(static_cast<int>(b) + 2), branch_colours[b % 6], b + 1, b == 0 ? " (lowest)" : "");
    return script + axis.tics() +
           fmt::format("set xrange [{}:{}]\nset title '{}' noenhanced\nplot {}{}\n", samples.front().k, samples.back().k,
                       c.kernel_label, plot, stability_legend);
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

// Stability: per lattice, a panel per kernel of min omega^2 against k, and one of the
// dispersion curves along the high-symmetry path.
void draw_stability_figures(const StudyResults& results, Canvas& canvas)
{
    std::vector<std::string> lattices;
    for (const auto& c : results.stability)
        if (!c.refused && std::find(lattices.begin(), lattices.end(), c.lattice) == lattices.end())
            lattices.push_back(c.lattice);
    int block = 0;
    for (const auto& lattice : lattices) {
        std::vector<const StabilityCase*> cases;
        for (const auto& c : results.stability)
            if (c.lattice == lattice && !c.refused) cases.push_back(&c);
        const auto [rows, columns] = layout(cases.size());
        std::string script = fmt::format(
            "set multiplot layout {},{} title '{}: the lowest squared frequency of each branch over the Brillouin "
            "zone against k (below zero: unstable); condition (22) at a_p = {}' noenhanced\n"
            "set grid\nset xlabel 'k = h / d'\nset ylabel 'min ω² [c²/d²] (symmetric log scale)'\n{}",
            rows, columns, lattice, cases.front()->overlap.empty() ? "-" : cases.front()->overlap.front().ap_name, key_setup);
        for (const auto* c : cases) script += stability_panel(*c, fmt::format("m{}", block++));
        canvas.draw(lattice + "-stability", panel_width * columns, panel_height * rows, script + "unset multiplot\n");
        script = fmt::format("set multiplot layout {},{} title '{}: squared frequency of each branch along the "
                             "high-symmetry path' noenhanced\nset grid xtics\nset xlabel 'wave vector along the path'\n"
                             "set ylabel 'ω² [c²/d²] (symmetric log scale)'\n{}",
                             rows, columns, lattice, key_setup);
        for (const auto* c : cases) script += dispersion_panel(*c, fmt::format("p{}", block++));
        canvas.draw(lattice + "-dispersion", panel_width * columns, panel_height * rows, script + "unset multiplot\n");
    }
}

} // namespace

std::vector<std::string> draw_study_plots(const Study& study, const StudyResults& results, const fs::path& folder,
                                          const fs::path& gnuplot, const std::vector<std::string>& formats)
{
    fs::create_directories(folder);
    Canvas canvas{folder, formats, gnuplot, {}};
    draw_bulk_figures(study, results, canvas);
    draw_surface_figures(results, canvas);
    draw_sweep_figures(results, canvas);
    draw_stability_figures(results, canvas);
    draw_particles_figures(results, [&](const std::string& name, int width, int height, const std::string& body) {
        canvas.draw(name, width, height, body);
    });
    return canvas.written;
}

} // namespace sphkern
