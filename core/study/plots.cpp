#include "study/plots.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/wait.h>

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
        if (!folder.empty() && fs::is_regular_file(candidate, ec)) return candidate;
    }
    return {};
}

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
        std::string script = fmt::format(
            "set encoding utf8\nset terminal svg size {},{} dynamic enhanced font 'sans,11' background '#ffffff'\n"
            "set output '{}'\nset multiplot layout {},{} title '{} on {}, mode {}: ε_ρ solid, "
            "ε_{{∇P}} dashed'\n"
            "set grid\nset xrange [{}:{}]\nset yrange [-0.1:0.1]\nset xlabel 'k'\nset key bottom right font ',9'\n",
            420 * columns, 340 * rows, name + ".svg", rows, columns,
            study.name, key.first, key.second, study.k_min, study.k_max);
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
        fs::path script_file = folder / (name + ".gp");
        std::ofstream(script_file) << script;
        // Run inside the folder so that the kept script names its output relatively.
        std::string command = "cd '" + folder.string() + "' && '" + gnuplot.string() + "' '" + name + ".gp' 2>&1";
        std::string output;
        if (FILE* pipe = ::popen(command.c_str(), "r")) {
            char buffer[512];
            while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
            int status = ::pclose(pipe);
            if (status != 0)
                throw Error(ExitCode::output, "gnuplot failed on " + script_file.string() + ": " +
                                                  output.substr(0, output.find('\n')));
        }
        written.push_back(folder.filename().string() + "/" + name + ".svg");
    }
    return written;
}

} // namespace sphkern
