// `sphkern eps`: both bulk errors of one kernel on one lattice at one k.
#include "cli/command.hpp"
#include "analysis/code_profiles.hpp"
#include "requests/eps_request.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

struct EpsOptions : CommonOptions {
    std::string kernel, lattice, code;
    std::optional<double> k;
    // A code's own setting, with --code (analysis/code_profiles): each code's parameter by its name.
    std::optional<double> eta, hfact, nngb, hdx, coefh;
    std::string axis = "k";
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
};

// The code's setting: its parameter's option, given only with --code and alone.
std::optional<CodeSetting> code_setting(const EpsOptions& o)
{
    const std::pair<const char*, const std::optional<double>*> given[] = {
        {"eta", &o.eta}, {"hfact", &o.hfact}, {"nngb", &o.nngb}, {"hdx", &o.hdx}, {"coefh", &o.coefh}};
    std::optional<CodeSetting> setting;
    for (const auto& [name, value] : given) {
        if (!value->has_value()) continue;
        if (o.code.empty()) throw Error(ExitCode::usage, fmt::format("--{} is a code's setting; expected --code too", name));
        const auto& profile = code_profile(o.code, ValueSource::option("--code"));
        if (profile.parameter != name)
            throw Error(ExitCode::usage, fmt::format("--{}: {} sets its resolution with --{}", name, o.code, profile.parameter));
        if (o.k) throw Error(ExitCode::usage, fmt::format("give one of --k and --{}", name));
        setting = CodeSetting{o.code, **value};
    }
    if (!o.code.empty() && !setting)
        throw Error(ExitCode::usage, fmt::format("--code {}: expected its setting, --{}", o.code,
                                                 code_profile(o.code, ValueSource::option("--code")).parameter));
    if (!setting && !o.k) throw Error(ExitCode::usage, "--k is required (or --code and the code's setting)");
    return setting;
}

EpsRequest request_from(const EpsOptions& o)
{
    EpsRequest r;
    r.code = code_setting(o);
    if (r.code && o.axis != "k") throw Error(ExitCode::usage, "--axis is the scale of --k; --code gives the code's own setting");
    if (o.k) r.k = {*o.k};
    r.axis = parse_axis(o.axis, "--axis");
    r.evaluation = evaluation_inputs(o.evaluation);
    return r;
}

EpsSources option_sources(const EpsOptions& o)
{
    const std::string parameter = o.code.empty() ? "" : code_profile(o.code, ValueSource::option("--code")).parameter;
    return {ValueSource::option("--k"), ValueSource::option("--axis"), evaluation_sources(o.evaluation),
            ValueSource::option("--code"), ValueSource::option("--" + parameter)};
}

} // namespace

Action add_eps_command(Command app)
{
    Command command = app.add_subcommand("eps", "eps_rho and eps_gradP of a kernel on a lattice at one k");
    auto options = std::make_shared<EpsOptions>();
    command.add_option("kernel", options->kernel, "Kernel name or plugin file").required();
    command.add_option("lattice", options->lattice, "Lattice name or file").required();
    command.add_option("--k", options->k, "Smoothing coefficient, h = k d (or --code and the code's own setting)");
    command.add_option("--code", options->code, "Give the resolution as an SPH code sets it: swift, phantom, gadget2, "
                                                "gadget4, pysph or dualsphysics, with its parameter below");
    command.add_option("--eta", options->eta, "With --code swift: SWIFT's eta, h = eta (m / rho)^(1/D)");
    command.add_option("--hfact", options->hfact, "With --code phantom: Phantom's hfact, h = hfact (m / rho)^(1/D)");
    command.add_option("--nngb", options->nngb, "With --code gadget2 or gadget4: the weighted neighbour number");
    command.add_option("--hdx", options->hdx, "With --code pysph: PySPH's hdx, h = hdx dx");
    command.add_option("--coefh", options->coefh, "With --code dualsphysics: DualSPHysics' coefh, h = coefh sqrt(D) dp");
    command.add_option("--axis", options->axis, "The scale of --k: k (h/d) or eta (h/V^(1/D))").capture_default_str();
    add_evaluation_options(command, options->evaluation);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        const auto sources = option_sources(*options);
        const auto request = request_from(*options);
        check_eps_request(request, sources);
        const auto [lattice, kernel] = kernel_on_lattice(*options, options->kernel, options->lattice, options->sets);
        const auto result = run_eps_at_k(request, sources, kernel, lattice);
        if (options->json) print_json(eps_document(result), command_inputs(&kernel, &lattice));
        else print_eps(result);
        return 0;
    };
}

} // namespace sphkern::cli
