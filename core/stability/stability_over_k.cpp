#include "stability/stability_over_k.hpp"

#include "stability/brillouin_zone.hpp"
#include "stability/stability_scan.hpp"
#include "support/interruption.hpp"

#include <algorithm>


namespace sphkern {

StabilityOverK stability_over_k(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                double gamma, int grid, int threads)
{
    const auto reciprocal = reciprocal_lattice(lattice);
    auto lowest = [&](double k) {
        throw_if_interrupted();
        return scan_brillouin_zone(Dispersion(kernel, lattice, k, gamma), reciprocal, grid, threads, false);
    };
    StabilityOverK result;
    result.bravais = reciprocal.bravais;
    for (int i = 0; i <= steps; ++i) {
        StabilitySample sample;
        sample.k = k_min + (k_max - k_min) * i / steps;
        const auto scan = lowest(sample.k);
        for (const auto& m : scan.minima) sample.branch_minima.push_back(m.omega2);
        sample.stable = scan.stable;
        sample.longitudinal = scan.lowest().longitudinal;
        result.samples.push_back(std::move(sample));
    }
    // The edge between a sample whose verdict is `a_stable` at a and the other at b.
    auto edge = [&](double a, double b, bool a_stable) {
        for (int it = 0; it < 20 && b - a > 1e-6; ++it) {
            const double m = 0.5 * (a + b);
            if (lowest(m).stable == a_stable) a = m;
            else b = m;
        }
        return 0.5 * (a + b);
    };
    bool inside = false; // a stable interval has started at `start`
    double start = 0;
    const auto& s = result.samples;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i].stable && !inside) start = i == 0 ? s[i].k : edge(s[i - 1].k, s[i].k, false), inside = true;
        if (!s[i].stable && inside) {
            result.stable.push_back({start, edge(s[i - 1].k, s[i].k, true)});
            inside = false;
        }
    }
    if (inside) result.stable.push_back({start, k_max});
    return result;
}

std::vector<KInterval> accurate_and_stable(const std::vector<KInterval>& accurate, const StabilityOverK& stability)
{
    std::vector<KInterval> both;
    for (const auto& x : accurate)
        for (const auto& y : stability.stable) {
            const double from = std::max(x.from, y.from), to = std::min(x.to, y.to);
            if (from < to) both.push_back({from, to});
        }
    return both;
}

} // namespace sphkern
