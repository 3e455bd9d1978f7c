#include "stability/dispersion_jumps.hpp"

#include "lattices/shells.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

// Whether w, w' or w'' differ across the cut q = c by more than 1e-6 of w(0) (at k).
bool jumps_at(const Kernel& kernel, double c, int D, double k)
{
    const double in = c * (1 - 1e-7), out = c * (1 + 1e-7), scale = std::abs(kernel.w(0, D, k));
    auto value = [&](double q, int order) {
        if (!kernel.inside(q)) return 0.0;
        return order == 0 ? kernel.w(q, D, k) : order == 1 ? kernel.dw(q, D, k) : kernel.d2w(q, D, k);
    };
    for (int order = 0; order < 3; ++order)
        if (!(std::abs(value(in, order) - value(out, order)) <= 1e-6 * scale)) return true;
    return false;
}

} // namespace

std::vector<double> dispersion_jumps(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max)
{
    std::vector<double> ks;
    const int D = lattice.dimension;
    const double k = 0.5 * (k_min + k_max);
    for (double cut : kernel.definition().truncations) {
        if (!jumps_at(kernel, cut, D, k)) continue;
        for (int site = 0; site < lattice.sites(); ++site)
            for (const auto& shell : lattice_shells(lattice, site, cut * k_max))
                if (const double at = shell.radius / cut; at > k_min && at < k_max) ks.push_back(at);
    }
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    return ks;
}

} // namespace sphkern
