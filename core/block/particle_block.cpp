#include "block/particle_block.hpp"

#include "kernels/kernel_validity.hpp"
#include "support/error.hpp"
#include "support/parallel_for.hpp"

#include <spdlog/spdlog.h>

#include <sphkern/kernel_plugin_helpers.h> // SPHKERN_VECTOR_CLONES

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <thread>
#include <type_traits>

namespace sphkern {

Eigen::Vector3d block_gravity(const Lattice& lattice)
{
    Eigen::Vector3d up;
    if (lattice.dimension == 2) {
        Eigen::Vector3d a1 = lattice.basis.col(0);
        up = Eigen::Vector3d(-a1.y(), a1.x(), 0).normalized();
        if (up.dot(lattice.basis.col(1)) < 0) up = -up;
    } else {
        up = lattice.basis.col(0).cross(lattice.basis.col(1)).normalized();
        if (up.dot(lattice.basis.col(2)) < 0) up = -up;
    }
    return -up;
}

std::vector<LayerRange> BlockResult::layers() const
{
    std::map<int, LayerRange> by_layer;
    for (std::size_t i = 0; i < layer.size(); ++i) {
        auto [it, added] = by_layer.emplace(layer[i], LayerRange{layer[i], 0, eps_rho[i], eps_rho[i], eps_gradp[i], eps_gradp[i], {}});
        auto& l = it->second;
        const int site = static_cast<int>(i / (layer.size() / static_cast<std::size_t>(sites)));
        if (std::find(l.sites.begin(), l.sites.end(), site) == l.sites.end()) l.sites.push_back(site);
        l.particles += 1;
        l.rho_min = std::min(l.rho_min, eps_rho[i]);
        l.rho_max = std::max(l.rho_max, eps_rho[i]);
        l.gradp_min = std::min(l.gradp_min, eps_gradp[i]);
        l.gradp_max = std::max(l.gradp_max, eps_gradp[i]);
    }
    std::vector<LayerRange> list;
    for (const auto& [n, l] : by_layer) list.push_back(l);
    return list;
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The cell list: the bins are the lattice cells themselves (each holds the motif's
// sites), and the stencil keeps the bin offsets whose closest pair of sites is in reach.
std::vector<Eigen::Vector3i> make_stencil(const Lattice& lattice, double reach, Eigen::Vector3i& extent)
{
    std::vector<Eigen::Vector3i> offsets;
    extent.setZero();
    Eigen::Matrix3d inverse = lattice.basis.inverse();
    int range[3] = {0, 0, 0};
    double cells = 1;
    for (int i = 0; i < lattice.dimension; ++i) {
        const double r = std::ceil(inverse.row(i).norm() * reach) + 1;
        cells *= 2 * r + 1;
        range[i] = static_cast<int>(std::min(r, 1e6));
    }
    if (cells > 1e6)
        fail_input("the block's cells are too skewed for a support of " + std::to_string(reach) +
                   " d: the neighbour stencil would search " + std::to_string(cells) + " cells");
    const double reach2 = reach * reach * (1 + 1e-12);
    // Offsets into one neighbour row of cells follow each other: that row stays in cache.
    for (int c = -range[2]; c <= range[2]; ++c)
        for (int b = -range[1]; b <= range[1]; ++b)
            for (int a = -range[0]; a <= range[0]; ++a) {
                double closest = INFINITY;
                for (const auto& ms : lattice.motif)
                    for (const auto& mt : lattice.motif)
                        closest = std::min(closest, (lattice.basis * (Eigen::Vector3d(a, b, c) + mt - ms)).squaredNorm());
                if (closest > reach2) continue;
                offsets.emplace_back(a, b, c);
                extent = extent.cwiseMax(Eigen::Vector3i(std::abs(a), std::abs(b), std::abs(c)));
            }
    return offsets;
}

// A contiguous run of particles i = first_i + p and their neighbours j = first_j + p
// (seen through a periodic image shifted by `shift`), p < length.
struct Run {
    std::size_t first_i, first_j, length, offset; // offset: of the run's first particle in its row
    Eigen::Vector3d shift;
};

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
        double weight;
        if constexpr (form == GradientForm::sum) weight = depth_i[p] + depth_j[p];
        else if constexpr (form == GradientForm::difference) weight = depth_j[p] - depth_i[p];
        else weight = rho_i[p] * (depth_i[p] / (rho_i[p] * rho_i[p]) + depth_j[p] / (rho_j[p] * rho_j[p]));
        const double term = weight * dw[p] * -height[p] * inv_r[p];
        sum[p] += r2[p] <= reach2 ? term : 0.0;
    }
}

} // namespace

BlockResult evaluate_block(const Kernel& kernel, const Lattice& lattice, const BlockOptions& options)
{
    const int dim = lattice.dimension;
    auto started = Clock::now();
    kernel.require_dimension(lattice.dimension, lattice.name);
    if (!std::isfinite(options.k) || options.k <= 0 || options.k > 100) fail_input("k must be in (0, 100]");
    if (!std::isfinite(options.a_p) || options.a_p <= 0) fail_input("a_p must be positive");
    long double total = lattice.sites();
    for (int i = 0; i < 3; ++i) {
        long long n = options.cells[static_cast<std::size_t>(i)];
        if (i >= dim && n != 1) fail_input("a " + std::to_string(dim) + "D block takes " + std::to_string(dim) + " sizes");
        if (n < 1) fail_input("block size " + std::to_string(n) + " along basis vector " + std::to_string(i + 1) +
                              " is not allowed, expected a positive number of cells");
        total *= static_cast<long double>(n);
    }
    if (total > static_cast<long double>(max_block_particles)) {
        std::ostringstream s;
        s << "a block of " << static_cast<double>(total) << " particles is more than the limit of " << max_block_particles
          << " (about " << max_block_particles * 100 / (1 << 20) << " MiB of memory)";
        fail_input(s.str());
    }
    require_usable_kernel(kernel, dim, options.k);
    const double reach = kernel.support() * options.k;
    Eigen::Vector3i extent;
    const auto stencil = make_stencil(lattice, reach, extent);
    const int lateral = dim - 1; // the last basis vector is vertical
    if (options.periodic)
        for (int i = 0; i < lateral; ++i)
            if (options.cells[static_cast<std::size_t>(i)] <= 2 * extent[i])
                fail_input("a periodic block needs more than " + std::to_string(2 * extent[i]) +
                           " cells along basis vector " + std::to_string(i + 1) + " at this support (R k = " +
                           std::to_string(reach) + " d)");

    BlockResult result;
    result.dimension = dim;
    result.gravity = block_gravity(lattice);
    result.spacing = surface_planes(lattice, result.gravity).period;
    result.threads = options.threads > 0 ? options.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const int sites = lattice.sites();
    result.sites = sites;
    const long long size[3] = {options.cells[0], options.cells[1], options.cells[2]};
    const long long n1 = size[0], n2 = size[1], n3 = size[2];
    const std::size_t cells = static_cast<std::size_t>(n1 * n2 * n3), count = static_cast<std::size_t>(total);
    // Site-major order: particle (site s, cell c) is s * cells + c, c = (c3 * n2 + c2) * n1 + c1,
    // so that a row of cells is a contiguous run for every site.
    // Every per-particle array is first touched by the thread that fills it.
    result.x = HugeArray<double>(count);
    result.y = HugeArray<double>(count);
    result.z = HugeArray<double>(count);
    result.layer = HugeArray<int>(count);
    result.eps_rho = HugeArray<double>(count);
    result.eps_gradp = HugeArray<double>(count);
    HugeArray<double> depth(count);
    double* x = result.x.data();
    double* y = result.y.data();
    double* z = result.z.data();
    // The highest particle sits in the top cell layer: the maximum height over the motif.
    double top = -INFINITY;
    for (const auto& m : lattice.motif)
        for (long long corner : {0LL, size[dim - 1] - 1}) {
            Eigen::Vector3d index = Eigen::Vector3d::Zero();
            index[dim - 1] = static_cast<double>(corner);
            top = std::max(top, -result.gravity.dot(lattice.basis * (index + m)));
        }
    // The layers are the occupied planes, top first, ranked by depth (several sites may share
    // one, and planes need not be equally spaced): the plane of (vertical cell, site).
    const long long vertical = size[dim - 1];
    std::vector<std::pair<double, std::size_t>> plane_depths; // depth, vertical cell * sites + site
    for (long long c = 0; c < vertical; ++c)
        for (int s = 0; s < sites; ++s) {
            Eigen::Vector3d index = Eigen::Vector3d::Zero();
            index[dim - 1] = static_cast<double>(c);
            plane_depths.emplace_back(top + result.gravity.dot(lattice.basis * (index + lattice.motif[static_cast<std::size_t>(s)])),
                                      static_cast<std::size_t>(c * sites + s));
        }
    std::sort(plane_depths.begin(), plane_depths.end());
    std::vector<int> plane_of(plane_depths.size());
    int rank = 0;
    for (std::size_t i = 0; i < plane_depths.size(); ++i) {
        if (i > 0 && plane_depths[i].first - plane_depths[i - 1].first > 1e-9) ++rank;
        plane_of[plane_depths[i].second] = rank;
    }
    ParallelFor fill;
    fill.run(count, result.threads, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t s = i / cells;
            const long long cc = static_cast<long long>(i - s * cells);
            const Eigen::Vector3d index(double(cc % n1), double((cc / n1) % n2), double(cc / (n1 * n2)));
            const Eigen::Vector3d p = lattice.basis * (index + lattice.motif[s]);
            x[i] = p.x();
            y[i] = p.y();
            z[i] = p.z();
            depth[i] = top + result.gravity.dot(p);
            const long long vertical_cell = dim == 3 ? cc / (n1 * n2) : (cc / n1) % n2;
            result.layer[i] = plane_of[static_cast<std::size_t>(vertical_cell) * static_cast<std::size_t>(sites) + s];
            result.eps_rho[i] = 0; // touched here, in this thread, rather than in the sweep
            result.eps_gradp[i] = 0;
        }
    });
    result.timings.setup = seconds_since(started);

    const double reach2 = reach * reach * (1 + 1e-12);
    const double k = options.k, inv_k = 1 / k, kd = std::pow(k, dim), kd1 = kd * k;

    // The runs of one row of cells (fixed c2, c3), one site pair and one stencil offset:
    // the row's particles whose neighbour cell exists, split where a periodic side wraps.
    auto row_runs = [&](std::size_t row, int s, int t, const Eigen::Vector3i& o, std::vector<Run>& runs) {
        runs.clear();
        const long long c[3] = {0, static_cast<long long>(row) % n2, static_cast<long long>(row) / n2};
        long long target[3] = {0, 0, 0};
        Eigen::Vector3d shift = Eigen::Vector3d::Zero();
        for (int d = 1; d < 3; ++d) {
            target[d] = c[d] + o[d];
            if (target[d] >= 0 && target[d] < size[d]) continue;
            if (!options.periodic || d >= lateral) return;
            long long wrap = target[d] < 0 ? size[d] : -size[d];
            target[d] += wrap;
            shift -= static_cast<double>(wrap) * lattice.basis.col(d);
        }
        const std::size_t row_i = static_cast<std::size_t>(s) * cells + row * static_cast<std::size_t>(n1);
        const std::size_t row_j = static_cast<std::size_t>(t) * cells + static_cast<std::size_t>((target[2] * n2 + target[1]) * n1);
        auto add = [&](long long lo, long long hi, long long wrap) {
            if (hi <= lo) return;
            Eigen::Vector3d s1 = shift - static_cast<double>(wrap) * lattice.basis.col(0);
            runs.push_back({row_i + static_cast<std::size_t>(lo), row_j + static_cast<std::size_t>(lo + o[0] + wrap),
                            static_cast<std::size_t>(hi - lo), static_cast<std::size_t>(lo), s1});
        };
        add(std::max(0LL, -static_cast<long long>(o[0])), std::min(n1, n1 - o[0]), 0);
        if (options.periodic && lateral > 0) {
            if (o[0] < 0) add(0, -o[0], n1);    // wraps to the far end
            if (o[0] > 0) add(n1 - o[0], n1, -n1);
        }
    };
    // Every particle of a row sums its neighbours in stencil order whatever thread does the
    // row, so the results do not depend on the thread count.
    const std::size_t rows = static_cast<std::size_t>(n2 * n3);
    auto for_each_run = [&](std::size_t row, int s, std::vector<Run>& runs, auto&& visit) {
        for (const auto& o : stencil)
            for (int t = 0; t < sites; ++t) {
                row_runs(row, s, t, o, runs);
                for (const auto& run : runs) {
                    // The particle itself: offset 0, same site, no image.
                    if (o.isZero() && t == s) continue;
                    visit(run);
                }
            }
    };

    // The sums. Sum and difference forms need no densities: one sweep computes each pair's
    // distance once and both sums from it. Monaghan's form needs every density first.
    const GradientForm form = options.form;
    result.timings.fused = form != GradientForm::monaghan;
    std::vector<std::size_t> pairs(static_cast<std::size_t>(result.threads));
    const double self = kernel.w(0, dim, k);
    auto sweep = [&](bool with_density, bool with_gradient, const double* rho) {
        ParallelFor pass;
        pass.run(rows, result.threads, [&](int thread, std::size_t begin, std::size_t end) {
            const std::size_t n = static_cast<std::size_t>(n1);
            std::vector<double> q(n), r2(n), height(n), inv_r(n), w(n), dw(n), rho_sum(n), gradient_sum(n);
            std::vector<Run> runs;
            std::size_t found = 0;
            for (std::size_t row = begin; row < end && pass.keep_going(); ++row)
                for (int s = 0; s < sites; ++s) {
                    std::fill(rho_sum.begin(), rho_sum.end(), self);
                    std::fill(gradient_sum.begin(), gradient_sum.end(), 0.0);
                    for_each_run(row, s, runs, [&](const Run& run) {
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
                            run_gradient<decltype(f)::value>(depth.data() + run.first_i, depth.data() + run.first_j,
                                                             rho + run.first_i, rho + run.first_j, dw.data(), height.data(),
                                                             inv_r.data(), r2.data(), reach2, run.length,
                                                             gradient_sum.data() + run.offset);
                        };
                        if (form == GradientForm::sum) call(std::integral_constant<GradientForm, GradientForm::sum>{});
                        else if (form == GradientForm::difference)
                            call(std::integral_constant<GradientForm, GradientForm::difference>{});
                        else call(std::integral_constant<GradientForm, GradientForm::monaghan>{});
                    });
                    const std::size_t first = static_cast<std::size_t>(s) * cells + row * n;
                    if (with_density)
                        for (std::size_t p = 0; p < n; ++p) result.eps_rho[first + p] = options.a_p * rho_sum[p] / kd - 1;
                    if (with_gradient)
                        for (std::size_t p = 0; p < n; ++p)
                            result.eps_gradp[first + p] = options.a_p * gradient_sum[p] / kd1 - 1;
                }
            if (with_density) pairs[static_cast<std::size_t>(thread)] = found;
        });
    };
    spdlog::debug("evaluating a block of {} particles on {} threads", count, result.threads);
    auto t0 = Clock::now();
    if (result.timings.fused) {
        sweep(true, true, depth.data()); // rho is unused by these forms
    } else {
        sweep(true, false, nullptr);
        HugeArray<double> density(count);
        ParallelFor fill_density;
        fill_density.run(count, result.threads, [&](int, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) density[i] = 1 + result.eps_rho[i];
        });
        sweep(false, true, density.data());
    }
    result.timings.evaluation = seconds_since(t0);
    for (auto p : pairs) result.pair_interactions += p;
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(result.eps_rho[i]) || !std::isfinite(result.eps_gradp[i]))
            throw Error(kernel_fault_code(kernel), "kernel " + kernel.label() + " gives a non-finite error at particle " +
                                                       std::to_string(i) + " of the block (k = " + std::to_string(options.k) +
                                                       "); no result is given");
    return result;
}

} // namespace sphkern
