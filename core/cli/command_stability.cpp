// `sphkern stability`: the linear stability of SPH on a lattice at one k: the modes at a
// wave vector, or the Brillouin-zone scan with the long-wave sound speeds.
#include "cli/command.hpp"
#include "requests/stability_report.hpp"
#include "requests/stability_request.hpp"

#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

// "x,y[,z]" in 1/d: finite numbers (their count and length are checked with the lattice).
std::vector<double> parse_wavevector(const std::string& text)
{
    try {
        return parse_number_list(text, ValueSource::option("--wavevector"), 0);
    } catch (const Error& e) {
        throw Error(e.code(), std::string(e.what()) + "; expected comma-separated numbers in 1/d");
    }
}

struct StabilityOptions : CommonOptions {
    std::string kernel, lattice, wavevector, h_model = "fixed", code;
    double k = 0, gamma = 5.0 / 3.0, k_min = 0, k_max = 0, horizon = default_horizon;
    int threads = 0, steps = 50;
    std::optional<int> grid, path;
    std::vector<std::string> sets;
};

// The command line's names for the request's values.
StabilitySources option_sources(const StabilityOptions& o)
{
    return {ValueSource::option("--k"),       ValueSource::option("--kmin"),
            ValueSource::option("--kmax"),    ValueSource::option("--gamma"),
            ValueSource::option("--horizon"), ValueSource::option("--wavevector " + one_line(o.wavevector)),
            ValueSource::option("--steps"),   ValueSource::option("--grid"),
            ValueSource::option("--path"),    " (or give --kmin and --kmax)"};
}

// The adapter: the text of the wave vector and h model (the request checks which options go together).
StabilityRequest request_from(const StabilityOptions& o)
{
    StabilityRequest r;
    if (o.k_max > 0 || o.k_min > 0) {
        r.k_min = o.k_min;
        r.k_max = o.k_max;
    } else {
        r.k = o.k; // 0 when not given: refused as out of range, with the k range as the other choice
    }
    r.steps = o.steps;
    if (!o.wavevector.empty()) r.wavevector = parse_wavevector(o.wavevector);
    r.path_points = o.path;
    r.gamma = o.gamma;
    r.horizon = o.horizon;
    r.h_model = parse_h_model(o.h_model, "--h-model");
    r.grid = o.grid;
    r.threads = o.threads;
    if (!o.code.empty()) {
        if (!r.k_min)
            throw Error(ExitCode::usage,
                        "--code gives the stable intervals over k in a code's setting; expected --kmin and --kmax");
        r.code = &code_profile(o.code, ValueSource::option("--code"));
    }
    return r;
}

void add_stability_options(Command command, StabilityOptions& o)
{
    Option k_option = command.add_option("--k", o.k, "Smoothing coefficient, h = k d");
    Option kmin_option = command.add_option("--kmin", o.k_min, "Scan k from here (with --kmax): stable intervals");
    Option kmax_option = command.add_option("--kmax", o.k_max, "Scan k up to here");
    command.add_option("--steps", o.steps, "Intervals of the k scan").capture_default_str();
    k_option.excludes(kmin_option).excludes(kmax_option);
    kmin_option.needs(kmax_option);
    kmax_option.needs(kmin_option);
    command.add_option("--gamma", o.gamma, "Adiabatic index of P = rho c^2 / gamma").capture_default_str();
    command.add_option("--wavevector", o.wavevector, "Cartesian wave vector x,y[,z] in 1/d: the modes there");
    Option path_option = command.add_option("--path", o.path,
                                            "Dispersion curves along the high-symmetry "
                                            "path: about this many points");
    path_option.excludes(kmin_option).excludes(kmax_option);
    command.add_option("--grid", o.grid,
                       "First zone grid, points per reciprocal axis (default 8 in 3D, 32 "
                       "in 2D; doubled until the minimum settles)");
    command.add_option("--horizon", o.horizon, "Growth time in d/c: slower instabilities are weak")
        .capture_default_str();
    command
        .add_option("--h-model", o.h_model,
                    "Smoothing length: fixed (h = k d) or adaptive (h = eta "
                    "(m/rho)^(1/D) with grad-h terms; k sets the equilibrium h = k d)")
        .capture_default_str();
    command.add_option("--threads", o.threads, "Threads (default: every core)").check_range(0, 1024);
    command.add_option("--code", o.code,
                       "With --kmin/--kmax: the stable intervals also in an SPH code's own setting, "
                       "with its own density: swift, phantom, gadget2, gadget4, pysph or dualsphysics");
}

} // namespace

Action add_stability_command(Command app)
{
    Command command =
        app.add_subcommand("stability", "Linear stability of SPH on a lattice: dispersion, Brillouin-zone "
                                        "scan, long-wave sound speed");
    auto options = std::make_shared<StabilityOptions>();
    command.add_option("kernel", options->kernel, "Kernel name or plugin file").required();
    command.add_option("lattice", options->lattice, "Lattice name or file").required();
    add_stability_options(command, *options);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        const auto request = request_from(*options);
        const auto sources = option_sources(*options);
        check_stability_request(request, sources);
        const auto [lattice, kernel] = kernel_on_lattice(*options, options->kernel, options->lattice, options->sets);
        const auto document = run_stability(request, sources, kernel, lattice);
        if (options->json) print_json(document);
        else print_stability(document, request, kernel.label(), lattice);
        return 0;
    };
}

} // namespace sphkern::cli
