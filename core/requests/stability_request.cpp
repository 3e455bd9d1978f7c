#include "requests/stability_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "analysis/hydrostatic_errors.hpp"
#include "analysis/results_json.hpp"
#include "stability/dispersion.hpp"
#include "stability/stability_budget.hpp"
#include "stability/stability_json.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace sphkern {

StabilityMode stability_mode(const StabilityRequest& r)
{
    if (r.k_min || r.k_max) return StabilityMode::over_k;
    if (r.wavevector) return StabilityMode::wavevector;
    return r.path_points ? StabilityMode::path : StabilityMode::zone_scan;
}

namespace {

// The option or argument alone: "--wavevector 1,0" -> "--wavevector".
std::string bare_name(const ValueSource& source) { return source.name.substr(0, source.name.find(' ')); }

// A k range or one k; a wave vector or a path.
void check_combination(const StabilityRequest& r, const StabilitySources& sources)
{
    if (r.k_min || r.k_max) {
        if (!r.k_min || !r.k_max || r.k || r.wavevector || r.path_points)
            throw Error(sources.k_min.code, fmt::format("{} and {} go together, without {}, {} or {}",
                                                        sources.k_min.name, sources.k_max.name, sources.k.name,
                                                        bare_name(sources.wavevector), sources.path.name));
        return;
    }
    if (!r.k)
        throw Error(sources.k.code, fmt::format("{}: expected a number (or {} and {})", sources.k.name,
                                                sources.k_min.name, sources.k_max.name));
    if (r.wavevector && r.path_points)
        throw Error(sources.wavevector.code,
                    fmt::format("{} and {}: give one of them", bare_name(sources.wavevector), sources.path.name));
}

// The stable intervals in a code's own setting, with the lattice's density at site 0 (its
// voronoi volume, as the dispersion matrix has it).
CodeIntervals intervals_in_code(const CodeProfile& code, const Kernel& kernel, const Lattice& lattice, double k_max,
                                const StabilityOverK& scan)
{
    require_code_kernel(code, kernel, lattice.dimension);
    require_lattice_volume(code, "a window of k at the lattice's a_p");
    const double a_p = lattice.volume_coefficient("voronoi");
    const HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, k_max);
    auto in_code = [&](const std::vector<KInterval>& intervals) {
        std::vector<KInterval> out;
        for (const KInterval& i : intervals)
            out.push_back({code_parameter(code, kernel, lattice.dimension, a_p, i.from, errors.at(i.from).eps_rho),
                           code_parameter(code, kernel, lattice.dimension, a_p, i.to, errors.at(i.to).eps_rho)});
        return out;
    };
    return {code.name, code.parameter, in_code(scan.stable), in_code(scan.usable)};
}

} // namespace

void check_stability_request(const StabilityRequest& r, const StabilitySources& sources)
{
    check_combination(r, sources);
    if (stability_mode(r) == StabilityMode::over_k) check_k_interval(*r.k_min, *r.k_max, sources.k_min, sources.k_max);
    else check_k(*r.k, sources.k, sources.k_hint);
    const SettingTable& declared = settings_of("stability");
    check_setting(declared["steps"], r.steps, sources.steps);
    if (r.grid) check_setting(declared["grid"], *r.grid, sources.grid);
    if (r.path_points) check_setting(declared["path"], *r.path_points, sources.path);
    check_setting(declared["threads"], r.threads, sources.threads);
    check_gamma(r.gamma, sources.gamma.name);
    check_horizon(r.horizon, sources.horizon.name);
}

StabilityResult run_stability(const StabilityRequest& r, const StabilitySources& sources, const Kernel& kernel,
                              const Lattice& lattice)
{
    const int threads = worker_threads(r.threads);
    const int grid = r.grid.value_or(0);
    // The work each mode asks for, refused naming the options that make it smaller (the same
    // limits the computations check once more).
    const std::string k = bare_name(sources.k), k_max = bare_name(sources.k_max), steps = bare_name(sources.steps),
                      grid_name = bare_name(sources.grid), path = bare_name(sources.path);
    switch (stability_mode(r)) {
    case StabilityMode::path:
        check_dispersion_work("the dispersion path", kernel, lattice, *r.k, *r.path_points,
                              fmt::format("a smaller {} or {}", k, path));
        return {path_dispersion(kernel, lattice, *r.k, r.gamma, *r.path_points, r.h_model), std::nullopt};
    case StabilityMode::wavevector: {
        const auto kappa = checked_wavevector(*r.wavevector, lattice.dimension, sources.wavevector.name);
        return {modes_at(kernel, lattice, *r.k, r.gamma, kappa, r.h_model), std::nullopt};
    }
    case StabilityMode::over_k: {
        check_stability_budget("the stability scan over k", r.steps, grid, lattice.dimension,
                               fmt::format("a smaller {} or {}", steps, grid_name));
        check_stability_work("the stability scan over k", kernel, lattice, *r.k_min, *r.k_max, r.steps, grid,
                             fmt::format("a smaller {}, {} or {}", k_max, steps, grid_name));
        StabilityAgainstK scan = stability_against_k(kernel, lattice, *r.k_min, *r.k_max, r.steps, r.gamma, grid,
                                                     threads, r.horizon, r.h_model);
        std::optional<CodeIntervals> code;
        if (r.code) code = intervals_in_code(*r.code, kernel, lattice, *r.k_max, scan.scan);
        return {std::move(scan), std::move(code)};
    }
    case StabilityMode::zone_scan: break;
    }
    check_stability_work("the stability zone scan", kernel, lattice, *r.k, *r.k, 0, grid,
                         fmt::format("a smaller {} or {}", k, grid_name));
    return {zone_scan(kernel, lattice, *r.k, r.gamma, grid, threads, r.horizon, r.h_model), std::nullopt};
}

nlohmann::json stability_json(const StabilityResult& result)
{
    nlohmann::json document = std::visit([](const auto& r) { return stability_json(r); }, result.result);
    if (result.code)
        document["code"] = {{"name", result.code->name},
                            {"parameter", result.code->parameter},
                            {"stable_intervals", intervals_json(result.code->stable)},
                            {"stable_at_horizon", intervals_json(result.code->usable)}};
    return document;
}

} // namespace sphkern
