#include "requests/stability_report.hpp"

#include "stability/h_model.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sphkern {

namespace {

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
    std::string s =
        fmt::format("{} (horizon {:g} d/c): ", verdict == "unstable" ? "UNSTABLE" : "weak", d["horizon"].get<double>());
    if (!d.contains("growth_time"))
        return s + "only long waves grow (omega^2 / kappa^2 < 0), ever more slowly as kappa -> 0";
    return s + fmt::format("growth time {:.4g} d/c, {} mode at kappa = {} / d (unfolded {})",
                           d["growth_time"].get<double>(), d["mode"]["kind"].get<std::string>(), vector_text(d["at"]),
                           vector_text(d["mode"]["unfolded_wavevector"]));
}

// "fixed", or "adaptive (h/l 1.23, Omega 1.001)": the equilibrium h is k d in both.
std::string h_model_text(const nlohmann::json& d)
{
    if (!d.contains("h_over_l")) return d["h_model"].get<std::string>();
    return fmt::format("adaptive (h/l {:.6g}, grad-h factor {:.6g})", d["h_over_l"].get<double>(),
                       d["grad_h_factor"].get<double>());
}

void print_over_k(const nlohmann::json& document, const std::string& kernel, const std::string& lattice,
                  const StabilityRequest& options)
{
    auto intervals = [&](const nlohmann::json& list) {
        std::string s;
        for (const auto& i : list) s += fmt::format(" [{:.6f}, {:.6f}]", i[0].get<double>(), i[1].get<double>());
        return s.empty() ? fmt::format(" none of [{}, {}]", *options.k_min, *options.k_max) : s;
    };
    fmt::print(results_file(), "{} on {}, gamma = {:.6g}, {} h: stable for k in{}\n", kernel, lattice, options.gamma,
               h_model_name(options.h_model), intervals(document["stable_intervals"]));
    fmt::print(results_file(), "  no mode grows faster than the horizon ({:g} d/c) for k in{}\n", options.horizon,
               intervals(document["stable_at_horizon"]));
    if (document.contains("code")) {
        const auto& c = document["code"];
        std::string s;
        for (const auto& i : c["stable_at_horizon"])
            s += fmt::format(" [{:.6g}, {:.6g}]", i[0].get<double>(), i[1].get<double>());
        fmt::print(
            results_file(),
            "  in {}'s own setting ({}, with its SPH density): no mode grows faster than the horizon for {} in{}\n",
            c["name"].get<std::string>(), c["parameter"].get<std::string>(), c["parameter"].get<std::string>(),
            s.empty() ? " none" : s);
    }
    fmt::print(results_file(), "  {:>10} {:>14} {:>9} {:>12} {}\n", "k", "min omega^2", "verdict", "growth time",
               "mode");
    for (const auto& p : document["samples"]) {
        const bool grows = p.contains("growth_time");
        fmt::print(results_file(), "  {:>10.6f} {:>14.6g} {:>9} {:>12} {}\n", p["k"].get<double>(),
                   p["min_omega2"].get<double>(), p["verdict"].get<std::string>(),
                   grows ? fmt::format("{:.4g}", p["growth_time"].get<double>()) : "",
                   grows ? p["mode"]["kind"].get<std::string>() : "");
    }
    // The cover's k are many (every edge to 1e-6): their count, not a line each.
    if (!document["between"].empty())
        fmt::print(results_file(), "  k looked at besides the samples, for the intervals: {}\n",
                   document["between"].size());
}

void print_path(const nlohmann::json& document, const std::string& kernel, const std::string& lattice,
                const StabilityRequest& options)
{
    const auto& path = document["path"];
    std::string labels;
    for (const auto& p : path["points"])
        labels += fmt::format("{}{} ({:.4f})", labels.empty() ? "" : " - ", p["label"].get<std::string>(),
                              p["at"].get<double>());
    fmt::print(results_file(), "{} on {} at k = {}, gamma = {:.6g}, {} h: omega^2 in (c/d)^2 along {}\n", kernel,
               lattice, *options.k, options.gamma, h_model_name(options.h_model), labels);
    for (std::size_t i = 0; i < path["position"].size(); ++i) {
        fmt::print(results_file(), "  {:>10.6f}", path["position"][i].get<double>());
        for (const auto& w : path["omega2"][i]) fmt::print(results_file(), " {:>14.8g}", w.get<double>());
        fmt::print(results_file(), "\n");
    }
}

void print_modes(const nlohmann::json& document, const std::string& kernel, const std::string& lattice,
                 const StabilityRequest& options)
{
    fmt::print(results_file(), "{} on {} at k = {}, gamma = {:.6g}, {} h, kappa = {} / d\n", kernel, lattice,
               *options.k, options.gamma, h_model_name(options.h_model), vector_text(document["wavevector"]));
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
            relation =
                fmt::format("  (eps_rho {:+.3e}, eps_gradP {:+.3e}, pressure term {:+.3e}, stiffness term {:+.3e})",
                            s["eps_rho"].get<double>(), s["eps_gradp"].get<double>(), s["pressure_term"].get<double>(),
                            s["stiffness_term"].get<double>());
        fmt::print(results_file(), "  {:<6} {:+.6e}{}\n", s["direction"].get<std::string>(),
                   s["longitudinal_error"].get<double>(), relation);
    }
}

void print_zone_scan(const nlohmann::json& document, const std::string& kernel, const Lattice& lattice,
                     const StabilityRequest& options)
{
    fmt::print(results_file(), "{} on {} ({} Bravais lattice) at k = {}, gamma = {:.6g}, {} h: {}\n", kernel,
               lattice.name, document["bravais"].get<std::string>(), *options.k, options.gamma, h_model_text(document),
               verdict_text(document));
    const auto& zone = document["zone_scan"];
    fmt::print(results_file(),
               "  min omega^2 per branch over the Brillouin zone (last grid {}^{}, {} grids, lowest "
               "branch {}):\n",
               zone["grid"].get<int>(), lattice.dimension, zone["grids"].get<int>(),
               zone["converged"].get<bool>() ? "settled within the tolerance" : "NOT settled");
    for (const auto& m : document["branches"])
        fmt::print(results_file(), "  branch {:>2}  {:>14.6g} (c/d)^2 at kappa = {} / d, longitudinal {:.3f}\n",
                   m["branch"].get<int>(), m["min_omega2"].get<double>(), vector_text(m["at"]),
                   m["longitudinal"].get<double>());
    print_long_waves(document);
}

} // namespace

void print_stability(const nlohmann::json& document, const StabilityRequest& options, const std::string& kernel,
                     const Lattice& lattice)
{
    switch (stability_mode(options)) {
    case StabilityMode::path: return print_path(document, kernel, lattice.name, options);
    case StabilityMode::wavevector: return print_modes(document, kernel, lattice.name, options);
    case StabilityMode::over_k: return print_over_k(document, kernel, lattice.name, options);
    case StabilityMode::zone_scan: return print_zone_scan(document, kernel, lattice, options);
    }
}

} // namespace sphkern
