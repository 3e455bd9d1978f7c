#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "study/study_provenance.hpp"
#include "support/error.hpp"
#include "support/io/provenance.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace sphkern::cli {

void add_plugin_option(Command command, CommonOptions& options)
{
    command.add_setting("plugin", options.plugins).one_value_per_use();
}

void add_json_option(Command command, CommonOptions& options) { command.add_setting("json", options.json); }

void add_set_option(Command command, std::vector<std::string>& sets)
{
    command.add_setting("params", sets).one_value_per_use();
}

std::map<std::string, double> parse_sets(const std::vector<std::string>& sets)
{
    std::map<std::string, double> values;
    for (const auto& s : sets) {
        auto eq = s.find('=');
        char* end = nullptr;
        double v = eq == std::string::npos ? 0 : std::strtod(s.c_str() + eq + 1, &end);
        if (eq == std::string::npos || eq == 0 || eq + 1 == s.size() || !end || *end != '\0' || !std::isfinite(v))
            throw Error(ExitCode::usage, "--set " + s + ": expected NAME=VALUE with a finite number");
        if (!values.emplace(s.substr(0, eq), v).second)
            throw Error(ExitCode::usage, "--set " + s.substr(0, eq) + " is given twice; give each parameter once");
    }
    return values;
}

KernelRegistry discover_kernels(const CommonOptions& options)
{
    std::vector<std::filesystem::path> files(options.plugins.begin(), options.plugins.end());
    return KernelRegistry::discover(files);
}

Kernel make_kernel(KernelRegistry& registry, const std::string& spec, const std::vector<std::string>& sets)
{
    return Kernel(registry.find(spec), parse_sets(sets));
}

void add_point_options(Command command, EvaluationOptions& options)
{
    command.add_setting("a_p", options.ap);
    command.add_setting("gravity", options.gravity);
    command.add_setting("site", options.site);
}

void add_evaluation_options(Command command, EvaluationOptions& options)
{
    add_point_options(command, options);
    command.add_setting("shells", options.shells);
    command.add_setting("continue_past_support", options.continue_past_support);
}

KernelOnLattice kernel_on_lattice(const CommonOptions& options, const std::string& kernel, const std::string& lattice,
                                  const std::vector<std::string>& sets)
{
    Lattice loaded = load_lattice(lattice);
    auto registry = discover_kernels(options);
    return {std::move(loaded), make_kernel(registry, kernel, sets)};
}

EvaluationInputs evaluation_inputs(const EvaluationOptions& options)
{
    EvaluationInputs inputs;
    inputs.a_p = options.ap;
    if (!options.gravity.empty()) inputs.gravity = parse_number_list(options.gravity, ValueSource::option("--gravity"));
    inputs.site = options.site;
    if (!options.shells.empty())
        inputs.shell_radii = parse_number_list(options.shells, ValueSource::option("--shells"));
    else if (options.continue_past_support)
        throw Error(ExitCode::usage, "--continue-past-support needs an explicit --shells list");
    inputs.continue_past_support = options.continue_past_support;
    return inputs;
}

EvaluationSources evaluation_sources(const EvaluationOptions& options)
{
    // A site the lattice lacks is refused as input (exit 3), as it always was.
    return {ValueSource::option("--gravity"),
            {"--site", ExitCode::input},
            ValueSource::option("--shells " + options.shells)};
}

std::vector<OutputTarget> given_outputs(const Command& command, const std::vector<OutputTarget>& options)
{
    std::vector<OutputTarget> given;
    for (const auto& target : options)
        if (command.count(target.option) > 0) given.push_back(target);
    return given;
}

std::vector<std::string> read_inputs(const std::string& source, const std::string& kernel,
                                     const std::vector<std::string>& plugins)
{
    std::vector<std::string> files = plugins;
    for (const auto& spec : {source, kernel})
        if (std::filesystem::exists(spec)) files.push_back(spec);
    return files;
}

// Every document says where it comes from; an array is a list of documents.
nlohmann::json command_inputs(const Kernel* kernel, const Lattice* lattice)
{
    nlohmann::json kernels = nlohmann::json::array(), lattices = nlohmann::json::array();
    if (kernel) kernels.push_back(kernel_input_json(*kernel));
    if (lattice) lattices.push_back(lattice_input_json(*lattice));
    return {{"kernels", kernels}, {"lattices", lattices}};
}

void print_json(nlohmann::json document, const nlohmann::json& inputs)
{
    const auto origin = provenance();
    if (document.is_object() && !inputs.is_null()) document["inputs"] = inputs;
    if (document.is_object()) document["provenance"] = origin;
    if (document.is_array())
        for (auto& item : document)
            if (item.is_object()) item["provenance"] = origin;
    fmt::print(results_file(), "{}\n", document.dump(2));
}

} // namespace sphkern::cli
