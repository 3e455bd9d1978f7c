// `sphkern kernels`: the kernels sphkern can find, with their metadata.
#include "cli/command.hpp"
#include "kernels/kernel_json.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>

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
        if (options->json) {
            nlohmann::json list = nlohmann::json::array();
            for (const auto& p : registry.plugins()) list.push_back(kernel_json(*p));
            print_json(list);
            return 0;
        }
        fmt::print(results_file(), "{:<20} {:>4} {:<6} {:<12} {}\n", "name", "R", "dims", "parameters", "reference / file");
        for (const auto& p : registry.plugins()) {
            std::string params;
            for (const auto& q : p->parameters) params += (params.empty() ? "" : ",") + q.name;
            fmt::print(results_file(), "{:<20} {:>4g} {:<6} {:<12} {}\n{:<46} {}\n", p->name, p->support, p->dimensions_text(),
                       params.empty() ? "-" : params, p->reference, "", p->source);
        }
        return 0;
    };
}

} // namespace sphkern::cli
