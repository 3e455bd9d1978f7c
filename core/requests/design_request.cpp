#include "requests/design_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "support/io/results_output.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>

#include <tuple>

namespace sphkern {

void check_design_request(const DesignRequest& r, const DesignSources& sources)
{
    check_k_interval(r.k_min, r.k_max, sources.window);
    check_evaluation(r.evaluation, sources.evaluation);
    check_setting(settings_of("design")["threads"], r.threads, sources.threads);
}

DesignOutcome run_design(const DesignRequest& r, const DesignSources& sources, const Kernel& kernel,
                         const Lattice& lattice)
{
    const auto evaluation = resolve_evaluation(r.evaluation, sources.evaluation, lattice);
    DesignOutcome outcome;
    auto& problem = outcome.problem;
    problem.lattice = &lattice;
    problem.site = evaluation.site;
    problem.a_p = evaluation.a_p;
    problem.gravity = evaluation.gravity;
    problem.k_min = r.k_min;
    problem.k_max = r.k_max;
    problem.parameter = r.parameter;
    problem.threads = worker_threads(r.threads);
    std::tie(problem.parameter_min, problem.parameter_max) =
        r.range ? *r.range : default_parameter_range(kernel, r.parameter);
    outcome.result = design_kernel(kernel, problem);
    return outcome;
}

void print_design(const DesignOutcome& outcome, const Kernel& kernel)
{
    const auto& problem = outcome.problem;
    const auto& result = outcome.result;
    fmt::print(results_file(), "{} on {}, a_p = {:.10g}: both errors zero for {} in [{}, {}], k in [{}, {}]\n",
               kernel.name(), problem.lattice->name, problem.a_p, problem.parameter, problem.parameter_min,
               problem.parameter_max, problem.k_min, problem.k_max);
    if (result.solutions.empty()) fmt::print(results_file(), "{}\n", result.note);
    else
        fmt::print(results_file(), "{:>14} {:>16} {:>10} {:>10} {:>9} {:>11} {:>11} {:>8}\n", "k", problem.parameter,
                   "eps_rho", "eps_gradP", "cond(J)", "dk(a_p+1%)", "dpar", "W >= 0");
    for (const auto& s : result.solutions)
        fmt::print(results_file(), "{:>14.10f} {:>16.10f} {:>10.1e} {:>10.1e} {:>9.3g} {:>+11.2e} {:>+11.2e} {:>8}\n",
                   s.k, s.parameter, s.values.eps_rho, s.values.eps_gradp, s.jacobian_condition, s.k_shift,
                   s.parameter_shift, s.non_negative ? "yes" : "no");
}

} // namespace sphkern
