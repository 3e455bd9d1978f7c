// `sphkern kernels`: the kernels sphkern can find, with their metadata.
#include "cli/command.hpp"
#include "requests/kernels_request.hpp"

#include <memory>

namespace sphkern::cli {

Action add_kernels_command(Command app)
{
    Command command = app.add_subcommand("kernels", "List the kernel plugins found");
    auto options = std::make_shared<CommonOptions>();
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        auto registry = discover_kernels(*options);
        if (options->json) print_json(kernels_listing(registry));
        else print_kernels(registry);
        return 0;
    };
}

} // namespace sphkern::cli
