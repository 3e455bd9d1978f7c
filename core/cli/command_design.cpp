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
    double k_min = 0.75, k_max = 1.25;
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
    return {ValueSource::option("--kmin/--kmax"), evaluation_sources(o.evaluation)};
}

} // namespace

Action add_design_command(Command app)
{
    Command command = app.add_subcommand("design", "Find (k, parameter) where eps_rho and eps_gradP both vanish");
    auto options = std::make_shared<DesignOptions>();
    command.add_option("kernel", options->kernel, "Kernel (a blend A+B, or one with parameters)").required();
    command.add_option("lattice", options->lattice, "Lattice name or file").required();
    command.add_option("--param", options->parameter, "The parameter to vary (alpha for a blend)").required();
    command
        .add_option("--range", options->range, "Parameter range A B (default: blends [-1, 2], else the declared range)")
        .expected(2);
    command.add_option("--kmin", options->k_min, "Smallest k").capture_default_str();
    command.add_option("--kmax", options->k_max, "Largest k").capture_default_str();
    command.add_option("--threads", options->threads, "Threads of the scan along the parameter (default: every core)")
        .check_range(0, 1024);
    add_point_options(command, options->evaluation, "Gravity x,y[,z] (default: the lattice's)", "Motif site");
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
