// `sphkern run`: a study (default: the paper's) into a results folder, complete or not at all.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "study/gnuplot.hpp"
#include "study/plots.hpp"
#include "study/report.hpp"
#include "study/reproduce.hpp"
#include "study/results_writer.hpp"
#include "study/study_runner.hpp"
#include "support/error.hpp"
#include "support/io/chunked_writer.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"
#include "support/io/output_folder.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace sphkern::cli {

namespace {

void write_curves_csv(std::ostream& out, const StudyResults& results)
{
    ChunkedWriter w(out);
    w.text("lattice,mode,kernel,volume_coefficient,a_p,k,eps_rho,eps_gradp,lateral,neighbours\n");
    for (const auto& c : results.cases)
        for (const auto& [k, v] : c.curve)
            w.print("{},{},\"{}\",{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{}\n", c.lattice, c.mode, c.kernel_label,
                    c.ap_name, c.a_p, k, v.eps_rho, v.eps_gradp, v.lateral, v.neighbours);
}

// Runs the study a results file records and says whether its numbers agree (exit 0) or
// not (exit 1); nothing is written.
int reproduce(const std::string& file, KernelRegistry& registry)
{
    const auto recorded = read_json_file(file);
    Study study = study_from_results(recorded, file);
    StudyResults results = run_study(study, registry);
    for (const auto& line : changed_inputs(recorded.value("inputs", nlohmann::json()), results.inputs))
        spdlog::warn("{}: {}", file, line);
    std::ostringstream text;
    write_study_results_json(text, study, results);
    const auto comparison = compare_result_numbers(recorded, nlohmann::json::parse(text.str()), 10);
    if (comparison.differing == 0) {
        fmt::print(results_file(), "reproduced: all {} numbers of {} agree within a relative 1e-9\n",
                   comparison.compared, file);
        return 0;
    }
    fmt::print(results_file(), "not reproduced: {} of {} numbers of {} differ; the first:\n", comparison.differing,
               comparison.compared, file);
    for (const auto& line : comparison.first) fmt::print(results_file(), "  {}\n", line);
    return static_cast<int>(ExitCode::check_failed);
}

// The report links the method document beside it: the folder reads on its own.
void write_method_document(OutputFolder& output)
{
    if (std::ifstream method{data_folder("docs") / "method.md"}) {
        std::ostringstream text;
        text << method.rdbuf();
        output.write("method.md", text.str());
    } else {
        spdlog::warn("{}: not found; the report's link to method.md will not resolve",
                     (data_folder("docs") / "method.md").string());
    }
}

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
            return reproduce(options->reproduce, registry);
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
        output.write("results.json", [&](std::ostream& out) { write_study_results_json(out, study, results); });
        output.write("curves.csv", [&](std::ostream& out) { write_curves_csv(out, results); });
        output.write("report.md", report_markdown(study, results, figures));
        write_method_document(output);
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
