#include "study/gnuplot.hpp"

#include "support/child_process.hpp"
#include "support/error.hpp"
#include "support/interruption.hpp"

#include <fmt/format.h>

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
        if (fs::path(folder).is_absolute() && fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return {};
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

} // namespace sphkern
