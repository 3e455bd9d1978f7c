#include "stability/verdict_span.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace sphkern {

namespace {

// omega^2 at the cell's two ends and its largest rate over the cell, at one kappa.
struct Point {
    double a, b, rate;
};

Point point(const OmegaRate& a, const OmegaRate& m, const OmegaRate& b)
{
    return {a.omega2, b.omega2, k_change_safety * std::max({a.rate, m.rate, b.rate})};
}

// Every kappa the cell is judged at: the grid, both ends' refined minima, and (strict rule,
// one site) the long-wave limit along the grid's directions.
void for_each_point(const CellRates& r, const StabilitySample& a, const StabilitySample& b, bool long_waves,
                    const std::function<void(const Point&)>& f)
{
    for (std::size_t i = 0; i < r.a.size(); ++i) f(point(r.a.on_grid(i), r.middle.on_grid(i), r.b.on_grid(i)));
    for (const Eigen::Vector3d& kappa : {a.at, b.at}) f(point(r.a.at(kappa), r.middle.at(kappa), r.b.at(kappa)));
    if (!long_waves) return;
    for (std::size_t i = 0; i < r.a.long_wave().size(); ++i)
        f(point(r.a.long_wave()[i], r.middle.long_wave()[i], r.b.long_wave()[i]));
}

} // namespace

bool rule_holds(const StabilitySample& s, StabilityRule rule)
{
    return rule == StabilityRule::strict ? s.stable : s.verdict != Verdict::unstable;
}

bool verdict_spans(StabilityRule rule, const StabilitySample& a, const StabilitySample& b, const CellRates& rates,
                   double horizon)
{
    // Unstable at the horizon: omega^2 below -1/T^2 (and below -1e-9, a growth time at all).
    const double t =
        rule == StabilityRule::strict ? -unstable_threshold : std::min(-unstable_threshold, -1 / (horizon * horizon));
    const double width = b.k - a.k;
    const bool strict = rule == StabilityRule::strict;
    if (rule_holds(a, rule)) {
        bool spans = true;
        for_each_point(rates, a, b, strict, [&](const Point& p) {
            if (!((p.a - t) + (p.b - t) >= p.rate * width)) spans = false;
        });
        return spans;
    }
    double from_a = 0, from_b = 0;
    for_each_point(rates, a, b, strict, [&](const Point& p) {
        if (p.a < t) from_a = std::max(from_a, p.rate > 0 ? (t - p.a) / p.rate : INFINITY);
        if (p.b < t) from_b = std::max(from_b, p.rate > 0 ? (t - p.b) / p.rate : INFINITY);
    });
    return from_a + from_b >= width;
}

} // namespace sphkern
