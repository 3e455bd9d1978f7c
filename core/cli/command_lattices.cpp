// `sphkern lattices`: the shipped lattices, their volume coefficients and gravity.
#include "cli/command.hpp"
#include "analysis/results_json.hpp"
#include "support/results_output.hpp"

#include <fmt/format.h>

#include <memory>

namespace sphkern::cli {

Action add_lattices_command(CLI::App& app)
{
    auto* command = app.add_subcommand("lattices", "List the shipped lattices");
    auto options = std::make_shared<CommonOptions>();
    add_json_option(*command, *options);
    add_plugin_option(*command, *options);
    return [options] {
        if (!options->plugins.empty()) discover_kernels(*options); // validated like everywhere
        nlohmann::json list = nlohmann::json::array();
        for (const auto& name : shipped_lattice_names()) list.push_back(lattice_json(load_lattice(name)));
        if (options->json) {
            print_json(list);
            return 0;
        }
        fmt::print(results_file(), "{:<12} {:>3} {:>5}  {:<44} {}\n", "name", "D", "sites", "a_p variants", "gravity");
        for (const auto& l : list) {
            std::string coefficients, gravity;
            for (const auto& [name, value] : l["volume_coefficients"].items())
                coefficients += fmt::format("{}{}={:.6g}", coefficients.empty() ? "" : " ", name, value.get<double>());
            for (double g : l["gravity"]) gravity += fmt::format("{}{:.4g}", gravity.empty() ? "" : ",", g);
            fmt::print(results_file(), "{:<12} {:>3} {:>5}  {:<44} {}\n", l["name"].get<std::string>(), l["dimension"].get<int>(),
                       l["sites"].get<int>(), coefficients, gravity);
        }
        return 0;
    };
}

} // namespace sphkern::cli
