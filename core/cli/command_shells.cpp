// `sphkern shells`: the neighbour shells of a lattice site.
#include "cli/command.hpp"
#include "requests/shells_request.hpp"

#include <memory>
#include <optional>

namespace sphkern::cli {

Action add_shells_command(Command app)
{
    Command command = app.add_subcommand("shells", "Neighbour shells of a lattice site up to a radius");
    struct Options : CommonOptions {
        std::string lattice;
        double radius = 0;
        int site = 0;
        std::string gravity;
    };
    auto options = std::make_shared<Options>();
    command.add_setting("lattice", options->lattice);
    command.add_setting("radius", options->radius);
    command.add_setting("site", options->site);
    command.add_setting("gravity", options->gravity);
    add_json_option(command, *options);
    add_plugin_option(command, *options);
    return [options] {
        if (!options->plugins.empty()) discover_kernels(*options); // validated like everywhere
        const auto lattice = load_lattice(options->lattice);
        ShellsRequest request{options->radius, options->site, std::nullopt};
        if (!options->gravity.empty())
            request.gravity = parse_number_list(options->gravity, ValueSource::option("--gravity"));
        const ShellsResult result = run_shells(request, shells_sources(FrontEnd::command_line), lattice);
        if (options->json) print_json(shells_json(result), command_inputs(nullptr, &lattice));
        else print_shells(result);
        return 0;
    };
}

} // namespace sphkern::cli
