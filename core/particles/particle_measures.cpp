#include "particles/particle_measures.hpp"

#include "kernels/kernel_validity.hpp"
#include "particles/neighbour_grid.hpp"
#include "support/error.hpp"
#include "support/parallel_for.hpp"

#include <sphkern/kernel_plugin_helpers.h> // SPHKERN_VECTOR_CLONES

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

// A plain line on stderr every few seconds of a long sweep, terminal or not: how far, and
// an estimate of the rest.
class ProgressLines {
public:
    ProgressLines(std::string what, std::size_t total) : what_(std::move(what)), total_(total) {}
    void report(std::size_t done)
    {
        const double elapsed = seconds_since(start_);
        if (elapsed - last_ < 3 || done == 0 || done >= total_) return;
        last_ = elapsed;
        const double fraction = static_cast<double>(done) / static_cast<double>(total_);
        spdlog::info("{}: {:.0f}% of the sums after {:.0f} s, about {:.0f} s to go", what_, 100 * fraction, elapsed,
                     elapsed * (1 - fraction) / fraction);
    }

private:
    std::string what_;
    std::size_t total_;
    Clock::time_point start_ = Clock::now();
    double last_ = 0;
};

// The points that may neighbour the particles of one bin, copied into contiguous arrays.
struct Candidates {
    std::vector<double> x, y, z, volume, mass;
    std::vector<std::uint32_t> point;
    std::size_t count = 0;
};

// One particle's neighbours: displacement, distance, q, V_j, m_j, W and W'.
struct Neighbours {
    std::vector<double> r2, dx, dy, dz, r, q, volume, mass, w, dw;
    std::vector<std::uint32_t> index;
    void reserve(std::size_t n)
    {
        if (r2.size() >= n) return;
        for (auto* v : {&r2, &dx, &dy, &dz, &r, &q, &volume, &mass, &w, &dw}) v->resize(n);
        index.resize(n);
    }
};

// r2[c] for every candidate: no branch, so that it vectorises.
SPHKERN_VECTOR_CLONES void squared_distances(const double* __restrict x, const double* __restrict y,
                                             const double* __restrict z, std::size_t n, double xi, double yi, double zi,
                                             double* __restrict r2)
{
    for (std::size_t c = 0; c < n; ++c) {
        const double dx = x[c] - xi, dy = y[c] - yi, dz = z[c] - zi;
        r2[c] = dx * dx + dy * dy + dz * dz;
    }
}

// The candidates inside the support (the particle itself, at r = 0, left out), and the
// number of candidates at r = 0 (1 unless two particles share a position).
std::size_t inside_support(const double* __restrict r2, std::size_t n, double reach2, std::uint32_t* __restrict index,
                           std::size_t& at_zero)
{
    std::size_t m = 0, zero = 0;
    for (std::size_t c = 0; c < n; ++c) {
        index[m] = static_cast<std::uint32_t>(c);
        m += r2[c] <= reach2 && r2[c] > 0;
        zero += r2[c] == 0;
    }
    at_zero = zero;
    return m;
}

struct Sweep {
    const Kernel& kernel;
    const ParticleSet& set;
    const MeasureInputs& in;
    const NeighbourGrid& grid;
    std::vector<double> volume, mass; // in point order

    void gather_candidates(std::size_t bin, Candidates& c) const
    {
        c.count = 0;
        grid.for_each_run_of_bin(bin, [&](std::size_t begin, std::size_t end) {
            const std::size_t n = c.count + (end - begin);
            if (c.x.size() < n)
                for (auto* v : {&c.x, &c.y, &c.z, &c.volume, &c.mass}) v->resize(2 * n);
            if (c.point.size() < n) c.point.resize(2 * n);
            for (std::size_t s = begin; s < end; ++s, ++c.count) {
                c.x[c.count] = grid.x()[s], c.y[c.count] = grid.y()[s], c.z[c.count] = grid.z()[s];
                c.volume[c.count] = volume[s], c.mass[c.count] = mass[s];
                c.point[c.count] = static_cast<std::uint32_t>(s);
            }
        });
    }

    [[noreturn]] void fail_duplicate(std::size_t p, const Candidates& c, const Neighbours& nb) const
    {
        for (std::size_t k = 0; k < c.count; ++k)
            if (nb.r2[k] == 0 && c.point[k] != p) {
                const auto a = grid.source(p), b = grid.source(c.point[k]);
                fail_input(fmt::format("{}: particles {} and {} are at the same position ({:g}, {:g}, {:g})", set.name,
                                       std::min(a, b), std::max(a, b), grid.x()[p], grid.y()[p], grid.z()[p]));
            }
        fail_input(set.name + ": two particles are at the same position");
    }

    void measure(std::size_t p, const Candidates& c, Neighbours& nb, ParticleMeasures& out) const
    {
        const std::size_t i = grid.source(p);
        const int dim = set.dimension;
        const double h = in.h[i], k = h / in.spacing, reach = kernel.support() * h, inv_h = 1 / h;
        const double xi = grid.x()[p], yi = grid.y()[p], zi = grid.z()[p];
        nb.reserve(c.count);
        squared_distances(c.x.data(), c.y.data(), c.z.data(), c.count, xi, yi, zi, nb.r2.data());
        std::size_t at_zero = 0;
        const std::size_t n = inside_support(nb.r2.data(), c.count, reach * reach * (1 + 2 * support_edge), nb.index.data(), at_zero);
        if (at_zero != 1) fail_duplicate(p, c, nb);
        for (std::size_t j = 0; j < n; ++j) {
            const std::uint32_t t = nb.index[j];
            nb.dx[j] = c.x[t] - xi, nb.dy[j] = c.y[t] - yi, nb.dz[j] = c.z[t] - zi;
            nb.r[j] = std::sqrt(nb.r2[t]);
            nb.q[j] = nb.r[j] * inv_h;
            nb.volume[j] = c.volume[t], nb.mass[j] = c.mass[t];
        }
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
        store(i, n, h, s0, sm, m1, e1, E, out);
    }

    void store(std::size_t i, std::size_t n, double h, double s0, double sm, const double* m1, const double* e1,
               const double* E, ParticleMeasures& out) const
    {
        const int dim = set.dimension;
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
    const Sweep sweep{kernel, set, inputs, grid, grid.gather(inputs.volume), grid.gather(mass)};

    ParticleMeasures out;
    const std::size_t n = set.size();
    out.e0.resize(n), out.eps_rho.resize(n), out.eps_gradp.resize(n), out.eps_gradp_sum.resize(n);
    out.e1.resize(n), out.m1.resize(n), out.E.resize(n), out.neighbours.resize(n);
    out.threads = inputs.threads > 0 ? inputs.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    out.grid_seconds = seconds_since(started);
    spdlog::debug("{}: {} particles and {} ghosts on {} threads", set.name, n, grid.points() - n, out.threads);
    auto t0 = Clock::now();
    // Bin by bin: the candidates of a bin are gathered once for all its particles.
    ParallelFor pass;
    ProgressLines progress(set.name, grid.bins());
    pass.run(grid.bins(), out.threads, [&](int thread, std::size_t begin, std::size_t end) {
        Candidates candidates;
        Neighbours nb;
        for (std::size_t b = begin; b < end && pass.keep_going(); ++b) {
            if (thread == 0 && (b & 255) == 0) progress.report((b - begin) * static_cast<std::size_t>(out.threads));
            bool gathered = false;
            for (std::size_t p = grid.bin_begin(b); p < grid.bin_begin(b + 1); ++p) {
                if (grid.is_ghost(p)) continue;
                if (!gathered) sweep.gather_candidates(b, candidates), gathered = true;
                sweep.measure(p, candidates, nb, out);
            }
        }
    });
    out.seconds = seconds_since(t0);
    for (int count : out.neighbours) out.pairs += static_cast<std::size_t>(count);
    return out;
}

} // namespace sphkern
