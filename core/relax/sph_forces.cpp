#include "relax/sph_forces.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/symmetric_pair_pass.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/vector_clones.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace sphkern {

double ForceField::pressure(double density, const ForceModel& model) const
{
    return model.rho0 * model.c * model.c / model.gamma * std::pow(density / model.rho0, model.gamma);
}

namespace {

SPHKERN_ENGINE_CLONES double sum_of(const double* __restrict w, std::size_t n)
{
    double total = 0;
    for (std::size_t j = 0; j < n; ++j) total += w[j];
    return total;
}

// f_j = W'(q_j) / (r_j h^(D+1)): grad_i W_ij = -f_j (x_j - x_i). Returns the sums of f dx
// (the gradient, up to -1) and of f dx (pi_i + pi_j) (the force, up to m), and leaves f_j in
// nb.w and f_j (pi_i + pi_j) in nb.q for the pair's other particle, whose terms are their negatives.
struct PairSums {
    double g[3] = {0, 0, 0}, a[3] = {0, 0, 0};
};
SPHKERN_ENGINE_CLONES PairSums pair_sums(Neighbours& nb, double scale, double pi_i)
{
    const double* __restrict dx = nb.dx.data(), * __restrict dy = nb.dy.data(), * __restrict dz = nb.dz.data();
    const double* __restrict r = nb.r.data(), * __restrict dw = nb.dw.data(), * __restrict pi = nb.a.data();
    double* __restrict f_out = nb.w.data(), * __restrict fp_out = nb.q.data();
    double gx = 0, gy = 0, gz = 0, ax = 0, ay = 0, az = 0;
    for (std::size_t j = 0; j < nb.count; ++j) {
        const double f = dw[j] * scale / r[j], fp = f * (pi_i + pi[j]);
        gx += f * dx[j], gy += f * dy[j], gz += f * dz[j];
        ax += fp * dx[j], ay += fp * dy[j], az += fp * dz[j];
        f_out[j] = f, fp_out[j] = fp;
    }
    PairSums s;
    s.g[0] = gx, s.g[1] = gy, s.g[2] = gz, s.a[0] = ax, s.a[1] = ay, s.a[2] = az;
    return s;
}

// Adds p's own force sums to own[0..5] and each paired neighbour's terms (the negatives of
// p's, from f and fp that pair_sums left) to its six in cluster_sums.
void add_force_terms(const PairSums& s, const Neighbours& nb, double* own, double* __restrict cluster_sums)
{
    for (int a = 0; a < 3; ++a) own[a] += s.g[a], own[3 + a] += s.a[a];
    for (std::size_t j = 0; j < nb.count; ++j) {
        double* theirs = cluster_sums + 6 * static_cast<std::int64_t>(nb.slot[j]);
        const double f = nb.w[j], fp = nb.q[j], d[3] = {nb.dx[j], nb.dy[j], nb.dz[j]};
        for (int a = 0; a < 3; ++a) theirs[a] -= f * d[a], theirs[3 + a] -= fp * d[a];
    }
}

// Calls visit(p, neighbours, cluster_sums) for every particle of the set on the engine's pass
// that takes each pair once, with dx, dy, dz, r, slot and a (unless null) of each later
// neighbour within the support radius `reach` (and its edge); sums of Q quantities a point.
// The density and force passes share the grid and its pair order.
template <std::size_t Q, class Visit>
void for_each_particle(const NeighbourGrid& grid, const PairOrder& order, const ParticleSet& set, double reach,
                       const double* a, int threads, double* sums, const Visit& visit)
{
    SymmetricPassInputs in{search_reach(reach), a, nullptr, true, ""};
    in.order = &order;
    symmetric_pair_pass<Q>(grid, set.name, in, threads, sums, [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
        fill_distances(nb);
        visit(p, nb, cluster_sums);
    });
}

// Names the cause of a sum that is not finite: the kernel at a neighbour's q, or else h.
[[noreturn]] void fail_non_finite(const Kernel& kernel, const ParticleSet& set, const ForceModel& model, std::size_t i,
                                  Neighbours& nb)
{
    scale_distances(nb.r.data(), nb.count, 1 / model.h, nb.q.data());
    fail_non_finite_sum(kernel, set.dimension, model.k, fmt::format("particle {} of {}", i, set.name),
                        fmt::format("h = {:.6g}", model.h), {nb.q.data(), nb.count});
}

} // namespace

void compute_forces(const Kernel& kernel, const ParticleSet& set, const ForceModel& model, ForceField& out)
{
    const int dim = set.dimension;
    const std::size_t n = set.size();
    const double reach = kernel.support() * model.h, hd = std::pow(model.h, dim);
    out.phases.restart();
    const NeighbourGrid grid(set, reach, model.threads);
    const PairOrder order(grid);
    out.phases.lap("grid");
    // Every value is written by the passes: sized, not cleared, so that no thread zeroes them alone.
    out.density.resize(n);
    const double w0 = kernel.w(0, dim, model.k);
    std::vector<double> density(grid.points() + 1, 0.0); // and the unpaired key's
    for_each_particle<1>(grid, order, set, reach, nullptr, model.threads, density.data(),
                         [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
                             scale_distances(nb.r.data(), nb.count, 1 / model.h, nb.q.data());
                             kernel.w_batch(nb.q.data(), nb.w.data(), nb.count, dim, model.k);
                             const double own = sum_of(nb.w.data(), nb.count);
                             if (!std::isfinite(own)) fail_non_finite(kernel, set, model, grid.source(p), nb);
                             density[p] += own;
                             add_to_pairs<1>(nb, {nb.w.data()}, cluster_sums);
                         });
    for_each_visited(grid, model.threads,
                     [&](std::size_t p, std::size_t i) { out.density[i] = model.mass * (w0 + density[p]) / hd; });
    out.phases.lap("density");
    // pi_j = P_j / rho_j^2 in point order, for the force.
    FirstTouchVector<double> pi(n);
    // The equation of state, not the kernel: (rho / rho0)^gamma past a double.
    if (model.pressure)
        if (const auto i = first_index_where(n, model.threads, [&](std::size_t i) {
                pi[i] = out.pressure(out.density[i], model) / (out.density[i] * out.density[i]);
                return !std::isfinite(pi[i]);
            }))
            fail_input(fmt::format("{}: the pressure of particle {} overflows a double (rho / rho0 = {:.4g}, gamma = "
                                   "{:g}); expected a gamma nearer 1 or a smaller time step",
                                   set.name, *i, out.density[*i] / model.rho0, model.gamma));
    const std::vector<double> pi_points = model.pressure ? grid.gather(pi) : std::vector<double>(grid.points(), 0.0);
    for (auto* v : {&out.gx, &out.gy, &out.gz}) v->resize(n);
    for (auto* v : {&out.ax, &out.ay, &out.az}) v->resize(model.pressure ? n : 0);
    const double scale = 1 / (hd * model.h);                  // W' = dW/dq: dW/dr = W' / h^(D+1)
    std::vector<double> forces(6 * (grid.points() + 1), 0.0); // six a point, and the unpaired key's
    for_each_particle<6>(grid, order, set, reach, pi_points.data(), model.threads, forces.data(),
                         [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
                             scale_distances(nb.r.data(), nb.count, 1 / model.h, nb.q.data());
                             kernel.dw_batch(nb.q.data(), nb.dw.data(), nb.count, dim, model.k);
                             const PairSums s = pair_sums(nb, scale, model.pressure ? pi_points[p] : 0.0);
                             if (!std::isfinite(s.g[0] + s.g[1] + s.g[2] + s.a[0] + s.a[1] + s.a[2]))
                                 fail_non_finite(kernel, set, model, grid.source(p), nb);
                             add_force_terms(s, nb, forces.data() + 6 * p, cluster_sums);
                         });
    for_each_visited(grid, model.threads, [&](std::size_t p, std::size_t i) {
        const double* f = forces.data() + 6 * p;
        out.gx[i] = -model.volume * f[0], out.gy[i] = -model.volume * f[1], out.gz[i] = -model.volume * f[2];
        if (model.pressure) out.ax[i] = model.mass * f[3], out.ay[i] = model.mass * f[4], out.az[i] = model.mass * f[5];
    });
    out.phases.lap("forces");
}

} // namespace sphkern
