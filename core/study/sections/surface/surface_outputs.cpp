#include "study/sections/surface/surface_section.hpp"

#include "analysis/results_json.hpp"
#include "study/canvas.hpp"
#include "study/report_text.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sphkern {

nlohmann::json SurfaceResults::json(const Study&) const
{
    nlohmann::json surface = nlohmann::json::array();
    for (const auto& c : cases) {
        auto entry = surface_json(c.profile);
        entry.update({{"lattice", c.lattice},
                      {"kernel", c.kernel_label},
                      {"form", c.form},
                      {"volume_coefficient", c.ap_name},
                      {"a_p", c.a_p},
                      {"k", c.k}});
        surface.push_back(entry);
    }
    return surface;
}

std::string SurfaceResults::markdown(const Study&) const
{
    std::string s;
    if (!cases.empty()) {
        s +=
            "## Free-surface profiles\n\nA particle on layer n below a free surface normal to gravity (layer 0 on top, "
            "P = 0 there), by lattice sums over the half-space (" +
            method_document() + " section 6). Each cell: eps_rho / eps_gradP.\n\n";
        std::size_t columns = 0;
        for (const auto& c : cases) columns = std::max(columns, c.profile.layers.size());
        std::string current;
        for (const auto& c : cases) {
            if (c.lattice != current) {
                current = c.lattice;
                s += fmt::format("### {} (a_p = {} = {:.6f}, layer spacing {:.4f} d)\n\n| kernel | form | k |",
                                 c.lattice, c.ap_name, c.a_p, c.profile.spacing);
                for (std::size_t n = 0; n < columns; ++n) s += fmt::format(" n = {} |", n);
                s += " bulk |\n|---|---|---|";
                for (std::size_t n = 0; n <= columns; ++n) s += "---|";
                s += "\n";
            }
            s += fmt::format("| {} | {} | {:.4f} |", c.kernel_label, c.form, c.k);
            for (std::size_t n = 0; n < columns; ++n)
                s += n < c.profile.layers.size() ? fmt::format(" {:+.4f} / {:+.4f} |", c.profile.layers[n].eps_rho,
                                                               c.profile.layers[n].eps_gradp)
                                                 : std::string(" |");
            s += fmt::format(" {:+.4f} / {:+.4f} |\n", c.profile.bulk.eps_rho, c.profile.bulk.eps_gradp);
        }
        s += "\n";
    }

    return s;
}

// A figure per lattice, a panel per kernel, a curve per form; the range follows the data.
void SurfaceResults::draw(const Study&, Canvas& canvas) const
{
    std::vector<std::string> surface_lattices;
    for (const auto& c : cases)
        if (std::find(surface_lattices.begin(), surface_lattices.end(), c.lattice) == surface_lattices.end())
            surface_lattices.push_back(c.lattice);
    for (const auto& lattice : surface_lattices) {
        std::vector<std::string> kernels;
        for (const auto& c : cases)
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
            for (const auto& c : cases) {
                if (c.lattice != lattice || c.kernel_label != kernel) continue;
                k = c.k;
                std::string id = fmt::format("s{}", block++);
                script += "$" + id + " << EOD\n";
                for (const auto& l : c.profile.layers)
                    script += fmt::format("{} {:.10g} {:.10g}\n", l.n, l.eps_rho, l.eps_gradp);
                script += "EOD\n";
                const char* rgb = curve_colours[colour++ % 6];
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

} // namespace sphkern
