#include "study/gnuplot.hpp"

#include "support/error.hpp"
#include "support/process/child_process.hpp"
#include "support/process/interruption.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

constexpr double gnuplot_timeout_seconds = 120;

} // namespace

fs::path find_gnuplot()
{
    const char* path = std::getenv("PATH");
    std::stringstream list(path ? path : "/usr/bin:/bin");
    std::string folder;
    std::error_code ec;
    while (std::getline(list, folder, ':')) {
        fs::path candidate = fs::path(folder) / "gnuplot";
        // Absolute folders only: gnuplot runs from the staging folder, where "." means something else.
        if (fs::path(folder).is_absolute() && fs::is_regular_file(candidate, ec) &&
            ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return {};
}

std::vector<std::string> parse_figure_formats(const std::string& list, const std::string& option)
{
    std::vector<std::string> formats;
    std::stringstream items(list);
    std::string item;
    while (std::getline(items, item, ',')) {
        if (item != "svg" && item != "png" && item != "pdf")
            throw Error(ExitCode::usage,
                        option + " " + list + ": \"" + item + "\" is not a figure format, expected svg, png or pdf");
        if (std::find(formats.begin(), formats.end(), item) == formats.end()) formats.push_back(item);
    }
    if (formats.empty()) throw Error(ExitCode::usage, option + ": expected a list of svg, png and pdf");
    return formats;
}

namespace {

std::string terminal(const std::string& format, int width, int height)
{
    if (format == "png")
        return fmt::format("set terminal pngcairo size {},{} enhanced font 'sans,10' background '#ffffff'", width,
                           height);
    if (format == "pdf")
        return fmt::format("set terminal pdfcairo size {:.3f}in,{:.3f}in enhanced font 'sans,8'", width / 96.0,
                           height / 96.0);
    return fmt::format("set terminal svg size {},{} enhanced font 'sans,11' background '#ffffff'", width, height);
}

std::string last_line(const std::string& text)
{
    const auto end = text.find_last_not_of(" \n\r\t");
    if (end == std::string::npos) return "no message";
    const auto start = text.find_last_of('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1,
                       end + 1 - (start == std::string::npos ? 0 : start + 1));
}

} // namespace

// Keeps the script beside the figure and runs gnuplot inside the folder (no shell: an
// argument vector), so that the script names its output relatively.
void render_figure(const fs::path& folder, const std::string& name, int width, int height, const std::string& body,
                   const std::vector<std::string>& formats, const fs::path& gnuplot)
{
    fs::path script_file = folder / (name + ".gp");
    {
        std::ofstream out(script_file);
        out << body;
        if (!out) throw Error(ExitCode::output, script_file.string() + ": cannot write (disk full?)");
    }
    for (const auto& format : formats) {
        throw_if_interrupted();
        const std::string setup =
            "set encoding utf8; " + terminal(format, width, height) + "; set output '" + name + "." + format + "'";
        auto run = run_program({gnuplot.string(), "-e", setup, name + ".gp"}, folder, gnuplot_timeout_seconds);
        if (run.timed_out)
            throw Error(ExitCode::output, fmt::format("gnuplot did not finish {} within {} s", script_file.string(),
                                                      gnuplot_timeout_seconds));
        if (run.exit_status != 0) {
            // gnuplot's message starts with a blank line and the line at fault; its reason is last.
            std::string reason = run.signal ? fmt::format("killed by signal {}", run.signal) : last_line(run.output);
            throw Error(ExitCode::output, "gnuplot failed on " + script_file.string() + " (" + format + "): " + reason);
        }
    }
}

} // namespace sphkern
