#include "block/block_geometry.hpp"

#include "particles/particles_memory.hpp"
#include "support/process/work_budget.hpp"

#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace sphkern {

std::size_t checked_block_size(const Lattice& lattice, const BlockOptions& options)
{
    const int dim = lattice.dimension;
    long double total = lattice.sites();
    for (int i = 0; i < 3; ++i) {
        long long n = options.cells[static_cast<std::size_t>(i)];
        if (i >= dim && n != 1)
            fail_input("a " + std::to_string(dim) + "D block takes " + std::to_string(dim) + " sizes");
        if (n < 1)
            fail_input("block size " + std::to_string(n) + " along basis vector " + std::to_string(i + 1) +
                       " is not allowed, expected a positive number of cells");
        total *= static_cast<long double>(n);
    }
    // The memory the machine has available now, at the bytes a block particle takes on the
    // particle engine (a peak of 150.5 MiB for 10^6 fcc particles, BENCHMARKS.md), not a fixed
    // count; evaluate_block counts the periodic images too, once it knows the support.
    const double limit = static_cast<double>(memory_limit_bytes() / bytes_per_block_particle);
    check_work_budget("the block", "cells x sites, its particles", static_cast<double>(total), limit);
    return static_cast<std::size_t>(total);
}

namespace {

// The highest particle sits in the top cell layer: the maximum height over the motif.
double top_height(const Lattice& lattice, long long vertical, const Eigen::Vector3d& gravity)
{
    const int dim = lattice.dimension;
    double top = -INFINITY;
    for (const auto& m : lattice.motif)
        for (long long corner : {0LL, vertical - 1}) {
            Eigen::Vector3d index = Eigen::Vector3d::Zero();
            index[dim - 1] = static_cast<double>(corner);
            top = std::max(top, -gravity.dot(lattice.basis * (index + m)));
        }
    return top;
}

// The layers are the occupied planes, top first, ranked by depth (several sites may share
// one, and planes need not be equally spaced): the rank of the plane of (vertical cell, site),
// indexed by vertical cell * sites + site.
std::vector<int> plane_ranks(const Lattice& lattice, long long vertical, double top, const Eigen::Vector3d& gravity)
{
    const int dim = lattice.dimension, sites = lattice.sites();
    std::vector<std::pair<double, std::size_t>> plane_depths; // depth, vertical cell * sites + site
    for (long long c = 0; c < vertical; ++c)
        for (int s = 0; s < sites; ++s) {
            Eigen::Vector3d index = Eigen::Vector3d::Zero();
            index[dim - 1] = static_cast<double>(c);
            plane_depths.emplace_back(top + gravity.dot(lattice.basis *
                                                        (index + lattice.motif[static_cast<std::size_t>(s)])),
                                      static_cast<std::size_t>(c * sites + s));
        }
    std::sort(plane_depths.begin(), plane_depths.end());
    std::vector<int> plane_of(plane_depths.size());
    int rank = 0;
    for (std::size_t i = 0; i < plane_depths.size(); ++i) {
        if (i > 0 && plane_depths[i].first - plane_depths[i - 1].first > 1e-9) ++rank;
        plane_of[plane_depths[i].second] = rank;
    }
    return plane_of;
}

// Site-major order: particle (site s, cell c) is s * cells + c, c = (c3 * n2 + c2) * n1 + c1.
// Every per-particle array is allocated here and first touched by the threads that fill it.
void allocate_particles(std::size_t count, BlockGeometry& geometry, BlockResult& result)
{
    result.x = HugeArray<double>(count);
    result.y = HugeArray<double>(count);
    result.z = HugeArray<double>(count);
    result.layer = HugeArray<int>(count);
    result.eps_rho = HugeArray<double>(count);
    result.eps_gradp = HugeArray<double>(count);
    geometry.depth = HugeArray<double>(count);
}

} // namespace

BlockGeometry place_particles(const Lattice& lattice, const BlockOptions& options, BlockResult& result)
{
    const int dim = lattice.dimension;
    const int sites = lattice.sites();
    const std::size_t count = checked_block_size(lattice, options);
    BlockGeometry geometry;
    const long long n1 = options.cells[0], n2 = options.cells[1], n3 = options.cells[2];
    geometry.size[0] = n1, geometry.size[1] = n2, geometry.size[2] = n3;
    const std::size_t cells = static_cast<std::size_t>(n1 * n2 * n3);
    geometry.cells = cells;
    geometry.count = count;
    allocate_particles(count, geometry, result);
    const long long vertical = geometry.size[dim - 1];
    const double top = top_height(lattice, vertical, result.gravity);
    const std::vector<int> plane_of = plane_ranks(lattice, vertical, top, result.gravity);
    double* x = result.x.data();
    double* y = result.y.data();
    double* z = result.z.data();
    double* depth = geometry.depth.data();
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
            result.eps_rho[i] = 0; // touched here, in these threads
            result.eps_gradp[i] = 0;
        }
    });
    return geometry;
}

} // namespace sphkern
