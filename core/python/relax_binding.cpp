// sphkern.relax: a particle set relaxed in its periodic box, through the requests `sphkern
// relax` runs (the source, h, the settings, the code, the outputs), its --json document as
// Python objects with the relaxed positions as a numpy array.
#include "command_docstrings.hpp"
#include "commands_binding.hpp"
#include "module_support.hpp"
#include "python_types.hpp"
#include "setting_keywords.hpp"

#include "requests/relax_run.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"
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

struct RelaxArguments {
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

// The code and its setting, if given.
std::optional<RelaxCode> relax_code_given(const RelaxArguments& a)
{
    if (a.value && !a.code) fail_input("value: the parameter of a code; expected code too");
    if (a.code) return RelaxCode{*a.code, a.value};
    return std::nullopt;
}

py::dict relax_command(const std::string& kernel_spec, const SourceGiven& source_given, const RelaxArguments& a,
                       const OptionalParams& params)
{
    set_memory_budget(a.memory_limit, named("memory_limit"));
    if (source_given.particle_radius && (a.h_over_l || a.nh || a.k))
        fail_input("particle_radius gives a SPlisHSPlasH file's h; expected no h_over_l, nh or k beside it");
    std::vector<std::string> inputs;
    for (const auto& spec_text : {source_given.spec, kernel_spec})
        if (std::filesystem::exists(spec_text)) inputs.push_back(spec_text);
    const bool primitive_block =
        source_kind(source_given.spec) == SourceKind::lattice && source_given.cell.value_or("") != "rectangular";
    const RelaxJob job = relax_job({a.h_over_l,
                                    a.nh,
                                    a.k,
                                    relax_code_given(a),
                                    {named("code"), named("value")},
                                    a.method,
                                    a.settings,
                                    a.rdf_max,
                                    a.rdf_bins,
                                    a.output,
                                    a.history,
                                    a.tile.value_or(""),
                                    a.rho0,
                                    a.u,
                                    primitive_block},
                                   FrontEnd::python, inputs);
    const ParticleSource source = source_of(source_given);
    const auto kernel = kernel_of(kernel_spec, params);
    nlohmann::json document;
    RelaxResult run;
    {
        py::gil_scoped_release unlocked;
        ParticleSet set = load_source(source, source_sources(FrontEnd::python), a.settings.threads);
        RelaxOutcome outcome = run_relax(kernel, std::move(set), job);
        document = relax_outcome_json(kernel, job, outcome);
        run = std::move(outcome.run);
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
