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
#include <optional>
#include <string>

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

// A kept list pays where it serves this many calls or more (BENCHMARKS.md, "Pair lists that last").
constexpr double lasting_calls = 4;

// The kept list where it holds or, where the particles moved since the last call, but so
// little that a new one would last lasting_calls calls, a new one; else none (this call
// searches: with no move seen yet, as at a relaxation's start, a list may not last).
PairList* lasting_list(const ParticleSet& set, const ForceModel& model, double support, KeptPairs& kept)
{
    const double moved = kept.since_last ? kept.since_last->farthest(set, model.threads) : 0.0;
    kept.since_last.emplace(set);
    const bool same = kept.list && kept.list->support() == support;
    if (same && kept.list->follow(set)) return kept.list.get();
    const double half_skin = model.skin * model.h / 2;
    if (!(half_skin > 0 && moved > 0 && moved * lasting_calls <= half_skin)) {
        kept.list.reset();
        return nullptr;
    }
    if (same) kept.list->rebuild(set);
    else kept.list.reset(), kept.list = std::make_shared<PairList>(set, support, 2 * half_skin, model.threads);
    ++kept.builds;
    return kept.list.get();
}

// Where a call's pairs come from: a kept list, or a search of this call's own grid.
class PairSource {
public:
    PairSource(const ParticleSet& set, const ForceModel& model, double support, KeptPairs* kept)
        : list_(kept ? lasting_list(set, model, support, *kept) : nullptr), support_(support), set_name_(set.name)
    {
        if (!list_) grid_.emplace(set, support, model.threads), order_.emplace(*grid_);
    }
    const NeighbourGrid& grid() const { return list_ ? list_->grid() : *grid_; }
    template <std::size_t Q, class Visit>
    void pass(const double* a, int threads, double* sums, const Visit& visit) const
    {
        if (list_) return list_->pass<Q>(a, threads, sums, visit);
        SymmetricPassInputs in{search_reach(support_), a, nullptr, true, ""};
        in.order = &*order_;
        symmetric_pair_pass<Q>(*grid_, set_name_, in, threads, sums, visit);
    }

private:
    const PairList* list_;
    std::optional<NeighbourGrid> grid_;
    std::optional<PairOrder> order_;
    double support_;
    std::string set_name_;
};

// Names the cause of a sum that is not finite: the kernel at a neighbour's q, or else h.
[[noreturn]] void fail_non_finite(const Kernel& kernel, const ParticleSet& set, const ForceModel& model, std::size_t i,
                                  Neighbours& nb)
{
    scale_distances(nb.r.data(), nb.count, 1 / model.h, nb.q.data());
    fail_non_finite_sum(kernel, set.dimension, model.k, fmt::format("particle {} of {}", i, set.name),
                        fmt::format("h = {:.6g}", model.h), {nb.q.data(), nb.count});
}

} // namespace

void compute_forces(const Kernel& kernel, const ParticleSet& set, const ForceModel& model, ForceField& out,
                    KeptPairs* kept)
{
    const int dim = set.dimension;
    const std::size_t n = set.size();
    const double reach = kernel.support() * model.h, hd = std::pow(model.h, dim);
    out.phases.restart();
    const PairSource pairs(set, model, reach, kept);
    const NeighbourGrid& grid = pairs.grid();
    out.phases.lap("grid");
    // Every value is written by the passes: sized, not cleared, so that no thread zeroes them alone.
    out.density.resize(n);
    const double w0 = kernel.w(0, dim, model.k);
    std::vector<double> density(grid.points() + 1, 0.0); // and the unpaired key's
    pairs.pass<1>(nullptr, model.threads, density.data(), [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
        fill_distances(nb);
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
    pairs.pass<6>(pi_points.data(), model.threads, forces.data(),
                  [&](std::size_t p, Neighbours& nb, double* cluster_sums) {
                      fill_distances(nb);
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
