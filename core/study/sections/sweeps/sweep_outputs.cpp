#include "study/sections/sweeps/sweep_section.hpp"

#include "analysis/results_json.hpp"
#include "study/canvas.hpp"
#include "study/report_text.hpp"
#include "study/study.hpp"

#include <fmt/format.h>

namespace sphkern {

nlohmann::json SweepResults::json(const Study& study) const
{
    nlohmann::json sweeps = nlohmann::json::array();
    for (const auto& c : cases) {
        nlohmann::json solutions = nlohmann::json::array();
        for (std::size_t i = 0; i < c.design.solutions.size(); ++i) {
            const auto& s = c.design.solutions[i];
            solutions.push_back({{"k", s.k},
                                 {"parameter", s.parameter},
                                 {"eps_rho", s.values.eps_rho},
                                 {"eps_gradp", s.values.eps_gradp},
                                 {"jacobian_condition", s.jacobian_condition},
                                 {"non_negative", s.non_negative},
                                 {"acceptance", acceptance_json(c.designed_acceptance[i], study.epsilon)}});
        }
        sweeps.push_back({{"lattice", c.lattice},
                          {"kernel", c.kernel},
                          {"parameter", c.parameter},
                          {"volume_coefficient", c.ap_name},
                          {"a_p", c.a_p},
                          {"k", c.ks},
                          {"values", c.values},
                          {"eps_rho", c.rho},
                          {"eps_gradp", c.gradp},
                          {"solutions", solutions},
                          {"note", c.design.note}});
    }
    return sweeps;
}

std::string SweepResults::markdown(const Study&) const
{
    std::string s;
    if (!cases.empty()) {
        s += "## Kernel design: parameter sweeps\n\nFor each swept parameter, the (k, parameter) where eps_rho and "
             "eps_gradP vanish together (sphkern design), with the designed kernel's condition (22) intervals; "
             "the maps in the figures show both errors over (k, parameter) with both zero contours.\n\n"
             "| lattice | kernel | a_p | k | parameter | cond(J) | dk, dparameter for a_p + 1% | W >= 0 | k where (22) "
             "holds |\n"
             "|---|---|---|---|---|---|---|---|---|\n";
        for (const auto& c : cases) {
            if (c.design.solutions.empty())
                s +=
                    fmt::format("| {} | {} | {} | - | - | | | | {} |\n", c.lattice, c.kernel, c.ap_name, c.design.note);
            for (std::size_t i = 0; i < c.design.solutions.size(); ++i) {
                const auto& d = c.design.solutions[i];
                s += fmt::format("| {} | {} | {} | {:.6f} | {} = {:.6f} | {:.3g} | {:+.2e}, {:+.2e} | {} | {} |\n",
                                 c.lattice, c.kernel, c.ap_name, d.k, c.parameter, d.parameter, d.jacobian_condition,
                                 d.k_shift, d.parameter_shift, d.non_negative ? "yes" : "no",
                                 intervals_text(c.designed_acceptance[i]));
            }
        }
        s += "\n";
    }

    return s;
}

// Maps of both errors over (k, parameter) with both zero contours. The ranges reach half a
// cell past the outer samples, so that the image stays in its frame.
void SweepResults::draw(const Study&, Canvas& canvas) const
{
    for (const auto& c : cases) {
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
        const double dv =
            c.values.size() > 1 ? (c.values.back() - c.values.front()) / double(c.values.size() - 1) / 2 : 0;
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

} // namespace sphkern
