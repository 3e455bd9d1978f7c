// `sphkern run`: a study (default: the paper's) into a results folder, complete or not at all.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "study/reproduce.hpp"
#include "study/study_run.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <memory>
#include <optional>

namespace sphkern::cli {

Action add_run_command(Command app)
{
    Command command = app.add_subcommand("run", "Run a study (default: share/studies/potapov2021.json)");
    struct Options : CommonOptions {
        std::string study;
        std::string output;
        bool no_plots = false;
        bool force = false;
        std::string reproduce;
        std::string format; // the default: requests/settings
    };
    auto options = std::make_shared<Options>();
    command.add_setting("study", options->study);
    command.add_setting("output", options->output);
    command.add_setting("no_plots", options->no_plots);
    command.add_setting("format", options->format);
    command.add_setting("force", options->force);
    command.add_setting("reproduce", options->reproduce)
        .excludes(command.get_option("study"))
        .excludes("--output")
        .excludes("--force");
    add_plugin_option(command, *options);
    return [options] {
        auto started = std::chrono::steady_clock::now();
        if (!options->reproduce.empty()) {
            auto registry = discover_kernels(*options);
            const Reproduction outcome = reproduce_study(options->reproduce, registry);
            fmt::print(results_file(), "{}", outcome.text);
            return outcome.agreed ? 0 : static_cast<int>(ExitCode::check_failed);
        }
        StudyRunRequest request{options->study, options->output, !options->no_plots, options->format, options->force};
        std::optional<KernelRegistry> registry;
        const StudyRun run = run_study_folder(request, {"--format"}, [&]() -> KernelRegistry& {
            return registry.emplace(discover_kernels(*options));
        });
        if (run.gnuplot_missing) spdlog::warn("gnuplot not found on PATH: figures skipped");
        fmt::print(results_file(), "{}", run.summary);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        spdlog::info("{} cases in {:.3f} s; report, results.json, curves.csv{} in {}", run.cases, seconds,
                     run.figures.empty() ? "" : " and figures", run.folder.string());
        return 0;
    };
}

} // namespace sphkern::cli
