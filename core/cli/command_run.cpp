// `sphkern run`: a study (default: the paper's) into a results folder, complete or not at all.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "study/gnuplot.hpp"
#include "study/plots.hpp"
#include "study/report.hpp"
#include "study/reproduce.hpp"
#include "study/results_folder.hpp"
#include "study/study_runner.hpp"
#include "support/error.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/output_folder.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <memory>

namespace sphkern::cli {

namespace {

// A study file, or the name of a shipped study (default: the paper's).
std::filesystem::path study_file(const std::string& study)
{
    if (study.empty()) return data_folder("studies") / "potapov2021.json";
    return looks_like_path(study, ".json") ? std::filesystem::path(study) : data_folder("studies") / (study + ".json");
}

} // namespace

Action add_run_command(Command app)
{
    Command command = app.add_subcommand("run", "Run a study (default: share/studies/potapov2021.json)");
    struct Options : CommonOptions {
        std::string study;
        std::string output;
        bool no_plots = false;
        bool force = false;
        std::string reproduce;
        std::string format = "svg";
    };
    auto options = std::make_shared<Options>();
    command.add_option("study", options->study, "Study file, or the name of a shipped study");
    command.add_option("-o,--output", options->output, "Results folder (default: sphkern-results/<study name>)");
    command.add_flag("--no-plots", options->no_plots, "Do not draw the figures");
    command.add_option("--format", options->format, "Figure formats, comma-separated: svg, png, pdf")
        .capture_default_str();
    command.add_flag("--force", options->force, "Replace an existing results folder");
    command.add_option("--reproduce", options->reproduce,
                        "Run the study a results.json records again and say whether the numbers agree (exit 1 if not)")
        .excludes(command.get_option("study")).excludes("--output").excludes("--force");
    add_plugin_option(command, *options);
    return [options] {
        auto started = std::chrono::steady_clock::now();
        if (!options->reproduce.empty()) {
            auto registry = discover_kernels(*options);
            const Reproduction outcome = reproduce_study(options->reproduce, registry);
            fmt::print(results_file(), "{}", outcome.text);
            return outcome.agreed ? 0 : static_cast<int>(ExitCode::check_failed);
        }
        const std::filesystem::path file = study_file(options->study);
        const auto formats = parse_figure_formats(options->format, "--format");
        Study study = read_study(file);
        std::filesystem::path target =
            options->output.empty() ? std::filesystem::path("sphkern-results") / study.name : std::filesystem::path(options->output);
        OutputFolder output(target, options->force);

        auto registry = discover_kernels(*options);
        StudyResults results = run_study(study, registry);

        std::vector<std::string> figures;
        if (study.plots && !options->no_plots) {
            auto gnuplot = find_gnuplot();
            if (gnuplot.empty()) spdlog::warn("gnuplot not found on PATH: figures skipped");
            else figures = draw_study_plots(study, results, output.staging() / "plots", gnuplot, formats);
        }
        write_results_folder(output, study, results, figures);
        output.commit();

        std::string summary = replication_markdown(results);
        fmt::print(results_file(), "{}", summary.empty() ? verdicts_markdown(study, results) : summary);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        spdlog::info("{} cases in {:.3f} s; report, results.json, curves.csv{} in {}", results.cases.size(), seconds,
                     figures.empty() ? "" : " and figures", target.string());
        return 0;
    };
}

} // namespace sphkern::cli
