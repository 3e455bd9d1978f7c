#include "particles/density_smoothing.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "particles/engine/pair_pass.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/vector_clones.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace sphkern {

namespace {

// sum_j m_j w(q_j) and sum_j m_j q_j w'(q_j).
SPHKERN_ENGINE_CLONES void weighted_sums(const double* __restrict w, const double* __restrict dw, const double* __restrict q,
                                         const double* __restrict m, std::size_t n, double& mw, double& mqdw)
{
    double a = 0, b = 0;
    for (std::size_t j = 0; j < n; ++j) a += m[j] * w[j], b += m[j] * q[j] * dw[j];
    mw = a, mqdw = b;
}

// The SPH density at its own h, rho_i = sum_j m_j W(r_ij, h_i) with itself, and its derivative
// in h_i, in one pass of the engine that sums nothing else. Only the particles still being
// solved are visited: in the gather form a particle's density depends on its own h alone.
class DensityPass {
public:
    DensityPass(const Kernel& kernel, const ParticleSet& set, std::span<const double> mass, double spacing, double self_weight,
                int threads)
        : kernel_(kernel), set_(set), mass_(mass), spacing_(spacing), self_weight_(self_weight), threads_(threads)
    {
    }

    // rho and drho / dh of the particles whose `solving` is set.
    void operator()(std::span<const double> h, const std::vector<std::uint8_t>& solving, std::vector<double>& rho,
                    std::vector<double>& drho)
    {
        const double h_max = *std::max_element(h.begin(), h.end());
        require_usable_kernel(kernel_, set_.dimension, h_max / spacing_);
        // The grid is kept while every support fits it: the solve moves h by little after its first passes.
        if (!grid_ || kernel_.support() * h_max > grid_reach_) {
            grid_reach_ = 1.1 * kernel_.support() * h_max;
            grid_.emplace(set_, grid_reach_, threads_);
            mass_points_ = grid_->gather(mass_);
        }
        const NeighbourGrid& grid = *grid_;
        const std::vector<double> h_points = grid.gather(h);
        std::vector<double> reach(h_points.size());
        std::vector<std::uint8_t> only(h_points.size());
        for (std::size_t p = 0; p < reach.size(); ++p) {
            reach[p] = search_reach(kernel_.support() * h_points[p]);
            only[p] = grid.visited(p) && solving[grid.source(p)];
        }
        const int dim = set_.dimension;
        rho.resize(set_.size()), drho.resize(set_.size());
        const PairPassInputs in{{reach.data(), 0}, mass_points_.data(), nullptr, true, "", only.data()};
        pair_pass(
            grid, set_.name, in, threads_,
            [&](int, std::size_t p, Neighbours& nb) {
                const double h_p = h_points[p], k = h_p / spacing_;
                fill_distances(nb);
                scale_distances(nb.r.data(), nb.count, 1 / h_p, nb.q.data());
                kernel_.w_batch(nb.q.data(), nb.w.data(), nb.count, dim, k);
                kernel_.dw_batch(nb.q.data(), nb.dw.data(), nb.count, dim, k);
                const std::size_t i = grid.source(p);
                double mw = 0, mqdw = 0;
                weighted_sums(nb.w.data(), nb.dw.data(), nb.q.data(), nb.a.data(), nb.count, mw, mqdw);
                mw += self_weight_ * mass_[i] * kernel_.w(0, dim, k); // q = 0: nothing in mqdw
                const double hd = dim == 3 ? h_p * h_p * h_p : h_p * h_p;
                // W = w(q) / h^D: dW / dh = -(D w + q w') / h^(D+1).
                rho[i] = mw / hd, drho[i] = -(dim * mw + mqdw) / (hd * h_p);
                if (!std::isfinite(rho[i]) || !std::isfinite(drho[i]))
                    fail_non_finite_sum(kernel_, dim, k, fmt::format("particle {} of {}", i, set_.name),
                                        fmt::format("h = {:.6g}", h_p), {nb.q.data(), nb.count});
            },
            [](int) {});
    }

private:
    const Kernel& kernel_;
    const ParticleSet& set_;
    std::span<const double> mass_;
    double spacing_, self_weight_;
    int threads_;
    std::optional<NeighbourGrid> grid_;
    double grid_reach_ = 0;
    std::vector<double> mass_points_;
};

} // namespace

PerParticle density_smoothing_lengths(const Kernel& kernel, const ParticleSet& set, double coefficient,
                                      double mean_volume, int threads, bool by_number, double self_weight)
{
    if (set.neighbours_only > 0)
        fail_input(fmt::format("{}: h from the SPH density is solved for every particle; the set has {} neighbours-only "
                               "particles, expected one particle array",
                               set.name, set.neighbours_only));
    const int dim = set.dimension;
    const std::size_t n = set.size();
    // Without masses, or counting by number, every particle has the mean volume's (rho0 = 1).
    const bool equal = by_number || set.mass.size() != n;
    const std::vector<double> own_masses = equal ? std::vector<double>(n, mean_volume) : std::vector<double>();
    const std::span<const double> masses = own_masses.empty() ? std::span<const double>(set.mass) : own_masses;
    auto mass = [&](std::size_t i) { return masses[i]; };
    auto h_of = [&](std::size_t i, double rho) { return coefficient * std::pow(mass(i) / rho, 1.0 / dim); };
    // Each particle's residual g(h) = h - c (m / rho(h))^(1/D) vanishes at its h, found by
    // Newton steps on g (g' from drho / dh, as SWIFT and GADGET step), a step that leaves
    // [h / 2, 2 h] or a g' that is not positive falling back to the fixed point's step. A
    // particle is done once its own residual is below the tolerance, at the h it was measured at.
    // The first guess takes the set's mean density, whatever the masses' units.
    double total_mass = 0;
    for (std::size_t i = 0; i < n; ++i) total_mass += mass(i);
    const double mean_density = total_mass / (static_cast<double>(n) * mean_volume);
    PerParticle h = PerParticle::of(fill_particle_values(n, threads, [&](std::size_t i) { return h_of(i, mean_density); }));
    std::vector<double> rho, drho;
    std::vector<std::uint8_t> solving(n, 1);
    DensityPass densities(kernel, set, masses, std::pow(mean_volume, 1.0 / dim), self_weight, threads);
    constexpr int max_passes = 100;
    constexpr double tolerance = 1e-12;
    double residual = INFINITY;
    for (int pass = 1; pass <= max_passes; ++pass) {
        densities(h.values, solving, rho, drho);
        // Each particle's step, on every thread: the largest residual and the particles left.
        struct Progress {
            double residual = 0;
            std::size_t left = 0;
        };
        const Progress step = parallel_reduce(
            n, threads, Progress{},
            [&](std::size_t i, Progress& p) {
                if (!solving[i]) return;
                const double now = h.values[i], fixed = h_of(i, rho[i]), g = now - fixed;
                p.residual = std::max(p.residual, std::abs(g) / now);
                if (std::abs(g) <= tolerance * now) {
                    solving[i] = 0;
                    return;
                }
                const double slope = 1 + fixed / dim * drho[i] / rho[i], newton = now - g / slope;
                h.values[i] = slope > 0 && newton > 0.5 * now && newton < 2 * now ? newton : fixed;
                ++p.left;
            },
            [](Progress& total, const Progress& block) {
                total.residual = std::max(total.residual, block.residual), total.left += block.left;
            });
        residual = step.residual;
        const std::size_t left = step.left;
        spdlog::debug("h from the SPH density: pass {}, largest relative residual {:.3g}, {} particles left", pass,
                      residual, left);
        if (left == 0) return h;
    }
    fail_input(fmt::format("{}: h from the SPH density did not settle in {} passes (the largest relative residual is still "
                           "{:.3g}); expected a set whose density the kernel resolves",
                           set.name, max_passes, residual));
}

} // namespace sphkern
