#include "relax/sph_forces.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/pair_pass.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/vector_clones.hpp"

#include <fmt/format.h>

#include <cmath>

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
// (the gradient, up to -1) and of f dx (pi_i + pi_j) (the force, up to m).
struct PairSums {
    double g[3] = {0, 0, 0}, a[3] = {0, 0, 0};
};
SPHKERN_ENGINE_CLONES PairSums pair_sums(const double* __restrict dx, const double* __restrict dy,
                                         const double* __restrict dz, const double* __restrict r,
                                         const double* __restrict dw, const double* __restrict pi, std::size_t n,
                                         double scale, double pi_i)
{
    double gx = 0, gy = 0, gz = 0, ax = 0, ay = 0, az = 0;
    for (std::size_t j = 0; j < n; ++j) {
        const double f = dw[j] * scale / r[j], fp = f * (pi_i + pi[j]);
        gx += f * dx[j], gy += f * dy[j], gz += f * dz[j];
        ax += fp * dx[j], ay += fp * dy[j], az += fp * dz[j];
    }
    PairSums s;
    s.g[0] = gx, s.g[1] = gy, s.g[2] = gz, s.a[0] = ax, s.a[1] = ay, s.a[2] = az;
    return s;
}

// Calls visit(p, neighbours) for every particle of the set on the engine's pair pass, with dx,
// dy, dz, r and a (unless null) of each neighbour within the support radius `reach` (and its edge).
template <class Visit>
void for_each_particle(const NeighbourGrid& grid, const ParticleSet& set, double reach, const double* a, int threads,
                       const Visit& visit)
{
    pair_pass(
        grid, set.name, {{nullptr, search_reach(reach)}, a, nullptr, true, ""}, threads,
        [&](int, std::size_t p, Neighbours& nb) {
            fill_distances(nb);
            visit(p, nb);
        },
        [](int) {});
}

} // namespace

void compute_forces(const Kernel& kernel, const ParticleSet& set, const ForceModel& model, ForceField& out)
{
    const int dim = set.dimension;
    const std::size_t n = set.size();
    const double reach = kernel.support() * model.h, hd = std::pow(model.h, dim);
    out.phases.restart();
    const NeighbourGrid grid(set, reach, model.threads);
    out.phases.lap("grid");
    // Every value is written by the passes: sized, not cleared, so that no thread zeroes them alone.
    out.density.resize(n);
    const double w0 = kernel.w(0, dim, model.k);
    for_each_particle(grid, set, reach, nullptr, model.threads, [&](std::size_t p, Neighbours& nb) {
        scale_distances(nb.r.data(), nb.count, 1 / model.h, nb.q.data());
        kernel.w_batch(nb.q.data(), nb.w.data(), nb.count, dim, model.k);
        const std::size_t i = grid.source(p);
        out.density[i] = model.mass * (w0 + sum_of(nb.w.data(), nb.count)) / hd;
        if (!std::isfinite(out.density[i]))
            fail_non_finite_sum(kernel, dim, model.k, fmt::format("particle {} of {}", i, set.name),
                                fmt::format("h = {:.6g}", model.h), {nb.q.data(), nb.count});
    });
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
    const double scale = 1 / (hd * model.h); // W' = dW/dq: dW/dr = W' / h^(D+1)
    for_each_particle(grid, set, reach, pi_points.data(), model.threads, [&](std::size_t p, Neighbours& nb) {
        scale_distances(nb.r.data(), nb.count, 1 / model.h, nb.q.data());
        kernel.dw_batch(nb.q.data(), nb.dw.data(), nb.count, dim, model.k);
        const std::size_t i = grid.source(p);
        const PairSums s = pair_sums(nb.dx.data(), nb.dy.data(), nb.dz.data(), nb.r.data(), nb.dw.data(), nb.a.data(),
                                     nb.count, scale, model.pressure ? pi[i] : 0.0);
        out.gx[i] = -model.volume * s.g[0], out.gy[i] = -model.volume * s.g[1], out.gz[i] = -model.volume * s.g[2];
        if (model.pressure)
            out.ax[i] = model.mass * s.a[0], out.ay[i] = model.mass * s.a[1], out.az[i] = model.mass * s.a[2];
        if (!std::isfinite(out.gx[i] + out.gy[i] + out.gz[i]) ||
            (model.pressure && !std::isfinite(out.ax[i] + out.ay[i] + out.az[i])))
            fail_non_finite_sum(kernel, dim, model.k, fmt::format("particle {} of {}", i, set.name),
                                fmt::format("h = {:.6g}", model.h), {nb.q.data(), nb.count});
    });
    out.phases.lap("forces");
}

} // namespace sphkern
