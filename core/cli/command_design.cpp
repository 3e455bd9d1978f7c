// `sphkern design`: the (k, parameter) where both bulk errors vanish together.
#include "analysis/results_json.hpp"
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "analysis/design.hpp"
#include "analysis/results_json.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <tuple>

namespace sphkern::cli {

Action add_design_command(CLI::App& app)
{
    auto* command = app.add_subcommand("design", "Find (k, parameter) where eps_rho and eps_gradP both vanish");
    struct Options : CommonOptions {
        std::string kernel, lattice, parameter;
        std::vector<double> range;
        double k_min = 0.75, k_max = 1.25;
        std::vector<std::string> sets;
        EvaluationOptions evaluation;
    };
    auto options = std::make_shared<Options>();
    command->add_option("kernel", options->kernel, "Kernel (a blend A+B, or one with parameters)")->required();
    command->add_option("lattice", options->lattice, "Lattice name or file")->required();
    command->add_option("--param", options->parameter, "The parameter to vary (alpha for a blend)")->required();
    command->add_option("--range", options->range, "Parameter range A B (default: blends [-1, 2], else the declared range)")
        ->expected(2);
    command->add_option("--kmin", options->k_min, "Smallest k")->capture_default_str();
    command->add_option("--kmax", options->k_max, "Largest k")->capture_default_str();
    command->add_option("--ap", options->evaluation.ap, "Volume coefficient: a name or a positive number")
        ->capture_default_str();
    command->add_option("--gravity", options->evaluation.gravity, "Gravity x,y[,z] (default: the lattice's)");
    command->add_option("--site", options->evaluation.site, "Motif site")->capture_default_str();
    add_set_option(*command, options->sets);
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    return [options] {
        check_k_interval(options->k_min, options->k_max, ValueSource::argument("--kmin/--kmax"));
        auto lattice = load_lattice(options->lattice);
        auto registry = discover_kernels(*options);
        auto kernel = make_kernel(registry, options->kernel, options->sets);
        DesignProblem problem;
        problem.lattice = &lattice;
        problem.site = options->evaluation.site;
        problem.a_p = lattice.volume_coefficient(options->evaluation.ap);
        problem.gravity = gravity_of(lattice, options->evaluation);
        problem.k_min = options->k_min;
        problem.k_max = options->k_max;
        problem.parameter = options->parameter;
        std::tie(problem.parameter_min, problem.parameter_max) =
            options->range.size() == 2 ? std::pair(options->range[0], options->range[1])
                                       : default_parameter_range(kernel, options->parameter);
        auto result = design_kernel(kernel, problem);
        if (options->json) {
            print_json(design_json(kernel, problem, result), command_inputs(&kernel, &lattice));
            return 0;
        }
        fmt::print(results_file(), "{} on {}, a_p = {:.10g}: both errors zero for {} in [{}, {}], k in [{}, {}]\n", kernel.name(),
                   lattice.name, problem.a_p, problem.parameter, problem.parameter_min, problem.parameter_max,
                   problem.k_min, problem.k_max);
        if (result.solutions.empty()) fmt::print(results_file(), "{}\n", result.note);
        else
            fmt::print(results_file(), "{:>14} {:>16} {:>10} {:>10} {:>9} {:>11} {:>11} {:>8}\n", "k", problem.parameter, "eps_rho",
                       "eps_gradP", "cond(J)", "dk(a_p+1%)", "dpar", "W >= 0");
        for (const auto& s : result.solutions)
            fmt::print(results_file(), "{:>14.10f} {:>16.10f} {:>10.1e} {:>10.1e} {:>9.3g} {:>+11.2e} {:>+11.2e} {:>8}\n", s.k, s.parameter,
                       s.values.eps_rho, s.values.eps_gradp, s.jacobian_condition, s.k_shift, s.parameter_shift,
                       s.non_negative ? "yes" : "no");
        return 0;
    };
}

} // namespace sphkern::cli
