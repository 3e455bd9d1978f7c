#include "block/block_sweep.hpp"

#include "analysis/gradient_form.hpp"
#include "support/process/parallel_for.hpp"

#include <sphkern/kernel_plugin_helpers.h> // SPHKERN_VECTOR_CLONES

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace sphkern {

namespace {

// q = r / h, r^2 and, for the gradient, height = e . (x_j - x_i) and 1 / r along a run.
// Plain pointers and no branch, so that the compiler vectorises it.
SPHKERN_VECTOR_CLONES void run_distances(const double* __restrict x, const double* __restrict y, const double* __restrict z,
                                         const Run& run, double inv_k, double* __restrict q, double* __restrict r2)
{
    const double sx = run.shift.x(), sy = run.shift.y(), sz = run.shift.z();
    const double *xi = x + run.first_i, *yi = y + run.first_i, *zi = z + run.first_i;
    const double *xj = x + run.first_j, *yj = y + run.first_j, *zj = z + run.first_j;
    for (std::size_t p = 0; p < run.length; ++p) {
        const double dx = xj[p] + sx - xi[p], dy = yj[p] + sy - yi[p], dz = zj[p] + sz - zi[p];
        r2[p] = dx * dx + dy * dy + dz * dz;
        q[p] = std::sqrt(r2[p]) * inv_k;
    }
}

SPHKERN_VECTOR_CLONES void run_distances_heights(const double* __restrict x, const double* __restrict y,
                                                 const double* __restrict z, const Run& run, double inv_k,
                                                 const Eigen::Vector3d& e, double* __restrict q, double* __restrict r2,
                                                 double* __restrict height, double* __restrict inv_r)
{
    const double ex = e.x(), ey = e.y(), ez = e.z(), sx = run.shift.x(), sy = run.shift.y(), sz = run.shift.z();
    const double *xi = x + run.first_i, *yi = y + run.first_i, *zi = z + run.first_i;
    const double *xj = x + run.first_j, *yj = y + run.first_j, *zj = z + run.first_j;
    for (std::size_t p = 0; p < run.length; ++p) {
        const double dx = xj[p] + sx - xi[p], dy = yj[p] + sy - yi[p], dz = zj[p] + sz - zi[p];
        r2[p] = dx * dx + dy * dy + dz * dz;
        const double r = std::sqrt(r2[p]);
        q[p] = r * inv_k;
        inv_r[p] = 1.0 / r;
        height[p] = ex * dx + ey * dy + ez * dz;
    }
}

// sum[p] += w[p] for the pairs within reach (adding +0.0 otherwise leaves the sum as it is).
SPHKERN_VECTOR_CLONES void run_density(const double* __restrict w, const double* __restrict r2, double reach2, std::size_t length,
                 double* __restrict sum, std::size_t& pairs)
{
    std::size_t found = 0;
    for (std::size_t p = 0; p < length; ++p) {
        const bool inside = r2[p] <= reach2;
        sum[p] += inside ? w[p] : 0.0;
        found += inside;
    }
    pairs += found;
}

// sum[p] += weight_ij W'(r) (x_i - x_j) . e / r for the pairs within reach, with
// (x_i - x_j) . e = -height and the weight of each form for P = rho0 g depth.
template <GradientForm form>
SPHKERN_VECTOR_CLONES void run_gradient(const double* __restrict depth_i, const double* __restrict depth_j, const double* __restrict rho_i,
                  const double* __restrict rho_j, const double* __restrict dw, const double* __restrict height,
                  const double* __restrict inv_r, const double* __restrict r2, double reach2, std::size_t length,
                  double* __restrict sum)
{
    for (std::size_t p = 0; p < length; ++p) {
        const double weight = gradient_form_weight<form>(depth_i[p], depth_j[p], rho_i[p], rho_j[p]);
        const double term = weight * dw[p] * -height[p] * inv_r[p];
        sum[p] += r2[p] <= reach2 ? term : 0.0;
    }
}

} // namespace

std::size_t sweep_block(const Kernel& kernel, const CellList& cells, const BlockGeometry& geometry,
                        const SweepParameters& parameters, bool with_density, bool with_gradient, const double* rho,
                        BlockResult& result)
{
    const int dim = parameters.dimension;
    const double k = parameters.k, inv_k = 1 / k, kd = std::pow(k, dim), kd1 = kd * k;
    const double reach = kernel.support() * k, reach2 = reach * reach * (1 + 2 * support_edge);
    const GradientForm form = parameters.form;
    const double self = kernel.w(0, dim, k);
    const int sites = result.sites;
    const double* x = result.x.data();
    const double* y = result.y.data();
    const double* z = result.z.data();
    std::vector<std::size_t> pairs(static_cast<std::size_t>(result.threads));
    ParallelFor pass;
    pass.run(cells.rows(), result.threads, [&](int thread, std::size_t begin, std::size_t end) {
        const std::size_t n = static_cast<std::size_t>(geometry.size[0]);
        std::vector<double> q(n), r2(n), height(n), inv_r(n), w(n), dw(n), rho_sum(n), gradient_sum(n);
        std::vector<Run> runs;
        std::size_t found = 0;
        for (std::size_t row = begin; row < end && pass.keep_going(); ++row)
            for (int s = 0; s < sites; ++s) {
                std::fill(rho_sum.begin(), rho_sum.end(), self);
                std::fill(gradient_sum.begin(), gradient_sum.end(), 0.0);
                cells.for_each_run(row, s, runs, [&](const Run& run) {
                    if (with_gradient)
                        run_distances_heights(x, y, z, run, inv_k, result.gravity, q.data(), r2.data(), height.data(),
                                              inv_r.data());
                    else
                        run_distances(x, y, z, run, inv_k, q.data(), r2.data());
                    if (with_density) {
                        kernel.w_batch(q.data(), w.data(), run.length, dim, k);
                        run_density(w.data(), r2.data(), reach2, run.length, rho_sum.data() + run.offset, found);
                    }
                    if (!with_gradient) return;
                    kernel.dw_batch(q.data(), dw.data(), run.length, dim, k);
                    auto call = [&](auto f) {
                        run_gradient<decltype(f)::value>(geometry.depth.data() + run.first_i, geometry.depth.data() + run.first_j,
                                                         rho + run.first_i, rho + run.first_j, dw.data(), height.data(),
                                                         inv_r.data(), r2.data(), reach2, run.length,
                                                         gradient_sum.data() + run.offset);
                    };
                    if (form == GradientForm::sum) call(std::integral_constant<GradientForm, GradientForm::sum>{});
                    else if (form == GradientForm::difference)
                        call(std::integral_constant<GradientForm, GradientForm::difference>{});
                    else call(std::integral_constant<GradientForm, GradientForm::monaghan>{});
                });
                const std::size_t first = static_cast<std::size_t>(s) * geometry.cells + row * n;
                if (with_density)
                    for (std::size_t p = 0; p < n; ++p) result.eps_rho[first + p] = parameters.a_p * rho_sum[p] / kd - 1;
                if (with_gradient)
                    for (std::size_t p = 0; p < n; ++p)
                        result.eps_gradp[first + p] = parameters.a_p * gradient_sum[p] / kd1 - 1;
            }
        if (with_density) pairs[static_cast<std::size_t>(thread)] = found;
    });
    std::size_t total = 0;
    for (auto p : pairs) total += p;
    return total;
}

} // namespace sphkern
