// `sphkern studies`: the shipped studies, each with its title and what it runs.
#include "cli/command.hpp"
#include "requests/studies_request.hpp"

#include <memory>

namespace sphkern::cli {

Action add_studies_command(Command app)
{
    Command command = app.add_subcommand("studies", "List the shipped studies (run them with sphkern run NAME)");
    auto options = std::make_shared<CommonOptions>();
    add_json_option(command, *options);
    return [options] {
        const auto listing = studies_listing();
        if (options->json) print_json(listing);
        else print_studies(listing);
        return 0;
    };
}

} // namespace sphkern::cli
