#include "particles/tiled_set.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>

namespace sphkern {

ParticleSet tiled_set(const ParticleSet& set, const std::array<int, 3>& tiles, int threads)
{
    if (!set.box) fail_input(fmt::format("{}: only a set with a periodic box can be tiled", set.name));
    const int dim = set.dimension;
    const std::size_t n = set.size();
    double copies = 1;
    for (int a = 0; a < dim; ++a) copies *= tiles[static_cast<std::size_t>(a)];
    if (copies * static_cast<double>(n) > static_cast<double>(max_particles()))
        fail_input(fmt::format("{}: {:.0f} copies of {} particles, more than the memory budget holds ({} particles)",
                               set.name, copies, n, max_particles()));
    ParticleSet out = set;
    const auto total = static_cast<std::size_t>(copies) * n;
    for (auto* column : {&out.x, &out.y, &out.z}) column->resize(total);
    for (auto* column : {&out.h, &out.mass, &out.density})
        if (!column->empty()) column->resize(total);
    const Eigen::Matrix3d& edges = set.box->edges;
    // Copy c is at (c % t0, c / t0 % t1, c / (t0 t1)) edges from the original.
    const std::size_t t0 = static_cast<std::size_t>(tiles[0]), t1 = static_cast<std::size_t>(dim >= 2 ? tiles[1] : 1);
    ParallelFor copying;
    copying.run_blocks(total, particle_block_size, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::size_t c = k / n, i = k % n;
            const double along[3] = {static_cast<double>(c % t0), static_cast<double>(c / t0 % t1),
                                     dim == 3 ? static_cast<double>(c / (t0 * t1)) : 0.0};
            const Eigen::Vector3d shift = edges.col(0) * along[0] + edges.col(1) * along[1] + edges.col(2) * along[2];
            out.x[k] = set.x[i] + shift.x(), out.y[k] = set.y[i] + shift.y(),
            out.z[k] = dim == 3 ? set.z[i] + shift.z() : 0.0;
            if (!set.h.empty()) out.h[k] = set.h[i];
            if (!set.mass.empty()) out.mass[k] = set.mass[i];
            if (!set.density.empty()) out.density[k] = set.density[i];
        }
    });
    for (int a = 0; a < dim; ++a) out.box->edges.col(a) *= tiles[static_cast<std::size_t>(a)];
    return out;
}

} // namespace sphkern
