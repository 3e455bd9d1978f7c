#include "block/block_sums.hpp"

#include "block/block_pair_sums.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/pair_pass.hpp"
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

    // Particle i's gradient sum (i in the block's order).
    double gradient(std::size_t i, const Neighbours& nb, std::size_t padded, const Eigen::Vector3d& gravity) const
    {
        const double rho_i = rho ? rho[i] : 1.0, e[3] = {gravity.x(), gravity.y(), gravity.z()};
        return block_gradient_sum(parameters.form, depth[i], rho_i, nb, e, padded);
    }
};

} // namespace

std::size_t sum_block(const Kernel& kernel, const NeighbourGrid& grid, const BlockGeometry& geometry,
                      const SweepParameters& parameters, bool with_density, bool with_gradient, const double* rho,
                      BlockResult& result)
{
    const int dim = parameters.dimension;
    const double k = parameters.k, kd = std::pow(k, dim);
    const bool monaghan = with_gradient && parameters.form == GradientForm::monaghan;
    BlockSweep sweep{kernel,
                     grid,
                     parameters,
                     with_density,
                     with_gradient,
                     geometry.depth.data(),
                     monaghan ? rho : nullptr,
                     monaghan ? grid.gather(std::vector<double>(rho, rho + grid.particles())) : std::vector<double>(),
                     parameters.reach,
                     kernel.w(0, dim, k),
                     kd,
                     kd * k};
    std::vector<std::size_t> pairs(static_cast<std::size_t>(result.threads));
    const PairPassInputs pass{{nullptr, sweep.reach}, nullptr, monaghan ? sweep.point_rho.data() : nullptr, false, ""};
    pair_pass(
        grid, "the block", pass, result.threads,
        [&](int thread, std::size_t p, Neighbours& nb) {
            pairs[static_cast<std::size_t>(thread)] += sweep.sum_particle(p, nb, result);
        },
        [](int) {});
    std::size_t total = 0;
    for (auto p : pairs) total += p;
    return total;
}

} // namespace sphkern
