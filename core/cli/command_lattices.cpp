// `sphkern lattices`: the shipped lattices, their volume coefficients and gravity, and the examples.
#include "cli/command.hpp"
#include "requests/lattices_request.hpp"

#include <memory>

namespace sphkern::cli {

Action add_lattices_command(Command app)
{
    Command command =
        app.add_subcommand("lattices", "List the shipped lattices, or describe the ones named (or files)");
    struct Options : CommonOptions {
        std::vector<std::string> lattices;
        double radius = 0; // the default: requests/settings
    };
    auto options = std::make_shared<Options>();
    command.add_setting("lattice", options->lattices);
    command.add_setting("radius", options->radius);
    add_json_option(command, *options);
    add_plugin_option(command, *options);
    return [options] {
        if (!options->plugins.empty()) discover_kernels(*options); // validated like everywhere
        if (options->lattices.empty()) {
            const auto listing = lattices_listing();
            if (options->json) print_json(listing);
            else print_lattices(listing);
            return 0;
        }
        const ValueSource radius = value_named(FrontEnd::command_line, "radius");
        nlohmann::json list = nlohmann::json::array();
        for (const auto& spec : options->lattices) {
            const auto lattice = load_lattice(spec);
            list.push_back(lattice_description(lattice, options->radius, radius));
            if (!options->json) print_lattice_description(lattice, list.back());
        }
        if (options->json) print_json(list);
        return 0;
    };
}

} // namespace sphkern::cli
