#include "study/study_run.hpp"

#include "study/gnuplot.hpp"
#include "study/plots.hpp"
#include "study/report.hpp"
#include "study/results_folder.hpp"
#include "study/study.hpp"
#include "study/study_runner.hpp"
#include "support/error.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/output_folder.hpp"
#include "support/text/value_checks.hpp"

#include <algorithm>

namespace sphkern {

namespace {

std::vector<std::string> shipped_study_names()
{
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(data_folder("studies"), ec))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

std::filesystem::path study_file(const std::string& study)
{
    if (study.empty()) return data_folder("studies") / "potapov2021.json";
    if (looks_like_path(study, ".json")) return study;
    const auto names = shipped_study_names();
    if (std::find(names.begin(), names.end(), study) == names.end()) {
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        fail_unknown("unknown study \"" + study + "\"" + did_you_mean(study, names) + "; shipped studies: " + list +
                     ", or give a path to a study file");
    }
    return data_folder("studies") / (study + ".json");
}

StudyRun run_study_folder(const StudyRunRequest& request, const StudyRunSources& sources,
                          const std::function<KernelRegistry&()>& kernels)
{
    const std::filesystem::path file = study_file(request.study);
    const auto formats = parse_figure_formats(request.formats, sources.format);
    const Study study = read_study(file);
    const std::filesystem::path target = request.output.empty() ? std::filesystem::path("sphkern-results") / study.name
                                                                : std::filesystem::path(request.output);
    OutputFolder output(target, request.force);
    const StudyResults results = run_study(study, kernels());
    StudyRun run;
    run.folder = target;
    run.cases = results.cases.size();
    if (study.plots && request.plots) {
        const auto gnuplot = find_gnuplot();
        run.gnuplot_missing = gnuplot.empty();
        if (!gnuplot.empty())
            run.figures = draw_study_plots(study, results, output.staging() / "plots", gnuplot, formats);
    }
    write_results_folder(output, study, results, run.figures);
    output.commit();
    run.summary = replication_markdown(results);
    if (run.summary.empty()) run.summary = verdicts_markdown(study, results);
    return run;
}

} // namespace sphkern
