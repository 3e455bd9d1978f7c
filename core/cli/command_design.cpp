// `sphkern design`: the (k, parameter) where both bulk errors vanish together.
#include "cli/command.hpp"
#include "requests/design_request.hpp"

#include "analysis/results_json.hpp"

#include <memory>

namespace sphkern::cli {

namespace {

struct DesignOptions : CommonOptions {
    std::string kernel, lattice, parameter;
    std::vector<double> range;
    double k_min = 0, k_max = 0; // the defaults: requests/settings
    int threads = 0;
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
};

DesignRequest request_from(const DesignOptions& o)
{
    DesignRequest r;
    r.parameter = o.parameter;
    if (o.range.size() == 2) r.range = std::pair(o.range[0], o.range[1]);
    r.k_min = o.k_min;
    r.k_max = o.k_max;
    r.evaluation = evaluation_inputs(o.evaluation);
    r.threads = o.threads;
    return r;
}

// The window refused as input (exit 3).
DesignSources option_sources(const DesignOptions& o)
{
    return {ValueSource::option("--kmin/--kmax"), evaluation_sources(o.evaluation), ValueSource::option("--threads")};
}

} // namespace

Action add_design_command(Command app)
{
    Command command = app.add_subcommand("design", "Find (k, parameter) where eps_rho and eps_gradP both vanish");
    auto options = std::make_shared<DesignOptions>();
    command.add_setting("kernel", options->kernel);
    command.add_setting("lattice", options->lattice);
    command.add_setting("param", options->parameter);
    command.add_setting("range", options->range).expected(2);
    command.add_setting("kmin", options->k_min);
    command.add_setting("kmax", options->k_max);
    command.add_setting("threads", options->threads);
    add_point_options(command, options->evaluation);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        const auto request = request_from(*options);
        const auto sources = option_sources(*options);
        check_design_request(request, sources);
        const auto [lattice, kernel] = kernel_on_lattice(*options, options->kernel, options->lattice, options->sets);
        const auto outcome = run_design(request, sources, kernel, lattice);
        if (options->json)
            print_json(design_json(kernel, outcome.problem, outcome.result), command_inputs(&kernel, &lattice));
        else print_design(outcome, kernel);
        return 0;
    };
}

} // namespace sphkern::cli
