#include "requests/stability_report.hpp"

#include "stability/h_model.hpp"
#include "stability/mode_kind.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

namespace {

// "(x, y[, z])" of the first `dim` components, a -0 written as 0 (as the JSON has it).
std::string vector_text(const Eigen::Vector3d& v, int dim)
{
    std::string s;
    for (int i = 0; i < dim; ++i) s += fmt::format("{}{:.6g}", s.empty() ? "" : ", ", v[i] == 0 ? 0.0 : v[i]);
    return "(" + s + ")";
}

// "stable", or "UNSTABLE: growth time 12.3 d/c, transverse mode at kappa = (...) / d" (or weak).
std::string verdict_text(const ZoneScan& z)
{
    const Verdict verdict = z.scan.verdict(z.horizon);
    if (verdict == Verdict::stable) return verdict_name(verdict);
    const int dim = z.setting.dimension;
    std::string s =
        fmt::format("{} (horizon {:g} d/c): ", verdict == Verdict::unstable ? "UNSTABLE" : "weak", z.horizon);
    if (!std::isfinite(z.scan.growth_time()))
        return s + "only long waves grow (omega^2 / kappa^2 < 0), ever more slowly as kappa -> 0";
    return s + fmt::format("growth time {:.4g} d/c, {} mode at kappa = {} / d (unfolded {})", z.scan.growth_time(),
                           mode_kind_name(z.scan.mode.kind), vector_text(z.scan.lowest().kappa, dim),
                           vector_text(z.scan.mode.unfolded, dim));
}

// "fixed", or "adaptive (h/l 1.23, Omega 1.001)": the equilibrium h is k d in both.
std::string h_model_text(const StabilitySetting& s)
{
    if (!s.eta) return h_model_name(s.h_model);
    return fmt::format("adaptive (h/l {:.6g}, grad-h factor {:.6g})", *s.eta, *s.grad_h_factor);
}

void print_over_k(const StabilityAgainstK& result, const std::optional<CodeIntervals>& code, const std::string& kernel,
                  const std::string& lattice, const StabilityRequest& options)
{
    auto intervals = [&](const std::vector<KInterval>& list) {
        std::string s;
        for (const auto& i : list) s += fmt::format(" [{:.6f}, {:.6f}]", i.from, i.to);
        return s.empty() ? fmt::format(" none of [{}, {}]", *options.k_min, *options.k_max) : s;
    };
    fmt::print(results_file(), "{} on {}, gamma = {:.6g}, {} h: stable for k in{}\n", kernel, lattice, options.gamma,
               h_model_name(options.h_model), intervals(result.scan.stable));
    fmt::print(results_file(), "  no mode grows faster than the horizon ({:g} d/c) for k in{}\n", options.horizon,
               intervals(result.scan.usable));
    if (code) {
        std::string s;
        for (const auto& i : code->usable) s += fmt::format(" [{:.6g}, {:.6g}]", i.from, i.to);
        fmt::print(
            results_file(),
            "  in {}'s own setting ({}, with its SPH density): no mode grows faster than the horizon for {} in{}\n",
            code->name, code->parameter, code->parameter, s.empty() ? " none" : s);
    }
    fmt::print(results_file(), "  {:>10} {:>14} {:>9} {:>12} {}\n", "k", "min omega^2", "verdict", "growth time",
               "mode");
    for (const StabilitySample& p : result.scan.samples) {
        const bool grows = std::isfinite(p.growth_time);
        fmt::print(results_file(), "  {:>10.6f} {:>14.6g} {:>9} {:>12} {}\n", p.k, p.branch_minima.front(),
                   verdict_name(p.verdict), grows ? fmt::format("{:.4g}", p.growth_time) : "",
                   grows ? mode_kind_name(p.mode.kind) : "");
    }
    // The cover's k are many (every edge to 1e-6): their count, not a line each.
    if (!result.scan.between.empty())
        fmt::print(results_file(), "  k looked at besides the samples, for the intervals: {}\n",
                   result.scan.between.size());
}

void print_path(const PathDispersion& result, const std::string& kernel, const std::string& lattice,
                const StabilityRequest& options)
{
    const DispersionPath& path = result.path;
    std::string labels;
    for (std::size_t i = 0; i < path.labels.size(); ++i)
        labels += fmt::format("{}{} ({:.4f})", labels.empty() ? "" : " - ", path.labels[i], path.label_positions[i]);
    fmt::print(results_file(), "{} on {} at k = {}, gamma = {:.6g}, {} h: omega^2 in (c/d)^2 along {}\n", kernel,
               lattice, *options.k, options.gamma, h_model_name(options.h_model), labels);
    for (std::size_t i = 0; i < path.position.size(); ++i) {
        fmt::print(results_file(), "  {:>10.6f}", path.position[i]);
        for (double w : path.omega2[i]) fmt::print(results_file(), " {:>14.8g}", w);
        fmt::print(results_file(), "\n");
    }
}

void print_modes(const WavevectorModes& result, const std::string& kernel, const std::string& lattice,
                 const StabilityRequest& options)
{
    fmt::print(results_file(), "{} on {} at k = {}, gamma = {:.6g}, {} h, kappa = {} / d\n", kernel, lattice,
               *options.k, options.gamma, h_model_name(options.h_model),
               vector_text(result.kappa, result.setting.dimension));
    fmt::print(results_file(), "  {:>6} {:>16} {:>13}\n", "branch", "omega^2 (c/d)^2", "longitudinal");
    for (std::size_t b = 0; b < result.modes.omega2.size(); ++b)
        fmt::print(results_file(), "  {:>6} {:>16.10g} {:>13.4f}\n", b, result.modes.omega2[b],
                   result.modes.longitudinal[b]);
}

void print_long_waves(const ZoneScan& result)
{
    const int dim = result.setting.dimension;
    fmt::print(results_file(), "  long waves: lowest omega^2 / kappa^2 over every direction {:.6g} c^2 along {}\n",
               result.scan.long_wave.omega2_over_kappa2, vector_text(result.scan.long_wave.direction, dim));
    fmt::print(results_file(), "  long waves: speed / c - 1 of the longitudinal mode\n");
    for (const DirectionSpeed& s : result.speeds) {
        std::string relation;
        if (s.terms)
            relation =
                fmt::format("  (eps_rho {:+.3e}, eps_gradP {:+.3e}, pressure term {:+.3e}, stiffness term {:+.3e})",
                            s.terms->eps_rho, s.terms->eps_gradp, s.terms->pressure_term, s.terms->stiffness_term);
        fmt::print(results_file(), "  {:<6} {:+.6e}{}\n", s.direction, s.speed.longitudinal - 1, relation);
    }
}

void print_zone_scan(const ZoneScan& result, const std::string& kernel, const Lattice& lattice,
                     const StabilityRequest& options)
{
    const StabilityScan& scan = result.scan;
    fmt::print(results_file(), "{} on {} ({} Bravais lattice) at k = {}, gamma = {:.6g}, {} h: {}\n", kernel,
               lattice.name, result.reciprocal.bravais, *options.k, options.gamma, h_model_text(result.setting),
               verdict_text(result));
    fmt::print(results_file(),
               "  min omega^2 per branch over the Brillouin zone (last grid {}^{}, {} grids, lowest "
               "branch {}):\n",
               scan.grid, lattice.dimension, scan.levels,
               scan.converged ? "settled within the tolerance" : "NOT settled");
    for (const BranchMinimum& m : scan.minima)
        fmt::print(results_file(), "  branch {:>2}  {:>14.6g} (c/d)^2 at kappa = {} / d, longitudinal {:.3f}\n",
                   m.branch, m.omega2, vector_text(m.kappa, lattice.dimension), m.longitudinal);
    print_long_waves(result);
}

} // namespace

void print_stability(const StabilityResult& result, const StabilityRequest& options, const std::string& kernel,
                     const Lattice& lattice)
{
    if (const auto* r = std::get_if<PathDispersion>(&result.result))
        return print_path(*r, kernel, lattice.name, options);
    if (const auto* r = std::get_if<WavevectorModes>(&result.result))
        return print_modes(*r, kernel, lattice.name, options);
    if (const auto* r = std::get_if<StabilityAgainstK>(&result.result))
        return print_over_k(*r, result.code, kernel, lattice.name, options);
    print_zone_scan(std::get<ZoneScan>(result.result), kernel, lattice, options);
}

} // namespace sphkern
