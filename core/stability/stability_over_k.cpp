#include "stability/stability_over_k.hpp"

#include "stability/stability_budget.hpp"

#include "stability/brillouin_zone.hpp"
#include "stability/verdict_cover.hpp"
#include "support/process/interruption.hpp"
#include "support/process/parallel_for.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace sphkern {

StabilitySample stability_sample(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int grid,
                                 int threads, double horizon)
{
    const auto scan = scan_brillouin_zone(dispersion, reciprocal, grid, threads, false);
    StabilitySample s;
    s.k = dispersion.k();
    for (const auto& m : scan.minima) s.branch_minima.push_back(m.omega2);
    s.stable = scan.stable;
    s.verdict = scan.verdict(horizon);
    s.longitudinal = scan.lowest().longitudinal;
    s.at = scan.lowest().kappa;
    s.mode = scan.mode;
    s.growth_time = scan.growth_time();
    s.floor = scan.floor;
    s.long_wave = scan.long_wave.omega2_over_kappa2;
    return s;
}

StabilityOverK stability_over_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                double gamma, int grid, int threads, double horizon, HModel h_model)
{
    check_stability_budget("the stability scan over k", steps, grid, lattice.dimension);
    check_stability_work("the stability scan over k", kernel, lattice, k_min, k_max, steps, grid);
    const auto reciprocal = reciprocal_lattice(lattice);
    // One zone scan per k, each a function of k alone: on several threads the k are shared out
    // (each scan on one thread), and the cover then finds what it asks for already known.
    const bool over_k = threads > 1;
    std::map<double, StabilitySample> seen; // the edges of both kinds of interval often coincide
    std::mutex seen_mutex;
    const std::function<StabilitySample(double)> at = [&](double k) {
        {
            std::lock_guard lock(seen_mutex);
            if (auto found = seen.find(k); found != seen.end()) return found->second;
        }
        throw_if_interrupted();
        auto s = stability_sample(Dispersion(kernel, lattice, k, gamma, h_model), reciprocal, grid,
                                  over_k ? 1 : threads, horizon);
        std::lock_guard lock(seen_mutex);
        return seen.try_emplace(k, std::move(s)).first->second;
    };
    auto curve_k = [&](int i) { return k_min + (k_max - k_min) * i / steps; };
    const CoverModel model{gamma, horizon, h_model, grid};
    std::shared_ptr<const CoverRates> ahead;
    if (over_k) {
        ParallelFor curve;
        curve.run_blocks(static_cast<std::size_t>(steps) + 1, 1, threads,
                         [&](std::size_t i, std::size_t, std::size_t) { at(curve_k(static_cast<int>(i))); });
        ahead = prefetch_cover(kernel, lattice, k_min, k_max, model, at, threads);
    }
    StabilityOverK result;
    result.bravais = reciprocal.bravais;
    result.horizon = horizon;
    // The curve's samples; the intervals come from a cover of k of their own, which
    // shares a sample only where a k is the same.
    for (int i = 0; i <= steps; ++i) result.samples.push_back(at(curve_k(i)));
    const auto cover = cover_verdicts(kernel, lattice, k_min, k_max, model, at, ahead.get());
    spdlog::debug("stability over k: {} samples for the curve, {} for the intervals", result.samples.size(),
                  cover.looked_at.size());
    for (const auto& s : cover.looked_at)
        if (std::none_of(result.samples.begin(), result.samples.end(),
                         [&](const StabilitySample& c) { return c.k == s.k; }))
            result.between.push_back(s);
    result.stable = cover.stable;
    result.usable = cover.usable;
    return result;
}

std::vector<KInterval> accurate_and_stable(const std::vector<KInterval>& accurate, const StabilityOverK& stability)
{
    std::vector<KInterval> both;
    for (const auto& x : accurate)
        for (const auto& y : stability.usable) {
            const double from = std::max(x.from, y.from), to = std::min(x.to, y.to);
            if (from < to) both.push_back({from, to});
        }
    return both;
}

} // namespace sphkern
