// `sphkern relax`: a particle set relaxed in its periodic box (SPH pressure with damping, or
// particle shifting), the glass it makes judged and written for `sphkern particles`.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/source_options.hpp"

#include "particles/formats/particle_writers.hpp"
#include "particles/particles_memory.hpp"
#include "requests/relax_output.hpp"
#include "requests/relax_report.hpp"
#include "requests/relax_request.hpp"
#include "requests/relax_series.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/output_targets.hpp"
#include "support/io/results_output.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

struct RelaxOptions : CommonOptions, SourceOptions {
    std::string kernel, method, output, history, tile; // the defaults: requests/settings
    std::vector<std::string> sets;
    std::optional<double> h_over_l, eta, nh, k;
    std::optional<double> rho0, u; // of the written initial conditions
    SettingOptions codes;          // --code and the codes' parameters but --eta (SWIFT's, with --code swift)
    RelaxSettings settings;
    double memory_limit = 0, rdf_max = 0;
    std::size_t rdf_bins = 0;
};

void add_options(Command c, RelaxOptions& o)
{
    c.add_setting("kernel", o.kernel);
    add_source_options(c, o);
    c.add_setting("h_over_l", o.h_over_l);
    c.add_setting("eta", o.eta);
    c.add_setting("nh", o.nh);
    c.add_setting("k", o.k);
    c.add_setting("code", o.codes.code);
    add_code_parameters(c, o.codes);
    // The radius gives a SPlisHSPlasH file's h, which a rule for h would leave unused.
    c.get_option("--particle-radius").excludes("--h-over-l").excludes("--nh").excludes("--k");
    c.add_setting("method", o.method);
    auto& s = o.settings;
    c.add_setting("steps", s.steps);
    c.add_setting("tolerance", s.tolerance);
    c.add_setting("gamma", s.gamma);
    c.add_setting("dt", s.time_step);
    c.add_setting("damping", s.damping);
    c.add_setting("alpha", s.alpha);
    c.add_setting("max_move", s.max_move);
    c.add_setting("threads", s.threads);
    c.add_setting("rdf_max", o.rdf_max);
    c.add_setting("rdf_bins", o.rdf_bins);
    c.add_setting("memory_limit", o.memory_limit);
    c.add_setting("output", o.output);
    c.add_setting("rho0", o.rho0);
    c.add_setting("u", o.u);
    c.add_setting("tile", o.tile);
    c.add_setting("history", o.history);
    add_set_option(c, o.sets);
    add_plugin_option(c, o);
    add_json_option(c, o);
}

// --output holds a rectangular box; a lattice block cut from its primitive cell is told how
// to cut it from a rectangular one.
void require_box_for_output(const ParticleSet& set, const RelaxOptions& o, ParticleLayout layout)
{
    try {
        require_layout_box(set, layout, "--output " + o.output);
    } catch (const Error& e) {
        if (source_kind(o.source) != SourceKind::lattice || o.cell == "rectangular") throw;
        throw Error(e.code(),
                    std::string(e.what()) + "; --cell rectangular cuts the block from the lattice's rectangular cell");
    }
}

// --history: the steps as CSV, or with a series each step's particles as it ends and the
// collection last.
void write_history(const RelaxOptions& o, const std::vector<RelaxStep>& steps, RelaxSeries* series)
{
    if (series) series->finish();
    else write_file_atomically(o.history, [&](std::ostream& out) { write_relax_history_csv(out, steps); });
}

// The run, each step's particles to the series where --history names one; a diverged run's
// steps to --history.
RelaxResult relax_with_history(const Kernel& kernel, ParticleSet set, double h, const RelaxOptions& o,
                               RelaxSeries* series)
{
    std::function<void(const RelaxState&, const RelaxStep&)> observe;
    if (series) observe = [series](const RelaxState& state, const RelaxStep& step) { series->write_step(state, step); };
    return relax_until_diverged(kernel, std::move(set), h, o.settings, observe, o.history,
                                [&](const std::vector<RelaxStep>& steps) { write_history(o, steps, series); });
}

// The series' .vtu files against what the run reads; their names differ from each other and
// from --output (.h5 or .csv) by construction, so each is checked alone.
void check_series_targets(const RelaxSeries& series, const std::vector<std::string>& inputs)
{
    for (const auto& file : series.member_files()) check_output_targets({{"--history", file}}, inputs);
}

// --code and its setting, if given; where the setting sets h, no other h beside it.
std::optional<RelaxCode> relax_code_of(const RelaxOptions& o)
{
    std::optional<RelaxCode> code;
    if (const auto choice = code_beside_own_eta(o.codes, o.eta)) code = RelaxCode{choice->code, choice->value};
    const auto [code_source, value_source] = code_sources(o.codes);
    if (code)
        check_code_beside_h(*code, o.h_over_l || o.nh || o.k, FrontEnd::command_line, {code_source, value_source});
    return code;
}

} // namespace

Action add_relax_command(Command app)
{
    Command command = app.add_subcommand("relax", "Relax a particle set into a glass and judge it");
    auto options = std::make_shared<RelaxOptions>();
    add_options(command, *options);
    return [options, command] {
        auto& o = *options;
        set_memory_budget(o.memory_limit, value_named(FrontEnd::command_line, "memory_limit"));
        const auto sources = relax_sources(FrontEnd::command_line);
        o.settings.method = relax_method_of(o.method, sources.method);
        check_relax_settings(o.settings, sources);
        check_rdf(o.rdf_max, o.rdf_bins, sources); // before the run: g(r) is drawn after it
        const std::optional<RelaxCode> code = relax_code_of(o);
        const auto [code_source, value_source] = code_sources(o.codes);
        SmoothingSpec spec = smoothing_spec({o.h_over_l, o.nh, o.k, std::nullopt}, sources.smoothing);
        const auto outputs = given_outputs(command, {{"--output", o.output}, {"--history", o.history}});
        check_output_targets(outputs, read_inputs(o.source, o.kernel, o.plugins));
        std::optional<RelaxSeries> series;
        if (is_pvd_name(o.history)) {
            series.emplace(o.history, o.settings.steps);
            check_series_targets(*series, read_inputs(o.source, o.kernel, o.plugins));
        }
        if (!o.output.empty()) check_relax_output(o.output, value_named(FrontEnd::command_line, "output"), code);
        const RelaxOutput output{o.output, o.tile, o.rho0, o.u};
        check_relax_output_settings(output, FrontEnd::command_line);
        auto registry = discover_kernels(o);
        auto kernel = make_kernel(registry, o.kernel, o.sets);
        const auto digest = o.json ? start_source_digest(o) : nullptr;
        ParticleSet set = load_source(source_of(o), source_sources(FrontEnd::command_line), o.settings.threads);
        if (code) check_relax_code(*code, o.output, kernel, set.dimension, {code_source, value_source});
        if (code && code->value) spec = relax_code_smoothing(*code, kernel, set.dimension, {code_source, value_source});
        check_output_targets(outputs, set.linked_files); // what the file reached through its links
        if (series) check_series_targets(*series, set.linked_files);
        const double h = relax_h(spec, set, kernel, sources.smoothing);
        // A CSV file holds any rectangular box; an HDF5 file the box of the code's layout.
        if (!o.output.empty())
            require_box_for_output(set, o, o.output.ends_with(".csv") ? ParticleLayout::swift : relax_layout(code));
        const auto tiles = tiles_of(o.tile, set, ValueSource::option("--tile"));
        const RelaxResult run = relax_with_history(kernel, std::move(set), h, o, series ? &*series : nullptr);
        const RelaxedSet judged = judge_relaxed(kernel, run, o.settings.threads, o.rdf_max, o.rdf_bins);
        std::optional<WrittenSet> wrote;
        if (!o.output.empty()) wrote = write_relaxed_set(kernel, run, output, o.settings, code, tiles);
        if (!o.history.empty()) write_history(o, run.history, series ? &*series : nullptr);
        if (o.json) {
            auto document = relax_json(kernel, o.settings, run, judged);
            if (code) document["code"] = relax_code_json(*code);
            if (wrote) document["output"] = written_json(*wrote);
            print_json(document, source_inputs(o, kernel, digest.get()));
        } else {
            print_relax(results_file(), kernel, o.settings, run, judged);
            if (code) fmt::print(results_file(), "{}\n", relax_code_text(*code));
            if (wrote) fmt::print(results_file(), "{}\n", written_text(*wrote));
        }
        return 0;
    };
}

} // namespace sphkern::cli
