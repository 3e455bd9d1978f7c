#include "analysis/acceptance.hpp"

#include "support/process/interruption.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

bool at_window_edge(double k, double window_min, double window_max)
{
    const double slack = 1e-9 * (window_max - window_min);
    return k <= window_min + slack || k >= window_max - slack;
}

double acceptance_error(const HydrostaticErrors& site, double k, const AcceptanceRule& rule)
{
    ErrorValues v = site.at(k);
    double worst = std::abs(v.eps_rho);
    if (rule.direction == Direction::gravity) {
        worst = std::max(worst, std::abs(v.eps_gradp));
        if (rule.lateral) worst = std::max(worst, v.lateral);
        return worst;
    }
    GradientTensor g = site.tensor(k);
    worst = std::max(worst, g.max_abs_eigenvalue());
    // The largest lateral error over all directions of a symmetric E: half its eigenvalue spread.
    if (rule.lateral) worst = std::max(worst, 0.5 * (g.eigenvalues.back() - g.eigenvalues.front()));
    return worst;
}

Acceptance evaluate_acceptance(const std::vector<const HydrostaticErrors*>& sites, double k_min, double k_max,
                               const AcceptanceRule& rule, int samples)
{
    auto worst = [&](double k) {
        double e = 0;
        for (const auto* site : sites) e = std::max(e, acceptance_error(*site, k, rule));
        return e;
    };
    auto ok = [&](double k) { return worst(k) <= rule.epsilon; };

    // Sample at a regular grid plus both sides of every breakpoint of every site.
    std::vector<double> ks;
    for (int i = 0; i <= samples; ++i) ks.push_back(k_min + (k_max - k_min) * i / samples);
    for (const auto* site : sites)
        for (double b : site->breakpoints(k_min, k_max)) {
            ks.push_back(b);
            ks.push_back(std::nextafter(b, k_max));
        }
    std::sort(ks.begin(), ks.end());

    Acceptance result;
    result.best_error = INFINITY;
    bool inside = false;
    double from = 0;
    for (std::size_t i = 0; i < ks.size(); ++i) {
        if (i % 64 == 0) throw_if_interrupted();
        double e = worst(ks[i]);
        if (e < result.best_error) {
            result.best_error = e;
            result.best_k = ks[i];
        }
        bool now = e <= rule.epsilon;
        if (now != inside) {
            // Bisect the predicate between the previous sample and this one.
            double lo = i ? ks[i - 1] : ks[i], hi = ks[i];
            for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
                double mid = 0.5 * (lo + hi);
                (ok(mid) == now ? hi : lo) = mid;
            }
            if (now) from = i ? hi : ks[i];
            else result.intervals.push_back({from, lo});
            inside = now;
        }
    }
    if (inside) result.intervals.push_back({from, k_max});
    return result;
}

Acceptance evaluate_acceptance(const HydrostaticErrors& errors, double k_min, double k_max, double epsilon, int samples)
{
    return evaluate_acceptance({&errors}, k_min, k_max, AcceptanceRule{epsilon}, samples);
}

} // namespace sphkern
