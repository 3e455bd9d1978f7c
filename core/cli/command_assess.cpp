// `sphkern assess`: one verdict on a setting, k or an SPH code's own, on a lattice, or a
// code's setting on a particle file.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/source_options.hpp"
#include "requests/assess_particles.hpp"
#include "requests/assess_request.hpp"
#include "requests/assess_sweep.hpp"
#include "requests/settings/command_settings.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"

#include <algorithm>
#include <map>
#include <memory>

namespace sphkern::cli {

namespace {

struct AssessOptions : CommonOptions {
    std::string kernel, lattice, box, array, neighbours_by;
    bool bias_correction = false;
    SettingOptions setting;
    std::map<std::string, std::vector<double>> ranges; // a code's parameter swept on a file
    int steps = 0, threads = 0;                        // the defaults: requests/settings
    std::size_t glass = 0;
    double k_min = 0, k_max = 0, epsilon = 0, gamma = 0, horizon = 0;
    std::optional<double> coef_sound;
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
};

AssessRequest request_from(const AssessOptions& o)
{
    AssessRequest r;
    r.setting.code = code_setting(o.setting);
    if (o.setting.k) r.setting.k = {*o.setting.k};
    r.setting.evaluation = evaluation_inputs(o.evaluation);
    r.window_min = o.k_min, r.window_max = o.k_max;
    r.epsilon = o.epsilon, r.gamma = o.gamma, r.horizon = o.horizon, r.coef_sound = o.coef_sound;
    r.threads = o.threads, r.glass = o.glass;
    return r;
}

AssessSources option_sources(const AssessOptions& o)
{
    const auto [code, value] = code_sources(o.setting);
    return {{ValueSource::option("--k"), ValueSource::option("--axis"), evaluation_sources(o.evaluation), code, value},
            ValueSource::option("--kmin/--kmax"),
            ValueSource::option("--epsilon"),
            ValueSource::option("--gamma"),
            ValueSource::option("--horizon"),
            ValueSource::option("--coef-sound"),
            ValueSource::option("--glass"),
            ValueSource::option("--threads")};
}

// A code's setting on a particle file: h as `particles --code` sets it, judged on the set.
int assess_file(const AssessOptions& o)
{
    if (o.setting.k)
        throw Error(ExitCode::usage, "--k needs a lattice; on a particle file give --code and its setting");
    if (o.setting.code.empty())
        throw Error(ExitCode::usage,
                    "on a particle file a code's setting is assessed; expected --code (and its setting, or "
                    "none for the file's own h)");
    check_epsilon(o.epsilon, ValueSource::option("--epsilon"));
    const auto range = parameter_range(o.ranges, o.setting.code);
    check_setting(settings_of("assess")["threads"], o.threads, ValueSource::option("--threads"));
    auto registry = discover_kernels(o);
    auto kernel = make_kernel(registry, o.kernel, o.sets);
    SourceOptions source;
    source.source = o.lattice, source.box = o.box, source.array = o.array;
    const auto digest = o.json ? start_source_digest(source) : nullptr;
    const ParticleSet set = load_source(source_of(source), source_sources(FrontEnd::command_line), 0);
    ParticleSources sources = particle_sources(FrontEnd::command_line);
    std::tie(sources.code.code, sources.code.value) = code_sources(o.setting);
    ParticleArguments given;
    const auto choice = code_beside_own_eta(o.setting, std::nullopt);
    // A sweep gives the parameter's values; a value of its own beside it is refused.
    if (range && choice->value)
        throw Error(ExitCode::usage,
                    fmt::format("{} sweeps the parameter; expected no single value beside it", range->first));
    name_code(given, choice->code, range ? std::optional<double>(range->second[0]) : choice->value);
    set_density_solve(given.code ? &*given.code : nullptr, o.neighbours_by, o.bias_correction);
    given.threads = o.threads;
    if (range) {
        const auto sweep =
            sweep_code_setting(kernel, set, given, sources, o.epsilon, range->second[0], range->second[1], o.steps,
                               ValueSource::option(range->first), ValueSource::option("--steps"));
        if (o.json) print_json(code_sweep_json(sweep), source_inputs(source, kernel, digest.get()));
        else print_code_sweep(results_file(), kernel, set, sweep);
        return 0;
    }
    const auto result = assess_particles(kernel, set, given, sources, o.epsilon);
    if (o.json)
        print_json(particle_assess_document(kernel, set, given, result), source_inputs(source, kernel, digest.get()));
    else print_particle_assess(results_file(), kernel, set, given, result);
    return 0;
}

// The lattice's options mean nothing on a particle set: said, not ignored.
void refuse_lattice_options(const Command& command, const std::string& file)
{
    for (const char* name : {"--ap", "--gravity", "--site", "--shells", "--continue-past-support", "--kmin", "--kmax",
                             "--gamma", "--coef-sound", "--horizon", "--glass"})
        if (command.count(name) > 0)
            throw Error(ExitCode::usage, fmt::format("{} is for a lattice; on a particle file ({}) assess judges "
                                                     "the set's own sums, expected none",
                                                     name, file));
}

// A particle file's options mean nothing on a lattice: said, not ignored.
void refuse_particle_file_options(const Command& command, const std::map<std::string, std::vector<double>>& ranges)
{
    for (const char* name : {"--box", "--array", "--neighbours-by", "--bias-correction", "--steps"})
        if (command.count(name) > 0)
            throw Error(ExitCode::usage, fmt::format("{} is for a particle file; expected one, not a lattice", name));
    for (const auto& [name, values] : ranges)
        if (!values.empty()) {
            std::string option = name;
            std::replace(option.begin(), option.end(), '_', '-');
            throw Error(ExitCode::usage,
                        fmt::format("--{}-range is for a particle file; expected one, not a lattice", option));
        }
}

// A setting on a lattice: accuracy, stability and the recommended setting.
int assess_lattice(const AssessOptions& o)
{
    const auto sources = option_sources(o);
    const auto request = request_from(o);
    check_assess_request(request, sources);
    const auto [lattice, kernel] = kernel_on_lattice(o, o.kernel, o.lattice, o.sets);
    const auto result = run_assess(request, sources, kernel, lattice);
    if (o.json) print_json(assess_document(request, result), command_inputs(&kernel, &lattice));
    else print_assess(request, result);
    return 0;
}

} // namespace

Action add_assess_command(Command app)
{
    Command command = app.add_subcommand("assess", "One verdict on a setting (k, or an SPH code's own) on a lattice: "
                                                   "accuracy, stability and the recommended setting");
    auto options = std::make_shared<AssessOptions>();
    command.add_setting("kernel", options->kernel);
    command.add_setting("lattice", options->lattice);
    add_setting_options(command, options->setting);
    command.add_setting("kmin", options->k_min);
    command.add_setting("kmax", options->k_max);
    command.add_setting("epsilon", options->epsilon);
    command.add_setting("gamma", options->gamma);
    command.add_setting("coef_sound", options->coef_sound);
    command.add_setting("horizon", options->horizon);
    command.add_setting("glass", options->glass);
    add_evaluation_options(command, options->evaluation);
    command.add_setting("box", options->box);
    command.add_setting("array", options->array);
    add_parameter_ranges(command, options->ranges);
    command.add_setting("steps", options->steps);
    command.add_setting("threads", options->threads);
    command.add_setting("neighbours_by", options->neighbours_by);
    command.add_setting("bias_correction", options->bias_correction);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options, command] {
        if (source_kind(options->lattice) == SourceKind::file) {
            refuse_lattice_options(command, options->lattice);
            return assess_file(*options);
        }
        refuse_particle_file_options(command, options->ranges);
        return assess_lattice(*options);
    };
}

} // namespace sphkern::cli
