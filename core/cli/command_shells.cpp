// `sphkern shells`: the neighbour shells of a lattice site.
#include "cli/command.hpp"
#include "lattices/lattice_json.hpp"
#include "lattices/numeric_inputs.hpp"
#include "support/io/results_output.hpp"

#include "lattices/shells.hpp"

#include <fmt/format.h>

#include <memory>

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
    command.add_option("lattice", options->lattice, "Lattice name or file").required();
    command.add_option("--radius", options->radius, "Largest radius, in units of d").required();
    command.add_option("--site", options->site, "Motif site").capture_default_str();
    command.add_option("--gravity", options->gravity, "Direction for the moments (default: the lattice's)");
    add_json_option(command, *options);
    add_plugin_option(command, *options);
    return [options] {
        if (!options->plugins.empty()) discover_kernels(*options); // validated like everywhere
        auto lattice = load_lattice(options->lattice);
        Eigen::Vector3d e = options->gravity.empty()
                                ? lattice.gravity
                                : direction_of(parse_number_list(options->gravity, ValueSource::option("--gravity")),
                                               lattice.dimension, ValueSource::option("--gravity"));
        if (options->json) {
            print_json(shells_json(lattice, options->site, options->radius, e), command_inputs(nullptr, &lattice));
            return 0;
        }
        auto shells = lattice_shells(lattice, options->site, options->radius);
        fmt::print(results_file(), "{:>12} {:>10} {:>6} {:>10} {:>14}\n", "radius/d", "radius^2", "count", "total", "sum (e.r^)^2");
        int total = 0;
        for (const auto& s : shells) {
            total += s.count;
            fmt::print(results_file(), "{:>12.8f} {:>10.6f} {:>6} {:>10} {:>14.8f}\n", s.radius, s.radius * s.radius, s.count, total,
                       s.directional_moment(e));
        }
        return 0;
    };
}

} // namespace sphkern::cli
