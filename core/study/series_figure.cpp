#include "study/series_figure.hpp"

#include "study/gnuplot.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <filesystem>

namespace sphkern {

std::string series_figure_format(const std::string& figure, const std::string& setting)
{
    const std::string ext = std::filesystem::path(figure).extension().string();
    if (ext != ".svg" && ext != ".png" && ext != ".pdf")
        throw Error(ExitCode::usage,
                    fmt::format("{} {}: expected a figure file ending in .svg, .png or .pdf", setting, figure));
    return ext.substr(1);
}

void draw_series_figure(const std::string& figure, const std::string& setting, const std::string& script)
{
    const auto gnuplot = find_gnuplot();
    if (gnuplot.empty())
        throw Error(ExitCode::output,
                    fmt::format("{} {}: gnuplot is not on PATH; expected it to draw the figure", setting, figure));
    const std::filesystem::path target(figure);
    const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
    const std::string format = series_figure_format(figure, setting),
                      name = fmt::format(".{}.{}", target.stem().string(), ::getpid());
    std::error_code ec;
    try {
        render_figure(folder, name, 900, 1000, script, {format}, gnuplot);
    } catch (...) {
        std::filesystem::remove(folder / (name + ".gp"), ec),
            std::filesystem::remove(folder / (name + "." + format), ec);
        throw;
    }
    std::filesystem::remove(folder / (name + ".gp"), ec);
    std::filesystem::rename(folder / (name + "." + format), target, ec);
    if (ec)
        throw Error(ExitCode::output,
                    fmt::format("{} {}: cannot put the figure in place ({})", setting, figure, ec.message()));
}

} // namespace sphkern
