#include "particles/particle_measures.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/neighbour_grid.hpp"
#include "support/error.hpp"
#include "support/parallel_for.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace sphkern {

double frobenius_norm(const std::array<double, 6>& E, int dimension)
{
    double sum = E[0] * E[0] + E[1] * E[1] + 2 * E[3] * E[3];
    if (dimension == 3) sum += E[2] * E[2] + 2 * (E[4] * E[4] + E[5] * E[5]);
    return std::sqrt(sum);
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The neighbours of one particle, gathered from its runs: displacement, distance, V_j, m_j.
struct Neighbours {
    std::vector<double> dx, dy, dz, r, q, volume, mass, w, dw;
    std::size_t count = 0;
    void reserve(std::size_t n)
    {
        if (dx.size() >= n) return;
        for (auto* v : {&dx, &dy, &dz, &r, &q, &volume, &mass, &w, &dw}) v->resize(std::max<std::size_t>(n, 2 * dx.size()));
    }
};

struct Sweep {
    const Kernel& kernel;
    const ParticleSet& set;
    const MeasureInputs& in;
    const NeighbourGrid& grid;
    std::vector<double> volume, mass; // in point order
    double self_w;                    // w(0) at each particle's own k: recomputed when k varies

    void gather(std::size_t p, double reach2, Neighbours& nb) const
    {
        nb.count = 0;
        const double xi = grid.x()[p], yi = grid.y()[p], zi = grid.z()[p];
        grid.for_each_run(p, [&](std::size_t begin, std::size_t end) {
            nb.reserve(nb.count + (end - begin));
            for (std::size_t s = begin; s < end; ++s) {
                const double dx = grid.x()[s] - xi, dy = grid.y()[s] - yi, dz = grid.z()[s] - zi;
                const double r2 = dx * dx + dy * dy + dz * dz;
                if (r2 > reach2 || s == p) continue;
                if (r2 == 0)
                    fail_input(fmt::format("{}: particles {} and {} are at the same position ({:g}, {:g}, {:g})", set.name,
                                           std::min(grid.source(p), grid.source(s)), std::max(grid.source(p), grid.source(s)),
                                           xi, yi, zi));
                const std::size_t n = nb.count++;
                nb.dx[n] = dx, nb.dy[n] = dy, nb.dz[n] = dz, nb.r[n] = std::sqrt(r2);
                nb.volume[n] = volume[s], nb.mass[n] = mass[s];
            }
        });
    }

    void measure(std::size_t p, Neighbours& nb, ParticleMeasures& out) const
    {
        const std::size_t i = grid.source(p);
        const int dim = set.dimension;
        const double h = in.h[i], k = h / in.spacing, reach = kernel.support() * h;
        gather(p, reach * reach * (1 + 2 * support_edge), nb);
        const std::size_t n = nb.count;
        for (std::size_t j = 0; j < n; ++j) nb.q[j] = nb.r[j] / h;
        kernel.w_batch(nb.q.data(), nb.w.data(), n, dim, k);
        kernel.dw_batch(nb.q.data(), nb.dw.data(), n, dim, k);
        const double w0 = kernel.w(0, dim, k);
        double s0 = volume[p] * w0, sm = mass[p] * w0;
        double m1[3] = {0, 0, 0}, e1[3] = {0, 0, 0}, E[6] = {0, 0, 0, 0, 0, 0};
        for (std::size_t j = 0; j < n; ++j) {
            const double vw = nb.volume[j] * nb.w[j];
            s0 += vw;
            sm += nb.mass[j] * nb.w[j];
            const double d[3] = {nb.dx[j], nb.dy[j], nb.dz[j]};
            // grad_i W_ij = -W'(r) r_ij / r; g collects -V_j W' / r.
            const double g = -nb.volume[j] * nb.dw[j] / nb.r[j];
            for (int a = 0; a < 3; ++a) m1[a] += vw * d[a], e1[a] += g * d[a];
            E[0] += g * d[0] * d[0], E[1] += g * d[1] * d[1], E[2] += g * d[2] * d[2];
            E[3] += g * d[0] * d[1], E[4] += g * d[0] * d[2], E[5] += g * d[1] * d[2];
        }
        const double hd = std::pow(h, dim), hd1 = hd * h;
        out.e0[i] = s0 / hd - 1;
        out.eps_rho[i] = sm / hd / in.rho0 - 1;
        for (int a = 0; a < 3; ++a) out.m1[i][static_cast<std::size_t>(a)] = m1[a] / hd / h;
        for (int a = 0; a < 3; ++a) out.e1[i][static_cast<std::size_t>(a)] = e1[a] / hd1 * h;
        std::array<double, 6> tensor;
        for (int a = 0; a < 6; ++a) tensor[static_cast<std::size_t>(a)] = E[a] / hd1 - (a < dim ? 1.0 : 0.0);
        if (dim == 2) tensor[2] = tensor[4] = tensor[5] = 0;
        out.E[i] = tensor;
        const Eigen::Vector3d g = set.gravity;
        Eigen::Matrix3d T;
        T << tensor[0], tensor[3], tensor[4], tensor[3], tensor[1], tensor[5], tensor[4], tensor[5], tensor[2];
        out.eps_gradp[i] = g.dot(T * g);
        const Eigen::Vector3d e1v(out.e1[i][0], out.e1[i][1], out.e1[i][2]);
        out.eps_gradp_sum[i] = out.eps_gradp[i] + 2 * in.depth * e1v.dot(g);
        out.neighbours[i] = static_cast<int>(n);
        if (!std::isfinite(out.e0[i]) || !std::isfinite(out.eps_gradp[i]) || !std::isfinite(out.eps_rho[i]))
            throw Error(kernel_fault_code(kernel), fmt::format("kernel {} gives a non-finite sum at particle {} of {} (h = {:g}); "
                                                               "no result is given",
                                                               kernel.label(), i, set.name, h));
    }
};

void check_inputs(const ParticleSet& set, const MeasureInputs& in)
{
    const std::size_t n = set.size();
    if (in.h.size() != n || in.volume.size() != n || (!in.mass.empty() && in.mass.size() != n))
        fail_input(fmt::format("{}: smoothing lengths, volumes or masses missing for some particles", set.name));
    if (!std::isfinite(in.rho0) || in.rho0 <= 0) fail_input(fmt::format("the reference density {} is not positive", in.rho0));
    if (!std::isfinite(in.depth) || in.depth < 0) fail_input(fmt::format("--depth {}: expected a non-negative number", in.depth));
    if (!std::isfinite(in.spacing) || in.spacing <= 0) fail_input(fmt::format("{}: the mean spacing is not positive", set.name));
}

} // namespace

ParticleMeasures measure_particles(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& inputs)
{
    check_inputs(set, inputs);
    kernel.require_dimension(set.dimension, set.name);
    const double h_max = *std::max_element(inputs.h.begin(), inputs.h.end());
    require_usable_kernel(kernel, set.dimension, h_max / inputs.spacing);
    auto started = Clock::now();
    const NeighbourGrid grid(set, kernel.support() * h_max);
    std::vector<double> mass = inputs.mass;
    if (mass.empty())
        for (double v : inputs.volume) mass.push_back(inputs.rho0 * v);
    Sweep sweep{kernel, set, inputs, grid, grid.gather(inputs.volume), grid.gather(mass), 0};

    ParticleMeasures out;
    const std::size_t n = set.size();
    out.e0.resize(n), out.eps_rho.resize(n), out.eps_gradp.resize(n), out.eps_gradp_sum.resize(n);
    out.e1.resize(n), out.m1.resize(n), out.E.resize(n), out.neighbours.resize(n);
    out.threads = inputs.threads > 0 ? inputs.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    out.grid_seconds = seconds_since(started);
    spdlog::debug("{}: {} particles and {} ghosts on {} threads", set.name, n, grid.points() - n, out.threads);
    auto t0 = Clock::now();
    const auto& order = grid.sorted_particles();
    ParallelFor pass;
    pass.run(n, out.threads, [&](int, std::size_t begin, std::size_t end) {
        Neighbours nb;
        for (std::size_t t = begin; t < end && pass.keep_going(); ++t) sweep.measure(order[t], nb, out);
    });
    out.seconds = seconds_since(t0);
    for (int count : out.neighbours) out.pairs += static_cast<std::size_t>(count);
    return out;
}

} // namespace sphkern
