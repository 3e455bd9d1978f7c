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
    std::string kernel, lattice, wavevector, h_model, code; // the defaults: requests/settings
    std::optional<double> k, k_min, k_max; // none given: refused as k = 0, with the k range as the other choice
    double gamma = 0, horizon = 0;
    int threads = 0, steps = 0;
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
            ValueSource::option("--path"),    " (or give --kmin and --kmax)",
            ValueSource::option("--threads")};
}

// The adapter: the text of the wave vector and h model (the request checks which options go together).
StabilityRequest request_from(const StabilityOptions& o)
{
    StabilityRequest r;
    if (o.k_min || o.k_max) {
        r.k_min = o.k_min.value_or(0);
        r.k_max = o.k_max.value_or(0);
    } else {
        r.k = o.k.value_or(0);
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
    Option k_option = command.add_setting("k", o.k);
    Option kmin_option = command.add_setting("kmin", o.k_min);
    Option kmax_option = command.add_setting("kmax", o.k_max);
    command.add_setting("steps", o.steps);
    k_option.excludes(kmin_option).excludes(kmax_option);
    kmin_option.needs(kmax_option);
    kmax_option.needs(kmin_option);
    command.add_setting("gamma", o.gamma);
    command.add_setting("wavevector", o.wavevector);
    Option path_option = command.add_setting("path", o.path);
    path_option.excludes(kmin_option).excludes(kmax_option);
    command.add_setting("grid", o.grid);
    command.add_setting("horizon", o.horizon);
    command.add_setting("h_model", o.h_model);
    command.add_setting("threads", o.threads);
    command.add_setting("code", o.code);
}

} // namespace

Action add_stability_command(Command app)
{
    Command command =
        app.add_subcommand("stability", "Linear stability of SPH on a lattice: dispersion, Brillouin-zone "
                                        "scan, long-wave sound speed");
    auto options = std::make_shared<StabilityOptions>();
    command.add_setting("kernel", options->kernel);
    command.add_setting("lattice", options->lattice);
    add_stability_options(command, *options);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        const auto request = request_from(*options);
        const auto sources = option_sources(*options);
        check_stability_request(request, sources);
        const auto [lattice, kernel] = kernel_on_lattice(*options, options->kernel, options->lattice, options->sets);
        const StabilityResult result = run_stability(request, sources, kernel, lattice);
        if (options->json) print_json(stability_json(result));
        else print_stability(result, request, kernel.label(), lattice);
        return 0;
    };
}

} // namespace sphkern::cli
