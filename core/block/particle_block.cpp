#include "block/particle_block.hpp"

#include "block/block_geometry.hpp"
#include "block/block_particle_set.hpp"
#include "block/block_sums.hpp"
#include "kernels/kernel_validity.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/work_budget.hpp"
#include "support/text/value_checks.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

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
        auto [it, added] =
            by_layer.emplace(layer[i], LayerRange{layer[i], 0, eps_rho[i], eps_rho[i], eps_gradp[i], eps_gradp[i], {}});
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

} // namespace

BlockResult evaluate_block(const Kernel& kernel, const Lattice& lattice, const BlockOptions& options)
{
    const int dim = lattice.dimension;
    auto started = Clock::now();
    kernel.require_dimension(lattice.dimension, lattice.name);
    check_k(options.k, ValueSource::argument("k"));
    if (!std::isfinite(options.a_p) || options.a_p <= 0) fail_input("a_p must be positive");
    const std::size_t count = checked_block_size(lattice, options);
    require_usable_kernel(kernel, dim, options.k);

    BlockResult result;
    result.dimension = dim;
    result.gravity = block_gravity(lattice);
    result.spacing = surface_planes(lattice, result.gravity).period;
    result.threads = worker_threads(options.threads);
    result.sites = lattice.sites();
    const double reach = search_reach(kernel.support() * options.k);
    require_periodic_width(lattice, options, reach); // before anything is allocated
    check_work_budget("the block", "its particles and their periodic images",
                      static_cast<double>(count) * block_points_per_particle(lattice, options, reach),
                      static_cast<double>(memory_limit_bytes() / bytes_per_block_particle));
    BlockGeometry geometry = place_particles(lattice, options, result);
    // The block is a particle set: its neighbours are the particle engine's.
    const NeighbourGrid grid(block_particle_set(lattice, options, result, reach), reach, result.threads);
    result.timings.setup = seconds_since(started);

    // Sum and difference forms need no densities: one sweep computes each pair's distance
    // once and both sums from it. Monaghan's form needs every density first.
    const SweepParameters parameters{dim, options.k, options.a_p, options.form, reach, options.each_pair_once};
    result.timings.fused = options.form != GradientForm::monaghan;
    spdlog::debug("evaluating a block of {} particles on {} threads", count, result.threads);
    auto t0 = Clock::now();
    if (result.timings.fused) {
        // The densities are not read by these forms.
        result.pair_interactions = sum_block(kernel, grid, geometry, parameters, true, true, nullptr, result);
    } else {
        result.pair_interactions = sum_block(kernel, grid, geometry, parameters, true, false, nullptr, result);
        HugeArray<double> density(count);
        ParallelFor fill_density;
        fill_density.run(count, result.threads, [&](int, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) density[i] = 1 + result.eps_rho[i];
        });
        sum_block(kernel, grid, geometry, parameters, false, true, density.data(), result);
    }
    result.timings.evaluation = seconds_since(t0);
    if (const auto i = first_index_where(count, result.threads, [&](std::size_t i) {
            return !std::isfinite(result.eps_rho[i]) || !std::isfinite(result.eps_gradp[i]);
        }))
        fail_non_finite_sum(kernel, dim, options.k, "particle " + std::to_string(*i) + " of the block",
                            fmt::format("k = {:.6g}", options.k));
    return result;
}

} // namespace sphkern
