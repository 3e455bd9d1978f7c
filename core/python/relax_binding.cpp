// sphkern.relax: a particle set relaxed in its periodic box, through the requests `sphkern
// relax` runs (the source, h, the settings, the code, the outputs), its --json document as
// Python objects with the relaxed positions as a numpy array.
#include "command_docstrings.hpp"
#include "commands_binding.hpp"
#include "module_support.hpp"
#include "python_types.hpp"
#include "setting_keywords.hpp"

#include "particles/formats/particle_writers.hpp"
#include "particles/tiled_set.hpp"
#include "requests/relax_output.hpp"
#include "requests/relax_report.hpp"
#include "requests/relax_request.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/output_targets.hpp"
#include "support/process/interruption.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace py = pybind11;

namespace sphkern {

namespace {

ValueSource named(const char* key) { return value_named(FrontEnd::python, key); }

// A sequence of numbers as the list text the source request reads ("4,4,4"), exactly.
std::string list_text(const py::object& values, const char* what, const char* expected)
{
    if (values.is_none()) return {};
    std::vector<double> numbers;
    try {
        numbers = values.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
        fail_input(fmt::format("{}: expected {}", what, expected));
    }
    std::string text;
    for (double v : numbers) text += (text.empty() ? "" : ",") + fmt::format("{}", v);
    return text.empty() ? "," : text; // an empty sequence: refused as a list without numbers
}

struct SourceGiven {
    std::string spec;
    OptionalIntSequence size;
    std::optional<std::string> cell;
    double sigma;
    unsigned long long seed;
    std::optional<unsigned long long> count;
    std::optional<int> dim;
    OptionalSequence box;
    std::optional<double> particle_radius;
    std::optional<std::string> array;
};

ParticleSource source_of(const SourceGiven& g)
{
    return particle_source_of({g.spec, list_text(g.size, "size", "whole numbers of cells [N1, N2] or [N1, N2, N3]"),
                               list_text(g.box, "box", "a sequence of box sides"), g.array.value_or(""),
                               g.cell.value_or(""), g.sigma, g.seed, g.count.value_or(0), g.dim.value_or(0),
                               g.particle_radius},
                              source_sources(FrontEnd::python));
}

struct RelaxGiven {
    std::optional<double> h_over_l, nh, k;
    std::optional<std::string> code;
    std::optional<double> value;
    std::string method;
    RelaxSettings settings;
    double rdf_max;
    std::size_t rdf_bins;
    double memory_limit;
    std::optional<std::string> output, tile, history;
    std::optional<double> rho0, u;
};

// The code and its setting, if given; where the setting sets h, no other h beside it.
std::optional<RelaxCode> relax_code_given(const RelaxGiven& g, const CodeSettingSources& sources)
{
    if (g.value && !g.code) fail_input("value: the parameter of a code; expected code too");
    std::optional<RelaxCode> code;
    if (g.code) code = RelaxCode{*g.code, g.value};
    if (code) check_code_beside_h(*code, g.h_over_l || g.nh || g.k, FrontEnd::python, sources);
    return code;
}

// The steps as CSV.
void write_history(const std::string& file, const std::vector<RelaxStep>& steps)
{
    write_file_atomically(file, [&](std::ostream& out) { write_relax_history_csv(out, steps); });
}

py::dict relax_command(const std::string& kernel_spec, const SourceGiven& source_given, RelaxGiven g,
                       const OptionalParams& params)
{
    set_memory_budget(g.memory_limit, named("memory_limit"));
    const auto sources = relax_sources(FrontEnd::python);
    g.settings.method = relax_method_of(g.method, sources.method);
    check_relax_settings(g.settings, sources);
    check_rdf(g.rdf_max, g.rdf_bins, sources);
    const CodeSettingSources code_sources{named("code"), named("value")};
    const std::optional<RelaxCode> code = relax_code_given(g, code_sources);
    if (source_given.particle_radius && (g.h_over_l || g.nh || g.k))
        fail_input("particle_radius gives a SPlisHSPlasH file's h; expected no h_over_l, nh or k beside it");
    SmoothingSpec spec = smoothing_spec({g.h_over_l, g.nh, g.k, std::nullopt}, sources.smoothing);
    std::vector<OutputTarget> outputs;
    if (g.output) outputs.push_back({"output", *g.output});
    if (g.history) outputs.push_back({"history", *g.history});
    std::vector<std::string> inputs;
    for (const auto& spec_text : {source_given.spec, kernel_spec})
        if (std::filesystem::exists(spec_text)) inputs.push_back(spec_text);
    check_output_targets(outputs, inputs);
    if (g.output) check_relax_output(*g.output, named("output"), code);
    const RelaxOutput output{g.output.value_or(""), g.tile.value_or(""), g.rho0, g.u};
    check_relax_output_settings(output, FrontEnd::python);
    const ParticleSource source = source_of(source_given);
    const auto kernel = kernel_of(kernel_spec, params);
    nlohmann::json document;
    RelaxResult run;
    {
        py::gil_scoped_release unlocked;
        ParticleSet set = load_source(source, source_sources(FrontEnd::python), g.settings.threads);
        if (code) check_relax_code(*code, g.output.value_or(""), kernel, set.dimension, code_sources);
        if (code && code->value) spec = relax_code_smoothing(*code, kernel, set.dimension, code_sources);
        check_output_targets(outputs, set.linked_files);
        const double h = relax_h(spec, set, kernel, sources.smoothing);
        const bool csv = g.output && g.output->ends_with(".csv");
        if (g.output) require_layout_box(set, csv ? ParticleLayout::swift : relax_layout(code), "output " + *g.output);
        const auto tiles = tiles_of(g.tile.value_or(""), set, named("tile"));
        run = relax_until_diverged(kernel, std::move(set), h, g.settings, {}, g.history.value_or(""),
                                   [&](const std::vector<RelaxStep>& steps) { write_history(*g.history, steps); });
        const RelaxedSet judged = judge_relaxed(kernel, run, g.settings.threads, g.rdf_max, g.rdf_bins);
        document = relax_json(kernel, g.settings, run, judged);
        if (code) document["code"] = relax_code_json(*code);
        if (g.output)
            document["output"] = written_json(write_relaxed_set(kernel, run, output, g.settings, code, tiles));
        if (g.history) write_history(*g.history, run.history);
    }
    py::dict out = to_python(document);
    out["positions"] = positions_array(run.state.set);
    return out;
}

} // namespace

void bind_relax(py::module_& m)
{
    const RelaxSettings d;
    const SettingKeywords relax_keywords("relax");
    m.def(
        "relax",
        [](const std::string& kernel, const std::string& source, const OptionalIntSequence& size,
           const std::optional<std::string>& cell, double sigma, unsigned long long seed,
           std::optional<unsigned long long> count, std::optional<int> dim, const OptionalSequence& box,
           std::optional<double> particle_radius, const std::optional<std::string>& array,
           std::optional<double> h_over_l, std::optional<double> nh, std::optional<double> k,
           const std::optional<std::string>& code, std::optional<double> value, const std::string& method, int steps,
           double tolerance, double gamma, double dt, double damping, double alpha, double max_move, int threads,
           double rdf_max, std::size_t rdf_bins, double memory_limit, const std::optional<std::string>& output,
           std::optional<double> rho0, std::optional<double> u, const OptionalIntSequence& tile,
           const std::optional<std::string>& history, const OptionalParams& params) {
            const RelaxSettings settings{
                RelaxMethod::pressure, steps, tolerance, gamma, dt, damping, alpha, max_move, threads};
            std::optional<std::string> tiles;
            if (!tile.is_none()) tiles = list_text(tile, "tile", "whole numbers of copies [N1, N2] or [N1, N2, N3]");
            return relax_command(kernel, {source, size, cell, sigma, seed, count, dim, box, particle_radius, array},
                                 {h_over_l, nh, k, code, value, method, settings, rdf_max, rdf_bins, memory_limit,
                                  output, tiles, history, rho0, u},
                                 params);
        },
        relax_keywords.required("kernel"), relax_keywords.required("source"), py::kw_only(), relax_keywords("size"),
        relax_keywords("cell"), relax_keywords("sigma"), relax_keywords("seed"), relax_keywords("count"),
        relax_keywords("dim"), relax_keywords("box"), relax_keywords("particle_radius"), relax_keywords("array"),
        relax_keywords("h_over_l"), relax_keywords("nh"), relax_keywords("k"), relax_keywords("code"),
        relax_keywords("value"), relax_keywords("method"), relax_keywords("steps"), relax_keywords("tolerance"),
        relax_keywords("gamma"), relax_keywords("dt"), relax_keywords("damping"), relax_keywords("alpha"),
        relax_keywords("max_move"), relax_keywords("threads"), relax_keywords("rdf_max"), relax_keywords("rdf_bins"),
        relax_keywords("memory_limit"), relax_keywords("output"), relax_keywords("rho0"), relax_keywords("u"),
        relax_keywords("tile"), relax_keywords("history"), relax_keywords("params"), doc::relax,
        py::call_guard<InterruptScope>());
}

} // namespace sphkern
