#include "stability/stability_over_k.hpp"

#include "stability/stability_budget.hpp"

#include "stability/brillouin_zone.hpp"
#include "support/process/interruption.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>

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

namespace {

// The intervals where `holds` is true over points sorted by k; each change between two
// neighbouring points bisected with `at`.
std::vector<KInterval> intervals_of(const std::vector<StabilitySample>& points,
                                    const std::function<bool(const StabilitySample&)>& holds,
                                    const std::function<StabilitySample(double)>& at)
{
    auto edge = [&](double a, double b, bool a_holds) {
        for (int it = 0; it < 40 && b - a > stability_k_tolerance; ++it) {
            const double m = 0.5 * (a + b);
            if (holds(at(m)) == a_holds) a = m;
            else b = m;
        }
        return 0.5 * (a + b);
    };
    std::vector<KInterval> found;
    bool inside = false;
    double start = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const bool h = holds(points[i]);
        if (h && !inside) start = i == 0 ? points[i].k : edge(points[i - 1].k, points[i].k, false), inside = true;
        if (!h && inside) {
            found.push_back({start, edge(points[i - 1].k, points[i].k, true)});
            inside = false;
        }
    }
    if (inside) found.push_back({start, points.back().k});
    return found;
}

// How far a sample is from a change of verdict, in c^2/d^2: the lowest valley floor away
// from Γ when stable, else the lowest omega^2; and the long-wave minimum of omega^2 / kappa^2.
std::array<double, 2> margins(const StabilitySample& s)
{
    return {s.stable ? s.floor : s.branch_minima.front(), s.long_wave};
}

// How fast each margin changes with k near each interval between samples: the steepest slope
// over that interval and its two neighbours.
std::vector<std::array<double, 2>> local_slopes(const std::vector<StabilitySample>& samples)
{
    const std::size_t n = samples.size() < 2 ? 0 : samples.size() - 1;
    std::vector<std::array<double, 2>> slope(n, {0, 0}), local(n, {0, 0});
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t q = 0; q < 2; ++q) {
            const double a = margins(samples[i])[q], b = margins(samples[i + 1])[q];
            if (std::isfinite(a) && std::isfinite(b)) slope[i][q] = std::abs(b - a) / (samples[i + 1].k - samples[i].k);
        }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i == 0 ? 0 : i - 1; j <= std::min(n - 1, i + 1); ++j)
            for (std::size_t q = 0; q < 2; ++q) local[i][q] = std::max(local[i][q], slope[j][q]);
    return local;
}

// Whether an instability could hide between two samples of one verdict: between stable
// samples a margin (the valley floor, the long-wave minimum) could cross 0, between weak ones
// the lowest omega^2 could cross -1/horizon^2, if it changes no faster than twice the
// steepest slope nearby: the sum of the distances must then be within 2 L (b - a). (A
// stable window hidden between unstable samples is not looked for: missing it is safe.)
bool may_hide_a_change(const StabilitySample& a, const StabilitySample& b, const std::array<double, 2>& slope,
                       double horizon)
{
    if (a.verdict != b.verdict || a.verdict == Verdict::unstable) return false;
    auto close = [&](std::size_t q, double t) {
        const double da = margins(a)[q] - t, db = margins(b)[q] - t;
        return std::isfinite(da) && std::isfinite(db) && da > 0 && db > 0 && da + db < 2 * slope[q] * (b.k - a.k);
    };
    if (a.verdict == Verdict::stable) return close(0, 0) || close(1, 0);
    return close(0, -1 / (horizon * horizon));
}

} // namespace

StabilityOverK stability_over_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                double gamma, int grid, int threads, double horizon, HModel h_model)
{
    check_stability_budget("the stability scan over k", steps, grid, lattice.dimension);
    check_stability_work("the stability scan over k", kernel, lattice, k_min, k_max, steps, grid);
    const auto reciprocal = reciprocal_lattice(lattice);
    std::map<double, StabilitySample> seen; // the edges of both kinds of interval often coincide
    auto at = [&](double k) {
        if (auto found = seen.find(k); found != seen.end()) return found->second;
        throw_if_interrupted();
        return seen[k] = stability_sample(Dispersion(kernel, lattice, k, gamma, h_model), reciprocal, grid, threads, horizon);
    };
    StabilityOverK result;
    result.bravais = reciprocal.bravais;
    result.horizon = horizon;
    for (int i = 0; i <= steps; ++i) result.samples.push_back(at(k_min + (k_max - k_min) * i / steps));
    // Where a change of verdict could hide between two samples, more k, down to 1/16 of the spacing.
    const auto slopes = local_slopes(result.samples);
    const double finest = (k_max - k_min) / steps / 16;
    std::function<void(const StabilitySample&, const StabilitySample&, const std::array<double, 2>&)> look_between =
        [&](const StabilitySample& a, const StabilitySample& b, const std::array<double, 2>& slope) {
            if (b.k - a.k <= finest * 1.5 || !may_hide_a_change(a, b, slope, horizon)) return;
            const auto m = at(0.5 * (a.k + b.k));
            result.between.push_back(m);
            look_between(a, m, slope);
            look_between(m, b, slope);
        };
    for (std::size_t i = 0; i + 1 < result.samples.size(); ++i)
        look_between(result.samples[i], result.samples[i + 1], slopes[i]);
    std::vector<StabilitySample> points = result.samples;
    points.insert(points.end(), result.between.begin(), result.between.end());
    auto by_k = [](const StabilitySample& a, const StabilitySample& b) { return a.k < b.k; };
    std::sort(points.begin(), points.end(), by_k);
    std::sort(result.between.begin(), result.between.end(), by_k);
    result.stable = intervals_of(points, [](const StabilitySample& s) { return s.stable; }, at);
    result.usable = intervals_of(points, [](const StabilitySample& s) { return s.verdict != Verdict::unstable; }, at);
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
