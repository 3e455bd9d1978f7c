#include "requests/relax_run.hpp"

#include "particles/formats/particle_writers.hpp"
#include "requests/relax_report.hpp"
#include "requests/relax_series.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/output_targets.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <utility>

namespace sphkern {

namespace {

// The files a run writes (its output, its history), named as the front end names them.
std::vector<OutputTarget> output_targets(const RelaxJob& job)
{
    std::vector<OutputTarget> outputs;
    const RelaxGiven& g = job.given;
    if (g.output) outputs.push_back({value_named(job.front_end, "output").name, *g.output});
    if (g.history) outputs.push_back({value_named(job.front_end, "history").name, *g.history});
    return outputs;
}

// The outputs and a series' .vtu files (named apart from each other and from the output by
// construction, so each is checked alone) against the files read.
void check_outputs(const RelaxJob& job, const std::vector<std::string>& inputs)
{
    check_output_targets(output_targets(job), inputs);
    if (!is_pvd_name(job.history)) return;
    const std::string history = value_named(job.front_end, "history").name;
    for (const auto& file : RelaxSeries(job.history, job.given.settings.steps).member_files())
        check_output_targets({{history, file}}, inputs);
}

// An output holds a rectangular box: a CSV file any, an HDF5 file the code's layout's; a
// lattice block cut from its primitive cell is told how to cut it from a rectangular one.
void require_box_for_output(const ParticleSet& set, const RelaxJob& job)
{
    const std::string& file = job.output.file;
    const ParticleLayout layout = file.ends_with(".csv") ? ParticleLayout::swift : relax_layout(job.given.code);
    try {
        require_layout_box(set, layout, fmt::format("{} {}", value_named(job.front_end, "output").name, file));
    } catch (const Error& e) {
        if (!job.given.primitive_block) throw;
        const std::string cell = job.front_end == FrontEnd::command_line ? "--cell rectangular" : "cell='rectangular'";
        throw Error(e.code(), fmt::format("{}; {} cuts the block from the lattice's rectangular cell", e.what(), cell));
    }
}

// The steps as CSV, or the series' collection (its steps were written as they ended).
void write_history(const std::string& file, const std::vector<RelaxStep>& steps, RelaxSeries* series)
{
    if (series) series->finish();
    else write_file_atomically(file, [&](std::ostream& out) { write_relax_history_csv(out, steps); });
}

} // namespace

RelaxJob relax_job(RelaxGiven given, FrontEnd front_end, const std::vector<std::string>& inputs)
{
    const auto sources = relax_sources(front_end);
    given.settings.method = relax_method_of(given.method, sources.method);
    check_relax_settings(given.settings, sources);
    check_rdf(given.rdf_max, given.rdf_bins, sources); // before the run: g(r) is drawn after it
    if (given.code)
        check_code_beside_h(*given.code, given.h_over_l || given.nh || given.k, front_end, given.code_sources);
    RelaxJob job{front_end, std::move(given), {}, {}, {}};
    const RelaxGiven& g = job.given;
    job.spec = smoothing_spec({g.h_over_l, g.nh, g.k, std::nullopt}, sources.smoothing);
    job.output = {g.output.value_or(""), g.tile, g.rho0, g.u};
    job.history = g.history.value_or("");
    check_outputs(job, inputs);
    if (g.output) check_relax_output(*g.output, value_named(front_end, "output"), g.code);
    check_relax_output_settings(job.output, front_end);
    return job;
}

RelaxOutcome run_relax(const Kernel& kernel, ParticleSet set, const RelaxJob& job)
{
    const RelaxGiven& g = job.given;
    SmoothingSpec spec = job.spec;
    if (g.code) check_relax_code(*g.code, job.output.file, kernel, set.dimension, g.code_sources);
    if (g.code && g.code->value) spec = relax_code_smoothing(*g.code, kernel, set.dimension, g.code_sources);
    check_outputs(job, set.linked_files); // what the file reached through its links
    const double h = relax_h(spec, set, kernel, relax_sources(job.front_end).smoothing);
    if (!job.output.file.empty()) require_box_for_output(set, job);
    const auto tiles = tiles_of(job.output.tile, set, value_named(job.front_end, "tile"));
    std::optional<RelaxSeries> series;
    if (is_pvd_name(job.history)) series.emplace(job.history, g.settings.steps);
    std::function<void(const RelaxState&, const RelaxStep&)> observe;
    if (series)
        observe = [&series](const RelaxState& state, const RelaxStep& step) { series->write_step(state, step); };
    RelaxOutcome outcome;
    outcome.run = relax_until_diverged(kernel, std::move(set), h, g.settings, observe, job.history,
                                       [&](const std::vector<RelaxStep>& steps) {
                                           write_history(job.history, steps, series ? &*series : nullptr);
                                       });
    outcome.judged = judge_relaxed(kernel, outcome.run, g.settings.threads, g.rdf_max, g.rdf_bins);
    if (!job.output.file.empty())
        outcome.written = write_relaxed_set(kernel, outcome.run, job.output, g.settings, g.code, tiles);
    if (!job.history.empty()) write_history(job.history, outcome.run.history, series ? &*series : nullptr);
    return outcome;
}

nlohmann::json relax_outcome_json(const Kernel& kernel, const RelaxJob& job, const RelaxOutcome& outcome)
{
    auto document = relax_json(kernel, job.given.settings, outcome.run, outcome.judged);
    if (job.given.code) document["code"] = relax_code_json(*job.given.code);
    if (outcome.written) document["output"] = written_json(*outcome.written);
    return document;
}

void print_relax_outcome(std::FILE* out, const Kernel& kernel, const RelaxJob& job, const RelaxOutcome& outcome)
{
    print_relax(out, kernel, job.given.settings, outcome.run, outcome.judged);
    if (job.given.code) fmt::print(out, "{}\n", relax_code_text(*job.given.code));
    if (outcome.written) fmt::print(out, "{}\n", written_text(*outcome.written));
}

} // namespace sphkern
