#include "block/block_particle_set.hpp"

#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace sphkern {

namespace {

// The box's edges per cell: the lateral basis vectors, and the upward normal of unit length
// in place of the vertical one (in 2D the third edge is e_z, which the engine ignores).
Eigen::Matrix3d unit_edges(const Lattice& lattice, const Eigen::Vector3d& gravity)
{
    const int vertical = lattice.dimension - 1;
    Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();
    for (int a = 0; a < vertical; ++a) edges.col(a) = lattice.basis.col(a);
    edges.col(vertical) = -gravity;
    return edges;
}

// The distance between the opposite faces of one cell across each lateral edge (1 / the
// norm of that row of the inverse, as PeriodicBox::smallest_width).
std::array<double, 2> cell_widths(const Lattice& lattice)
{
    Eigen::Matrix3d cell = unit_edges(lattice, block_gravity(lattice));
    if (lattice.dimension == 2) cell.col(2) = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d inverse = cell.inverse();
    return {1 / inverse.row(0).norm(), 1 / inverse.row(1).norm()};
}

} // namespace

// Along each lateral edge, the cells a periodic block needs so that its box is at least
// twice the reach wide between opposite faces: the engine's rule, with a relative margin of
// 1e-12 so that no block it passes is refused by the engine's own check of the box (whose
// height, and so its rounding, is only known once the particles are placed).
void require_periodic_width(const Lattice& lattice, const BlockOptions& options, double reach)
{
    if (!options.periodic) return;
    const auto widths = cell_widths(lattice);
    const double wanted = 2 * reach * (1 + 1e-12);
    for (int a = 0; a < lattice.dimension - 1; ++a) {
        const double per_cell = widths[static_cast<std::size_t>(a)];
        auto width = [&](double cells) { return cells * per_cell; };
        double needed = std::max(1.0, std::ceil(wanted / per_cell) - 1);
        while (width(needed) < wanted) needed += 1;
        if (static_cast<double>(options.cells[static_cast<std::size_t>(a)]) < needed)
            fail_input(fmt::format("a periodic block needs more than {} cells along basis vector {} at this support "
                                   "(R k = {:.6g} d)",
                                   needed - 1, a + 1, reach));
    }
}

double block_points_per_particle(const Lattice& lattice, const BlockOptions& options, double reach)
{
    if (!options.periodic) return 1;
    const auto widths = cell_widths(lattice);
    double points = 1;
    for (std::size_t a = 0; a + 1 < static_cast<std::size_t>(lattice.dimension); ++a)
        points *= 1 + 2 * reach / (static_cast<double>(options.cells[a]) * widths[a]);
    return points;
}

ParticleSet block_particle_set(const Lattice& lattice, const BlockOptions& options, const BlockResult& result,
                               double reach)
{
    const int dim = lattice.dimension;
    ParticleSet set;
    set.name = "the block";
    set.dimension = dim;
    set.spacing = 1;
    set.gravity = result.gravity;
    const std::size_t n = result.particles();
    set.x.resize(n), set.y.resize(n), set.z.resize(n);
    const auto place = [&](const auto& position) {
        ParallelFor pass;
        pass.run_blocks(n, particle_block_size, result.threads, [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Eigen::Vector3d p = position(Eigen::Vector3d(result.x[i], result.y[i], result.z[i]));
                set.x[i] = p.x(), set.y[i] = p.y(), set.z[i] = dim == 3 ? p.z() : 0.0;
            }
        });
    };
    if (!options.periodic) {
        place([](const Eigen::Vector3d& p) { return p; });
        return set;
    }

    const Eigen::Matrix3d unit = unit_edges(lattice, result.gravity);
    // Heights above the lowest particle, and the box's height: the block's and twice a
    // reach of empty space (more than the engine's margin for images, a reach).
    const Eigen::Vector3d up = -result.gravity;
    using Range = std::pair<double, double>;
    const auto [low, high] = parallel_reduce(
        n, result.threads, Range{INFINITY, -INFINITY},
        [&](std::size_t i, Range& r) {
            const double height = up.dot(Eigen::Vector3d(result.x[i], result.y[i], result.z[i]));
            r.first = std::min(r.first, height), r.second = std::max(r.second, height);
        },
        [](Range& r, const Range& block) {
            r.first = std::min(r.first, block.first), r.second = std::max(r.second, block.second);
        });
    PeriodicBox box;
    box.edges = unit;
    for (int a = 0; a < dim - 1; ++a)
        box.edges.col(a) *= static_cast<double>(options.cells[static_cast<std::size_t>(a)]);
    box.edges.col(dim - 1) *= high - low + 4 * reach;
    Eigen::Matrix3d cell = box.edges;
    if (dim == 2) cell.col(2) = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d inverse = cell.inverse();
    const Eigen::Vector3d lift = up * (2 * reach - low);
    place([&](const Eigen::Vector3d& p) {
        Eigen::Vector3d f = inverse * (p + lift);
        for (int a = 0; a < dim - 1; ++a) f[a] -= std::floor(f[a]);
        return Eigen::Vector3d(cell * f);
    });
    set.box = box;
    return set;
}

} // namespace sphkern
