// `sphkern surface`: the error profile below a free surface, layer by layer.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "analysis/results_json.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

// The layers below the surface, then the bulk, as text.
void print_surface(const Kernel& kernel, const Lattice& lattice, double k, double a_p, GradientForm form,
                   const SurfaceProfile& profile)
{
    const bool one_site = lattice.sites() == 1;
    if (one_site)
        fmt::print(results_file(), "{} on {}, k = {}, a_p = {:.10g}, form {}, layer spacing {:.6f} d\n", kernel.label(),
                   lattice.name, k, a_p, gradient_form_name(form), profile.spacing);
    else {
        std::string names;
        for (std::size_t t = 0; t < profile.planes.types.size(); ++t)
            names += fmt::format("{}{}: {}", t ? ", " : "", t, profile.planes.name(static_cast<int>(t)));
        fmt::print(results_file(),
                   "{} on {}, k = {}, a_p = {:.10g}, form {}; the occupied planes repeat every {:.6f} d; "
                   "terminations {}; on top: {}\n",
                   kernel.label(), lattice.name, k, a_p, gradient_form_name(form), profile.spacing, names,
                   profile.termination);
    }
    fmt::print(results_file(), "{:>5} {:>10} {}{:>6} {:>14} {:>14}\n", "layer", "depth/d", one_site ? "" : " site",
               "N", "eps_rho", "eps_gradP");
    for (const auto& l : profile.layers)
        for (const auto& v : l.sites)
            fmt::print(results_file(), "{:>5} {:>10.5f} {}{:>6} {:>14.8f} {:>14.8f}\n", l.n, l.depth,
                       one_site ? "" : fmt::format("{:>5}", v.site), v.neighbours, v.eps_rho, v.eps_gradp);
    for (const auto& v : profile.bulk.sites)
        fmt::print(results_file(), "{:>5} {:>10} {}{:>6} {:>14.8f} {:>14.8f}\n", "bulk", "",
                   one_site ? "" : fmt::format("{:>5}", v.site), v.neighbours, v.eps_rho, v.eps_gradp);
    for (std::size_t s = 0; s < profile.first_moments.size(); ++s)
        if (profile.first_moments[s].norm() > 1e-9)
            fmt::print(results_file(),
                       "site {} is not a centre of inversion (first moment {:.3g}): with the sum form its gradient "
                       "error grows with depth by 2 P_i m1; the bulk row leaves that term out\n",
                       s, profile.first_moments[s].norm());
}

} // namespace

Action add_surface_command(CLI::App& app)
{
    auto* command = app.add_subcommand("surface", "Errors layer by layer below a free surface");
    struct Options : CommonOptions {
        std::string kernel, lattice, form = "sum";
        double k = 0;
        int layers = 4;
        std::optional<int> termination;
        std::vector<std::string> sets;
        EvaluationOptions evaluation;
    };
    auto options = std::make_shared<Options>();
    command->add_option("kernel", options->kernel, "Kernel name or plugin file")->required();
    command->add_option("lattice", options->lattice, "Lattice name or file")->required();
    command->add_option("--k", options->k, "Smoothing coefficient, h = k d")->required();
    command->add_option("--layers", options->layers, "Report at least this many layers")->capture_default_str();
    command->add_option("--form", options->form, "Gradient form: sum, difference or monaghan")->capture_default_str();
    command->add_option("--ap", options->evaluation.ap, "Volume coefficient: a name or a positive number")
        ->capture_default_str();
    command->add_option("--gravity", options->evaluation.gravity, "Gravity x,y[,z], normal to a lattice plane");
    command->add_option("--site", options->evaluation.site, "Motif site on the top layer")->capture_default_str();
    command->add_option("--termination", options->termination,
                        "Which plane type is on top (an index from the listed terminations; default: --site's)")
        ->check(CLI::NonNegativeNumber);
    add_set_option(*command, options->sets);
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    return [options] {
        auto form = parse_gradient_form(options->form);
        auto lattice = load_lattice(options->lattice);
        auto registry = discover_kernels(*options);
        auto kernel = make_kernel(registry, options->kernel, options->sets);
        double a_p = lattice.volume_coefficient(options->evaluation.ap);
        auto profile = surface_profile(kernel, lattice, options->evaluation.site, a_p,
                                       gravity_of(lattice, options->evaluation), options->k, options->layers, form,
                                       options->termination);
        if (options->json) {
            print_json(surface_document(kernel, lattice, options->k, a_p, form, profile), command_inputs(&kernel, &lattice));
            return 0;
        }
        print_surface(kernel, lattice, options->k, a_p, form, profile);
        return 0;
    };
}

} // namespace sphkern::cli
