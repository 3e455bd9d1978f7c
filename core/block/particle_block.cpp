#include "block/particle_block.hpp"

#include "support/error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <thread>

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
        auto [it, added] = by_layer.emplace(layer[i], LayerRange{layer[i], 0, eps_rho[i], eps_rho[i], eps_gradp[i], eps_gradp[i]});
        auto& l = it->second;
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

// The cell list: bins are the lattice cells themselves (each holds the motif's sites),
// and the stencil keeps the bin offsets whose closest pair of sites is within reach.
struct Stencil {
    std::vector<Eigen::Vector3i> offsets;
    Eigen::Vector3i extent = Eigen::Vector3i::Zero();
};

Stencil make_stencil(const Lattice& lattice, double reach)
{
    Stencil stencil;
    Eigen::Matrix3d inverse = lattice.basis.inverse();
    int range[3] = {0, 0, 0};
    for (int i = 0; i < lattice.dimension; ++i) range[i] = static_cast<int>(std::ceil(inverse.row(i).norm() * reach)) + 1;
    const double reach2 = reach * reach * (1 + 1e-12);
    for (int a = -range[0]; a <= range[0]; ++a)
        for (int b = -range[1]; b <= range[1]; ++b)
            for (int c = -range[2]; c <= range[2]; ++c) {
                double closest = INFINITY;
                for (const auto& ms : lattice.motif)
                    for (const auto& mt : lattice.motif)
                        closest = std::min(closest, (lattice.basis * (Eigen::Vector3d(a, b, c) + mt - ms)).squaredNorm());
                if (closest > reach2) continue;
                stencil.offsets.emplace_back(a, b, c);
                stencil.extent = stencil.extent.cwiseMax(Eigen::Vector3i(std::abs(a), std::abs(b), std::abs(c)));
            }
    return stencil;
}

template <class Work>
void parallel_for(std::size_t n, int threads, const Work& work)
{
    if (threads <= 1) {
        work(0, std::size_t{0}, n);
        return;
    }
    std::vector<std::thread> pool;
    std::size_t chunk = (n + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
    for (int t = 0; t < threads; ++t) {
        std::size_t begin = std::min(n, chunk * static_cast<std::size_t>(t)), end = std::min(n, begin + chunk);
        pool.emplace_back([&work, t, begin, end] { work(t, begin, end); });
    }
    for (auto& th : pool) th.join();
}

} // namespace

BlockResult evaluate_block(const Kernel& kernel, const Lattice& lattice, const BlockOptions& options)
{
    const int dim = lattice.dimension;
    auto started = Clock::now();
    if (!kernel.supports(dim))
        fail_input("kernel " + kernel.name() + " is defined in " + kernel.plugin().dimensions_text() +
                   "D only, not on the " + std::to_string(dim) + "D lattice " + lattice.name);
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
    const double reach = kernel.support() * options.k;
    const Stencil stencil = make_stencil(lattice, reach);
    const int lateral = dim - 1; // the last basis vector is vertical
    if (options.periodic)
        for (int i = 0; i < lateral; ++i)
            if (options.cells[static_cast<std::size_t>(i)] <= 2 * stencil.extent[i])
                fail_input("a periodic block needs more than " + std::to_string(2 * stencil.extent[i]) +
                           " cells along basis vector " + std::to_string(i + 1) + " at this support (R k = " +
                           std::to_string(reach) + " d)");

    BlockResult result;
    result.dimension = dim;
    result.gravity = block_gravity(lattice);
    result.spacing = layer_spacing(lattice, 0, result.gravity);
    result.threads = options.threads > 0 ? options.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const int sites = lattice.sites();
    const long long n1 = options.cells[0], n2 = options.cells[1], n3 = options.cells[2];
    const std::size_t count = static_cast<std::size_t>(total);
    result.positions.resize(count);
    // Particle index = ((c3 * n2 + c2) * n1 + c1) * sites + site: cell by cell.
    for (long long c3 = 0; c3 < n3; ++c3)
        for (long long c2 = 0; c2 < n2; ++c2)
            for (long long c1 = 0; c1 < n1; ++c1)
                for (int s = 0; s < sites; ++s)
                    result.positions[static_cast<std::size_t>(((c3 * n2 + c2) * n1 + c1) * sites + s)] =
                        lattice.basis * (Eigen::Vector3d(double(c1), double(c2), double(c3)) + lattice.motif[static_cast<std::size_t>(s)]);
    std::vector<double> depth(count);
    double top = -INFINITY;
    for (const auto& x : result.positions) top = std::max(top, -result.gravity.dot(x));
    result.layer.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        depth[i] = top + result.gravity.dot(result.positions[i]);
        result.layer[i] = static_cast<int>(std::lround(depth[i] / result.spacing));
    }
    result.timings.setup = seconds_since(started);

    const double reach2 = reach * reach * (1 + 1e-12);
    const long long size[3] = {n1, n2, n3};
    const double kd = std::pow(options.k, dim), kd1 = kd * options.k;
    // The flat index difference of each stencil offset, for cells whose stencil stays inside the block.
    std::vector<std::ptrdiff_t> flat;
    for (const auto& o : stencil.offsets) flat.push_back(static_cast<std::ptrdiff_t>(((o[2] * n2 + o[1]) * n1 + o[0]) * sites));
    // Coordinates packed x, y, z per particle in a plain array: one memory stream per
    // stencil offset, and no aliasing with the output buffers.
    std::vector<double> packed(3 * count);
    for (std::size_t i = 0; i < count; ++i)
        for (int d = 0; d < 3; ++d) packed[3 * i + static_cast<std::size_t>(d)] = result.positions[i][d];
    const Eigen::Vector3d e = result.gravity;
    const double inv_k = 1 / options.k;
    const std::size_t most = flat.size() * static_cast<std::size_t>(sites);

    // The neighbours j != i of particle i within reach: fills q = r / h, height = e . (x_j - x_i)
    // and j; returns how many.
    auto gather = [&, p = packed.data()](std::size_t i, double* __restrict q,
                                                                    double* __restrict height,
                                                                    std::size_t* __restrict index) {
        const long long cell = static_cast<long long>(i) / sites;
        const long long c[3] = {cell % n1, (cell / n1) % n2, cell / (n1 * n2)};
        const double xi = p[3 * i], yi = p[3 * i + 1], zi = p[3 * i + 2];
        const double ex = e.x(), ey = e.y(), ez = e.z();
        std::size_t n = 0;
        bool interior = true;
        for (int d = 0; d < dim; ++d) interior = interior && c[d] >= stencil.extent[d] && c[d] + stencil.extent[d] < size[d];
        if (interior) { // the common case: no bounds, no periodic images
            const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(cell * sites);
            for (std::ptrdiff_t delta : flat)
                for (int s = 0; s < sites; ++s) {
                    const std::size_t j = static_cast<std::size_t>(base + delta + s);
                    const double dx = p[3 * j] - xi, dy = p[3 * j + 1] - yi, dz = p[3 * j + 2] - zi;
                    const double r2 = dx * dx + dy * dy + dz * dz;
                    if (r2 <= reach2 && j != i) {
                        q[n] = std::sqrt(r2) * inv_k;
                        height[n] = ex * dx + ey * dy + ez * dz;
                        index[n++] = j;
                    }
                }
            return n;
        }
        for (const auto& o : stencil.offsets) {
            long long t[3];
            Eigen::Vector3d shift = Eigen::Vector3d::Zero();
            bool inside = true;
            for (int d = 0; d < 3 && inside; ++d) {
                t[d] = c[d] + o[d];
                if (t[d] >= 0 && t[d] < size[d]) continue;
                if (!options.periodic || d >= lateral) {
                    inside = false;
                } else {
                    long long wrap = t[d] < 0 ? 1 : -1;
                    t[d] += wrap * size[d];
                    shift -= static_cast<double>(wrap * size[d]) * lattice.basis.col(d);
                }
            }
            if (!inside) continue;
            std::size_t first = static_cast<std::size_t>(((t[2] * n2 + t[1]) * n1 + t[0]) * sites);
            for (int s = 0; s < sites; ++s) {
                std::size_t j = first + static_cast<std::size_t>(s);
                if (j == i && shift.isZero()) continue;
                const double dx = p[3 * j] + shift.x() - xi, dy = p[3 * j + 1] + shift.y() - yi,
                             dz = p[3 * j + 2] + shift.z() - zi;
                const double r2 = dx * dx + dy * dy + dz * dz;
                if (r2 <= reach2) {
                    q[n] = std::sqrt(r2) * inv_k;
                    height[n] = ex * dx + ey * dy + ez * dz;
                    index[n++] = j;
                }
            }
        }
        return n;
    };

    // Density pass: sum over neighbours, kernel values through the batch interface.
    result.eps_rho.resize(count);
    std::vector<std::size_t> pairs(static_cast<std::size_t>(result.threads));
    auto t = Clock::now();
    const double self = kernel.w(0, dim, options.k);
    parallel_for(count, result.threads, [&](int thread, std::size_t begin, std::size_t end) {
        std::vector<double> q(most), height(most), w(most);
        std::vector<std::size_t> index(most);
        std::size_t found = 0;
        for (std::size_t i = begin; i < end; ++i) {
            std::size_t n = gather(i, q.data(), height.data(), index.data());
            kernel.w_batch(q.data(), w.data(), n, dim, options.k);
            double sum = self;
            for (std::size_t p = 0; p < n; ++p) sum += w[p];
            result.eps_rho[i] = options.a_p * sum / kd - 1;
            found += n;
        }
        pairs[static_cast<std::size_t>(thread)] = found;
    });
    result.timings.density = seconds_since(t);
    for (auto p : pairs) result.pair_interactions += p;

    // Gradient pass: P = rho0 g depth, the chosen form, projected on gravity:
    // sum_j weight_ij W'(r) (x_i - x_j) . e / r, with (x_i - x_j) . e = -height.
    result.eps_gradp.resize(count);
    t = Clock::now();
    const GradientForm form = options.form;
    parallel_for(count, result.threads, [&](int, std::size_t begin, std::size_t end) {
        std::vector<double> q(most), height(most), dw(most);
        std::vector<std::size_t> index(most);
        for (std::size_t i = begin; i < end; ++i) {
            std::size_t n = gather(i, q.data(), height.data(), index.data());
            kernel.dw_batch(q.data(), dw.data(), n, dim, options.k);
            const double depth_i = depth[i], rho_i = 1 + result.eps_rho[i];
            double sum = 0;
            for (std::size_t p = 0; p < n; ++p) {
                const double depth_j = depth[index[p]];
                double weight;
                if (form == GradientForm::sum) weight = depth_i + depth_j;
                else if (form == GradientForm::difference) weight = depth_j - depth_i;
                else {
                    const double rho_j = 1 + result.eps_rho[index[p]];
                    weight = rho_i * (depth_i / (rho_i * rho_i) + depth_j / (rho_j * rho_j));
                }
                sum += weight * dw[p] * -height[p] / (q[p] * options.k);
            }
            result.eps_gradp[i] = options.a_p * sum / kd1 - 1;
        }
    });
    result.timings.gradient = seconds_since(t);
    return result;
}

} // namespace sphkern
