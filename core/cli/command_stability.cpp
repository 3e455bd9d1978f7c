// `sphkern stability`: the linear stability of SPH on a lattice at one k: the modes at a
// wave vector, or the Brillouin-zone scan with the long-wave sound speeds.
#include "cli/command.hpp"
#include "requests/stability_request.hpp"
#include "support/io/results_output.hpp"

#include "stability/brillouin_zone.hpp"
#include "stability/stability_json.hpp"
#include "stability/stability_over_k.hpp"
#include "stability/stability_scan.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

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

std::string vector_text(const nlohmann::json& v)
{
    std::string s;
    for (const auto& x : v) s += fmt::format("{}{:.6g}", s.empty() ? "" : ", ", x.get<double>());
    return "(" + s + ")";
}

// "stable", or "UNSTABLE: growth time 12.3 d/c, transverse mode at kappa = (...) / d" (or weak).
std::string verdict_text(const nlohmann::json& d)
{
    const std::string verdict = d["verdict"].get<std::string>();
    if (verdict == "stable") return verdict;
    std::string s = fmt::format("{} (horizon {:g} d/c): ", verdict == "unstable" ? "UNSTABLE" : "weak",
                                d["horizon"].get<double>());
    if (!d.contains("growth_time")) return s + "only long waves grow (omega^2 / kappa^2 < 0), ever more slowly as kappa -> 0";
    return s + fmt::format("growth time {:.4g} d/c, {} mode at kappa = {} / d (unfolded {})", d["growth_time"].get<double>(),
                           d["mode"]["kind"].get<std::string>(), vector_text(d["at"]),
                           vector_text(d["mode"]["unfolded_wavevector"]));
}

// "fixed", or "adaptive (eta 1.23, Omega 1.001)": the equilibrium h is k d in both.
std::string h_model_text(const nlohmann::json& d)
{
    if (!d.contains("eta")) return d["h_model"].get<std::string>();
    return fmt::format("adaptive (eta {:.6g}, grad-h factor {:.6g})", d["eta"].get<double>(),
                       d["grad_h_factor"].get<double>());
}

struct StabilityOptions : CommonOptions {
    std::string kernel, lattice, wavevector, h_model = "fixed";
    double k = 0, gamma = 5.0 / 3.0, k_min = 0, k_max = 0, horizon = default_horizon;
    int threads = 0, steps = 50;
    std::optional<int> grid, path;
    std::vector<std::string> sets;
};

void print_over_k(const nlohmann::json& document, const std::string& kernel, const std::string& lattice,
                  const StabilityOptions& options)
{
    auto intervals = [&](const nlohmann::json& list) {
        std::string s;
        for (const auto& i : list) s += fmt::format(" [{:.6f}, {:.6f}]", i[0].get<double>(), i[1].get<double>());
        return s.empty() ? fmt::format(" none of [{}, {}]", options.k_min, options.k_max) : s;
    };
    fmt::print(results_file(), "{} on {}, gamma = {:.6g}, {} h: stable for k in{}\n", kernel, lattice, options.gamma,
               options.h_model, intervals(document["stable_intervals"]));
    fmt::print(results_file(), "  no mode grows faster than the horizon ({:g} d/c) for k in{}\n", options.horizon,
               intervals(document["stable_at_horizon"]));
    fmt::print(results_file(), "  {:>10} {:>14} {:>9} {:>12} {}\n", "k", "min omega^2", "verdict", "growth time",
               "mode");
    for (const auto& p : document["samples"]) {
        const bool grows = p.contains("growth_time");
        fmt::print(results_file(), "  {:>10.6f} {:>14.6g} {:>9} {:>12} {}\n", p["k"].get<double>(),
                   p["min_omega2"].get<double>(), p["verdict"].get<std::string>(),
                   grows ? fmt::format("{:.4g}", p["growth_time"].get<double>()) : "",
                   grows ? p["mode"]["kind"].get<std::string>() : "");
    }
    if (!document["between"].empty())
        fmt::print(results_file(), "  k looked at between the samples, where a change could hide: {}\n",
                   document["between"].size());
    for (const auto& p : document["between"])
        if (p["verdict"] != "stable")
            fmt::print(results_file(), "  {:>10.6f} {:>14.6g} {:>9}\n", p["k"].get<double>(),
                       p["min_omega2"].get<double>(), p["verdict"].get<std::string>());
}

void print_path(const nlohmann::json& document, const std::string& kernel, const std::string& lattice,
                const StabilityOptions& options)
{
    const auto& path = document["path"];
    std::string labels;
    for (const auto& p : path["points"])
        labels += fmt::format("{}{} ({:.4f})", labels.empty() ? "" : " - ", p["label"].get<std::string>(),
                              p["at"].get<double>());
    fmt::print(results_file(), "{} on {} at k = {}, gamma = {:.6g}, {} h: omega^2 in (c/d)^2 along {}\n", kernel,
               lattice, options.k, options.gamma, options.h_model, labels);
    for (std::size_t i = 0; i < path["position"].size(); ++i) {
        fmt::print(results_file(), "  {:>10.6f}", path["position"][i].get<double>());
        for (const auto& w : path["omega2"][i]) fmt::print(results_file(), " {:>14.8g}", w.get<double>());
        fmt::print(results_file(), "\n");
    }
}

void print_modes(const nlohmann::json& document, const std::string& kernel, const std::string& lattice,
                 const StabilityOptions& options)
{
    fmt::print(results_file(), "{} on {} at k = {}, gamma = {:.6g}, {} h, kappa = {} / d\n", kernel, lattice,
               options.k, options.gamma, options.h_model, vector_text(document["wavevector"]));
    fmt::print(results_file(), "  {:>6} {:>16} {:>13}\n", "branch", "omega^2 (c/d)^2", "longitudinal");
    int b = 0;
    for (const auto& m : document["modes"])
        fmt::print(results_file(), "  {:>6} {:>16.10g} {:>13.4f}\n", b++, m["omega2"].get<double>(),
                   m["longitudinal"].get<double>());
}

void print_long_waves(const nlohmann::json& document)
{
    fmt::print(results_file(), "  long waves: lowest omega^2 / kappa^2 over every direction {:.6g} c^2 along {}\n",
               document["long_wave"]["min_omega2_over_kappa2"].get<double>(),
               vector_text(document["long_wave"]["direction"]));
    fmt::print(results_file(), "  long waves: speed / c - 1 of the longitudinal mode\n");
    for (const auto& s : document["sound_speed"]) {
        std::string relation;
        if (s.contains("pressure_term"))
            relation = fmt::format("  (eps_rho {:+.3e}, eps_gradP {:+.3e}, pressure term {:+.3e}, stiffness term {:+.3e})",
                                   s["eps_rho"].get<double>(), s["eps_gradp"].get<double>(),
                                   s["pressure_term"].get<double>(), s["stiffness_term"].get<double>());
        fmt::print(results_file(), "  {:<6} {:+.6e}{}\n", s["direction"].get<std::string>(),
                   s["longitudinal_error"].get<double>(), relation);
    }
}

void print_zone_scan(const nlohmann::json& document, const std::string& kernel, const Lattice& lattice,
                     const StabilityOptions& options)
{
    fmt::print(results_file(), "{} on {} ({} Bravais lattice) at k = {}, gamma = {:.6g}, {} h: {}\n", kernel,
               lattice.name, document["bravais"].get<std::string>(), options.k, options.gamma,
               h_model_text(document), verdict_text(document));
    const auto& zone = document["zone_scan"];
    fmt::print(results_file(), "  min omega^2 per branch over the Brillouin zone (last grid {}^{}, {} grids, lowest "
                               "branch {}):\n", zone["grid"].get<int>(), lattice.dimension, zone["grids"].get<int>(),
               zone["converged"].get<bool>() ? "settled within the tolerance" : "NOT settled");
    for (const auto& m : document["branches"])
        fmt::print(results_file(), "  branch {:>2}  {:>14.6g} (c/d)^2 at kappa = {} / d, longitudinal {:.3f}\n",
                   m["branch"].get<int>(), m["min_omega2"].get<double>(), vector_text(m["at"]),
                   m["longitudinal"].get<double>());
    print_long_waves(document);
}

// The text form of the document, for the request's mode.
void print_stability(const nlohmann::json& document, StabilityMode mode, const std::string& kernel,
                     const Lattice& lattice, const StabilityOptions& options)
{
    switch (mode) {
    case StabilityMode::path: return print_path(document, kernel, lattice.name, options);
    case StabilityMode::wavevector: return print_modes(document, kernel, lattice.name, options);
    case StabilityMode::over_k: return print_over_k(document, kernel, lattice.name, options);
    case StabilityMode::zone_scan: return print_zone_scan(document, kernel, lattice, options);
    }
}

// The command line's names for the request's values.
StabilitySources option_sources(const StabilityOptions& o)
{
    return {ValueSource::option("--k"),
            ValueSource::option("--kmin"),
            ValueSource::option("--kmax"),
            ValueSource::option("--gamma"),
            ValueSource::option("--horizon"),
            ValueSource::option("--wavevector " + one_line(o.wavevector)),
            ValueSource::option("--steps"),
            ValueSource::option("--grid"),
            ValueSource::option("--path"),
            " (or give --kmin and --kmax)"};
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
    Option path_option = command.add_option("--path", o.path, "Dispersion curves along the high-symmetry "
                                                             "path: about this many points");
    path_option.excludes(kmin_option).excludes(kmax_option);
    command.add_option("--grid", o.grid, "First zone grid, points per reciprocal axis (default 8 in 3D, 32 "
                                         "in 2D; doubled until the minimum settles)");
    command.add_option("--horizon", o.horizon, "Growth time in d/c: slower instabilities are weak").capture_default_str();
    command.add_option("--h-model", o.h_model, "Smoothing length: fixed (h = k d) or adaptive (h = eta "
                                               "(m/rho)^(1/D) with grad-h terms; k sets the equilibrium h = k d)")
        .capture_default_str();
    command.add_option("--threads", o.threads, "Threads (default: every core)").check_range(0, 1024);
}

} // namespace

Action add_stability_command(Command app)
{
    Command command = app.add_subcommand("stability", "Linear stability of SPH on a lattice: dispersion, Brillouin-zone "
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
        else print_stability(document, stability_mode(request), kernel.label(), lattice, *options);
        return 0;
    };
}

} // namespace sphkern::cli
