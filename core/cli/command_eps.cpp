// `sphkern eps`: both bulk errors of one kernel on one lattice at one k.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "analysis/resolution_axis.hpp"
#include "analysis/site_errors.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>

namespace sphkern::cli {

namespace {

// Every site's values, when the lattice has more than one.
void print_every_site(const std::vector<SiteReport>& reports, int chosen, std::size_t worst)
{
    if (reports.size() <= 1) return;
    fmt::print(results_file(), "every site (the values above are site {}; worst site {}):\n", chosen,
               reports[worst].site);
    fmt::print(results_file(), "  {:>4} {:>14} {:>14} {:>10} {:>5}  {:<34} {}\n", "site", "eps_rho", "eps_gradP",
               "lateral", "N_H", "eigenvalues of E", "|first moment|");
    for (const auto& r : reports) {
        std::string eigen;
        for (double e : r.gradient.eigenvalues) eigen += fmt::format("{}{:+.6f}", eigen.empty() ? "" : " ", e);
        fmt::print(results_file(), "  {:>4} {:>14.8f} {:>14.8f} {:>10.3g} {:>5}  {:<34} {:.3g}\n", r.site,
                   r.values.eps_rho, r.values.eps_gradp, r.values.lateral, r.values.neighbours, eigen,
                   r.gradient.first_moment.norm());
    }
}

} // namespace

Action add_eps_command(CLI::App& app)
{
    auto* command = app.add_subcommand("eps", "eps_rho and eps_gradP of a kernel on a lattice at one k");
    struct Options : CommonOptions {
        std::string kernel, lattice;
        double k = 0;
        std::string axis = "k";
        std::vector<std::string> sets;
        EvaluationOptions evaluation;
    };
    auto options = std::make_shared<Options>();
    command->add_option("kernel", options->kernel, "Kernel name or plugin file")->required();
    command->add_option("lattice", options->lattice, "Lattice name or file")->required();
    command->add_option("--k", options->k, "Smoothing coefficient, h = k d")->required();
    command->add_option("--axis", options->axis, "The scale of --k: k (h/d) or eta (h/V^(1/D))")->capture_default_str();
    add_evaluation_options(*command, options->evaluation);
    add_set_option(*command, options->sets);
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    return [options] {
        check_k(options->k, ValueSource::option("--k"));
        auto lattice = load_lattice(options->lattice);
        auto registry = discover_kernels(*options);
        auto kernel = make_kernel(registry, options->kernel, options->sets);
        double a_p = lattice.volume_coefficient(options->evaluation.ap);
        check_sites(lattice, {options->evaluation.site}, "--site");
        const Axis axis = parse_axis(options->axis, "--axis");
        if (axis == Axis::nh) fail_input("--axis nh names a window, not one value: give --k on the k or eta axis");
        const double given = options->k;
        if (axis == Axis::eta) options->k = k_of_eta(given, a_p, lattice.dimension);
        if (!k_in_range(options->k))
            fail_input(fmt::format("--k {} on the eta axis is k = {}, expected k in (0, 100]", given, options->k));
        const double eta = eta_of_k(options->k, a_p, lattice.dimension);
        // Every site: the top-level values describe the one chosen with --site.
        auto sites = errors_per_site(kernel, lattice, every_site(lattice), a_p, gravity_of(lattice, options->evaluation),
                                     options->k, evaluation_mode(options->evaluation));
        std::vector<SiteReport> reports;
        for (const auto& s : sites) reports.push_back(site_report(*s, options->k));
        const auto& v = reports[static_cast<std::size_t>(options->evaluation.site)].values;
        const std::size_t worst = worst_site(reports);
        if (options->json) {
            nlohmann::json per_site = nlohmann::json::array();
            for (const auto& r : reports) per_site.push_back(site_report_json(r, lattice.dimension));
            print_json({{"kernel", kernel.label()}, {"lattice", lattice.name}, {"k", options->k}, {"a_p", a_p},
                        {"eta", eta}, {"site", options->evaluation.site}, {"eps_rho", v.eps_rho}, {"eps_gradp", v.eps_gradp},
                        {"lateral", v.lateral}, {"neighbours", v.neighbours},
                        {"support_radius", kernel.support() * options->k}, {"sites", per_site},
                        {"worst_site", reports[worst].site}},
                       command_inputs(&kernel, &lattice));
            return 0;
        }
        fmt::print(results_file(), "{} on {} at k = {}, a_p = {:.10g}{}\n", kernel.label(), lattice.name, options->k, a_p,
                   axis == Axis::eta ? fmt::format(" (eta = {:.10g})", eta) : "");
        fmt::print(results_file(), "  eps_rho    {:.12g}\n  eps_gradP  {:.12g}\n  lateral    {:.3g}\n  N_H        {}\n  H/d        {:.10g}\n",
                   v.eps_rho, v.eps_gradp, v.lateral, v.neighbours, kernel.support() * options->k);
        print_every_site(reports, options->evaluation.site, worst);
        return 0;
    };
}

} // namespace sphkern::cli
