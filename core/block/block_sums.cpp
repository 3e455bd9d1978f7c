#include "block/block_sums.hpp"

#include "analysis/gradient_form.hpp"
#include "particles/neighbour_gather.hpp"
#include "particles/pair_pass.hpp"
#include "support/process/parallel_for.hpp"
#include "support/vector_clones.hpp"

#include <cmath>
#include <type_traits>
#include <vector>

namespace sphkern {

namespace {

constexpr std::size_t lanes = neighbour_lanes;

// The sum of W over the `live` neighbours, in eight lanes added in a fixed order.
SPHKERN_ENGINE_CLONES double density_sum(const double* __restrict w, std::size_t n, std::size_t live)
{
    double acc[lanes] = {};
    for (std::size_t base = 0; base < n; base += lanes)
        for (std::size_t l = 0; l < lanes; ++l) acc[l] += base + l < live ? w[base + l] : 0.0;
    double t = 0;
    for (double a : acc) t += a;
    return t;
}

// The sum of weight_ij W'(r) (x_i - x_j) . e / r over the `padded` neighbours, with
// (x_i - x_j) . e = -height, height = e . (x_j - x_i), and the weight of each form for
// P = rho0 g depth (inv_r = 0 past the live neighbours). Gravity is normal to the lateral
// sides, so a neighbour's depth is depth_i + height, through a periodic side too: it is not
// gathered.
template <GradientForm form>
SPHKERN_ENGINE_CLONES double gradient_sum(double depth_i, double rho_i, const Neighbours& nb, const double* e,
                                          std::size_t n)
{
    const double *__restrict dx = nb.dx.data(), *__restrict dy = nb.dy.data(), *__restrict dz = nb.dz.data();
    const double *__restrict rho_j = nb.b.data(), *__restrict dw = nb.dw.data(), *__restrict inv_r = nb.inv_r.data();
    double acc[lanes] = {};
    for (std::size_t base = 0; base < n; base += lanes)
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::size_t j = base + l;
            const double height = e[0] * dx[j] + e[1] * dy[j] + e[2] * dz[j];
            const double rj = form == GradientForm::monaghan ? rho_j[j] : 1.0;
            const double weight = gradient_form_weight<form>(depth_i, depth_i + height, rho_i, rj);
            acc[l] += weight * dw[j] * -height * inv_r[j];
        }
    double t = 0;
    for (double a : acc) t += a;
    return t;
}

struct BlockSweep {
    const Kernel& kernel;
    const NeighbourGrid& grid;
    const SweepParameters& parameters;
    bool with_density, with_gradient;
    const double* depth;                  // in the block's order
    const double* rho;                    // in the block's order (Monaghan's form only)
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
        if (with_density) result.eps_rho[i] = parameters.a_p * (self + density_sum(nb.w.data(), padded, n)) / kd - 1;
        if (with_gradient) result.eps_gradp[i] = parameters.a_p * gradient(i, nb, padded, result.gravity) / kd1 - 1;
        return n;
    }

    // Particle i's gradient sum (i in the block's order).
    double gradient(std::size_t i, const Neighbours& nb, std::size_t padded, const Eigen::Vector3d& gravity) const
    {
        const double rho_i = rho ? rho[i] : 1.0, e[3] = {gravity.x(), gravity.y(), gravity.z()};
        auto call = [&](auto form) { return gradient_sum<decltype(form)::value>(depth[i], rho_i, nb, e, padded); };
        switch (parameters.form) {
        case GradientForm::sum: return call(std::integral_constant<GradientForm, GradientForm::sum>{});
        case GradientForm::difference: return call(std::integral_constant<GradientForm, GradientForm::difference>{});
        case GradientForm::monaghan: break;
        }
        return call(std::integral_constant<GradientForm, GradientForm::monaghan>{});
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
        [&](int thread, std::size_t p, Neighbours& nb) { pairs[static_cast<std::size_t>(thread)] += sweep.sum_particle(p, nb, result); },
        [](int) {});
    std::size_t total = 0;
    for (auto p : pairs) total += p;
    return total;
}

} // namespace sphkern
