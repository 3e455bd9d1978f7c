#include "block/block_sums.hpp"

#include "block/block_pair_sums.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/pair_pass.hpp"
#include "particles/engine/symmetric_pair_pass.hpp"
#include "support/process/parallel_for.hpp"

#include <cmath>
#include <vector>

namespace sphkern {

namespace {

struct BlockSweep {
    const Kernel& kernel;
    const NeighbourGrid& grid;
    const SweepParameters& parameters;
    bool with_density, with_gradient;
    const double* depth;           // in the block's order
    const double* rho;             // in the block's order (Monaghan's form only)
    std::vector<double> point_rho; // in the grid's point order (empty but for Monaghan's form)
    double reach;
    double self, kd, kd1;

    // Particle p's sums over its neighbours (kept by the pair pass); returns their count.
    std::size_t sum_particle(std::size_t p, Neighbours& nb, BlockResult& result) const
    {
        const int dim = parameters.dimension;
        const double k = parameters.k;
        const std::size_t n = nb.count, padded = padded_count(n);
        for (std::size_t j = n; j < padded; ++j) nb.b[j] = 1; // Monaghan's weight divides by rho_j
        distances(nb, padded, 1 / k);
        const std::size_t i = grid.source(p);
        if (with_density && !with_gradient) kernel.w_batch(nb.q.data(), nb.w.data(), padded, dim, k);
        else kernel.w_dw_batch(nb.q.data(), nb.w.data(), nb.dw.data(), padded, dim, k);
        if (with_density)
            result.eps_rho[i] = parameters.a_p * (self + block_density_sum(nb.w.data(), padded, n)) / kd - 1;
        if (with_gradient) result.eps_gradp[i] = parameters.a_p * gradient(i, nb, padded, result.gravity) / kd1 - 1;
        return n;
    }

    // Each pair once: particle p's terms added to its sums, its pairs' other terms to theirs
    // (the density always: Monaghan's gradient pass ignores it).
    void add_pairs(std::size_t p, Neighbours& nb, const double* e, double* sums, double* cluster_sums) const
    {
        const std::size_t n = nb.count, padded = padded_count(n);
        for (std::size_t j = n; j < padded; ++j) nb.b[j] = 1;
        distances(nb, padded, 1 / parameters.k);
        const std::size_t i = grid.source(p);
        kernel.w_dw_batch(nb.q.data(), nb.w.data(), nb.dw.data(), padded, parameters.dimension, parameters.k);
        const double rho_i = rho ? rho[i] : 1.0;
        const auto form = with_gradient ? std::optional<GradientForm>(parameters.form) : std::nullopt;
        add_block_pair_terms(form, depth[i], rho_i, nb, e, padded, sums + 2 * p, cluster_sums);
    }

    // Particle i's gradient sum (i in the block's order).
    double gradient(std::size_t i, const Neighbours& nb, std::size_t padded, const Eigen::Vector3d& gravity) const
    {
        const double rho_i = rho ? rho[i] : 1.0, e[3] = {gravity.x(), gravity.y(), gravity.z()};
        return block_gradient_sum(parameters.form, depth[i], rho_i, nb, e, padded);
    }
};

// Each pair once: the sums by point, then each particle's result from its own.
std::size_t sum_block_pairs(const BlockSweep& sweep, BlockResult& result)
{
    const NeighbourGrid& grid = sweep.grid;
    // The density and gradient sums of each point, and of the unpaired key.
    std::vector<double> sums(2 * (grid.points() + 1));
    const double e[3] = {result.gravity.x(), result.gravity.y(), result.gravity.z()};
    SymmetricPassInputs pass{sweep.reach, nullptr, sweep.point_rho.empty() ? nullptr : sweep.point_rho.data(), false,
                             ""};
    pass.count_pairs = true;
    const std::size_t pairs = symmetric_pair_pass<2>(grid, "the block", pass, result.threads, sums.data(),
                                                     [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
                                                         sweep.add_pairs(p, nb, e, sums.data(), cluster_sums);
                                                     });
    const SweepParameters& parameters = sweep.parameters;
    for_each_visited(grid, result.threads, [&](std::size_t p, std::size_t i) {
        if (sweep.with_density) result.eps_rho[i] = parameters.a_p * (sweep.self + sums[2 * p]) / sweep.kd - 1;
        if (sweep.with_gradient) result.eps_gradp[i] = parameters.a_p * sums[2 * p + 1] / sweep.kd1 - 1;
    });
    return pairs;
}

// Every particle gathers its own neighbours and sums them.
std::size_t sum_block_gathered(const BlockSweep& sweep, BlockResult& result)
{
    std::vector<std::size_t> pairs(static_cast<std::size_t>(result.threads));
    const PairPassInputs pass{
        {nullptr, sweep.reach}, nullptr, sweep.point_rho.empty() ? nullptr : sweep.point_rho.data(), false, ""};
    pair_pass(
        sweep.grid, "the block", pass, result.threads,
        [&](int thread, std::size_t p, Neighbours& nb) {
            pairs[static_cast<std::size_t>(thread)] += sweep.sum_particle(p, nb, result);
        },
        [](int) {});
    std::size_t total = 0;
    for (auto n : pairs) total += n;
    return total;
}

} // namespace

std::size_t sum_block(const Kernel& kernel, const NeighbourGrid& grid, const BlockGeometry& geometry,
                      const SweepParameters& parameters, bool with_density, bool with_gradient, const double* rho,
                      BlockResult& result)
{
    const int dim = parameters.dimension;
    const double k = parameters.k, kd = std::pow(k, dim);
    const bool monaghan = with_gradient && parameters.form == GradientForm::monaghan;
    const BlockSweep sweep{kernel,
                           grid,
                           parameters,
                           with_density,
                           with_gradient,
                           geometry.depth.data(),
                           monaghan ? rho : nullptr,
                           monaghan ? grid.gather(std::vector<double>(rho, rho + grid.particles()))
                                    : std::vector<double>(),
                           parameters.reach,
                           kernel.w(0, dim, k),
                           kd,
                           kd * k};
    return parameters.each_pair_once ? sum_block_pairs(sweep, result) : sum_block_gathered(sweep, result);
}

} // namespace sphkern
