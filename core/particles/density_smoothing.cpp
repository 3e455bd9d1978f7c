#include "particles/density_smoothing.hpp"

#include "particles/particle_measures.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sphkern {

PerParticle density_smoothing_lengths(const Kernel& kernel, const ParticleSet& set, double coefficient,
                                      double mean_volume, int threads)
{
    if (set.neighbours_only > 0)
        fail_input(fmt::format("{}: h from the SPH density is solved for every particle; the set has {} neighbours-only "
                               "particles, expected one particle array",
                               set.name, set.neighbours_only));
    const int dim = set.dimension;
    const std::size_t n = set.size();
    const bool masses = set.mass.size() == n;
    auto mass = [&](std::size_t i) { return masses ? set.mass[i] : mean_volume; };
    auto h_of = [&](std::size_t i, double rho) { return coefficient * std::pow(mass(i) / rho, 1.0 / dim); };
    // Each particle's residual g(h) = h - c (m / rho(h))^(1/D) vanishes at its h. The first
    // step is the fixed point's, the next ones secant steps on g (superlinear; the fixed point
    // alone gains only a factor of about 0.7 a pass on a Poisson set), a step that leaves
    // [h / 2, 2 h] or divides by nothing falling back to the fixed point's.
    PerParticle h = PerParticle::of(fill_particle_values(n, threads, [&](std::size_t i) { return h_of(i, 1.0); }));
    std::vector<double> previous_h(n), previous_g(n);
    const PerParticle volume = PerParticle::same(n, mean_volume);
    constexpr int max_passes = 100;
    constexpr double tolerance = 1e-12;
    double residual = INFINITY;
    for (int pass = 1; pass <= max_passes; ++pass) {
        MeasureInputs inputs;
        inputs.h = h.view();
        inputs.volume = volume.view();
        if (masses) inputs.mass = set.mass;
        inputs.threads = threads;
        inputs.vectors = false;
        const auto measures = measure_particles(kernel, set, inputs);
        const auto& eps_rho = measures.eps_rho_values(); // rho_i / rho0 - 1, rho0 = 1
        residual = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double now = h.values[i], fixed = h_of(i, 1 + eps_rho[i]), g = now - fixed;
            residual = std::max(residual, std::abs(g) / now);
            double next = fixed;
            if (pass > 1 && g != previous_g[i]) {
                const double secant = now - g * (now - previous_h[i]) / (g - previous_g[i]);
                if (secant > 0.5 * now && secant < 2 * now) next = secant;
            }
            previous_h[i] = now, previous_g[i] = g;
            h.values[i] = next;
        }
        spdlog::debug("h from the SPH density: pass {}, largest relative residual {:.3g}", pass, residual);
        if (residual <= tolerance) {
            for (std::size_t i = 0; i < n; ++i) h.values[i] = previous_h[i]; // the h whose residual was measured
            return h;
        }
    }
    fail_input(fmt::format("{}: h from the SPH density did not settle in {} passes (the largest relative residual is still "
                           "{:.3g}); expected a set whose density the kernel resolves",
                           set.name, max_passes, residual));
}

} // namespace sphkern
