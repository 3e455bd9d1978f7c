// `sphkern eps`: both bulk errors of one kernel on one lattice at one k.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "requests/eps_request.hpp"
#include "support/error.hpp"

#include <memory>

namespace sphkern::cli {

namespace {

struct EpsOptions : CommonOptions {
    std::string kernel, lattice;
    SettingOptions setting;
    std::string axis; // the default: requests/settings
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
};

EpsRequest request_from(const EpsOptions& o)
{
    EpsRequest r;
    r.code = code_setting(o.setting);
    if (r.code && o.axis != "k")
        throw Error(ExitCode::usage, "--axis is the scale of --k; --code gives the code's own setting");
    if (o.setting.k) r.k = {*o.setting.k};
    r.axis = parse_axis(o.axis, "--axis");
    r.evaluation = evaluation_inputs(o.evaluation);
    return r;
}

EpsSources option_sources(const EpsOptions& o)
{
    const auto [code, value] = code_sources(o.setting);
    return {ValueSource::option("--k"), ValueSource::option("--axis"), evaluation_sources(o.evaluation), code, value};
}

} // namespace

Action add_eps_command(Command app)
{
    Command command = app.add_subcommand("eps", "eps_rho and eps_gradP of a kernel on a lattice at one k");
    auto options = std::make_shared<EpsOptions>();
    command.add_setting("kernel", options->kernel);
    command.add_setting("lattice", options->lattice);
    add_setting_options(command, options->setting);
    command.add_setting("axis", options->axis);
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
