// `sphkern surface`: the error profile below a free surface, layer by layer.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "requests/surface_request.hpp"

#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

struct SurfaceOptions : CommonOptions {
    std::string kernel, lattice, form; // the defaults: requests/settings
    SettingOptions setting;
    int layers = 0;
    std::optional<int> termination;
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
};

SurfaceRequest request_from(const SurfaceOptions& o)
{
    SurfaceRequest r;
    r.code = code_setting(o.setting);
    if (!r.code) r.k = *o.setting.k;
    r.layers = o.layers;
    r.form = parse_gradient_form(o.form);
    r.termination = o.termination;
    r.evaluation = evaluation_inputs(o.evaluation);
    return r;
}

SurfaceSources option_sources(const SurfaceOptions& o)
{
    const auto [code, code_value] = code_sources(o.setting);
    return {ValueSource::option("--k"), evaluation_sources(o.evaluation), ValueSource::option("--layers"), code,
            code_value};
}

} // namespace

Action add_surface_command(Command app)
{
    Command command = app.add_subcommand("surface", "Errors layer by layer below a free surface");
    auto options = std::make_shared<SurfaceOptions>();
    command.add_setting("kernel", options->kernel);
    command.add_setting("lattice", options->lattice);
    add_setting_options(command, options->setting);
    command.add_setting("layers", options->layers);
    command.add_setting("form", options->form);
    add_point_options(command, options->evaluation);
    command.add_setting("termination", options->termination).check_non_negative();
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        const auto request = request_from(*options);
        const auto sources = option_sources(*options);
        check_surface_request(request, sources);
        const auto [lattice, kernel] = kernel_on_lattice(*options, options->kernel, options->lattice, options->sets);
        const auto result = run_surface(request, sources, kernel, lattice);
        if (options->json)
            print_json(surface_request_document(request, result, kernel, lattice), command_inputs(&kernel, &lattice));
        else print_surface(request, result, kernel, lattice);
        return 0;
    };
}

} // namespace sphkern::cli
