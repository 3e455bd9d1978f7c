#include "analysis/acceptance.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

Acceptance evaluate_acceptance(const HydrostaticErrors& errors, double k_min, double k_max, double epsilon,
                               int samples)
{
    auto worst = [&](double k) {
        ErrorValues v = errors.at(k);
        return std::max(std::abs(v.eps_rho), std::abs(v.eps_gradp));
    };
    auto ok = [&](double k) { return worst(k) <= epsilon; };

    // Sample at a regular grid plus both sides of every breakpoint.
    std::vector<double> ks;
    for (int i = 0; i <= samples; ++i) ks.push_back(k_min + (k_max - k_min) * i / samples);
    for (double b : errors.breakpoints(k_min, k_max)) {
        ks.push_back(b);
        ks.push_back(std::nextafter(b, k_max));
    }
    std::sort(ks.begin(), ks.end());

    Acceptance result;
    result.best_error = INFINITY;
    bool inside = false;
    double from = 0;
    for (std::size_t i = 0; i < ks.size(); ++i) {
        double e = worst(ks[i]);
        if (e < result.best_error) {
            result.best_error = e;
            result.best_k = ks[i];
        }
        bool now = e <= epsilon;
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

} // namespace sphkern
