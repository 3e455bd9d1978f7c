// Voronoi volumes with voro++'s periodic container, which takes a box whose edges are
// (bx, 0, 0), (bxy, by, 0), (bxz, byz, bz): the set is turned into that frame by the QR
// factorisation of its box (a rotation, or a reflection: volumes do not change).
#include "particles/particle_volumes.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <Eigen/QR>
#include <fmt/format.h>
#include <voro++/voro++.hh>

#include <algorithm>
#include <cmath>

namespace sphkern {

std::vector<double> voronoi_volumes(const ParticleSet& set)
{
    const int dim = set.dimension;
    const std::size_t n = set.size();
    Eigen::Matrix3d edges = set.box->edges;
    const double area_or_volume = set.box->volume(dim);
    // A 2D set is a slab one mean spacing thick: its cells are prisms of the 2D cells.
    const double thickness = dim == 2 ? std::sqrt(area_or_volume / static_cast<double>(n)) : 0;
    if (dim == 2) edges.col(2) = Eigen::Vector3d(0, 0, thickness);
    Eigen::HouseholderQR<Eigen::Matrix3d> qr(edges);
    Eigen::Matrix3d Q = qr.householderQ();
    Eigen::Matrix3d U = Q.transpose() * edges;
    for (int a = 0; a < 3; ++a)
        if (U(a, a) < 0) U.row(a) *= -1, Q.col(a) *= -1;
    const double volume = U(0, 0) * U(1, 1) * U(2, 2);
    const double side = std::cbrt(volume / std::max(1.0, static_cast<double>(n) / 5));
    auto blocks = [&](double length) { return std::clamp(static_cast<int>(std::lround(length / side)), 1, 1 << 10); };
    voro::container_periodic container(U(0, 0), U(0, 1), U(1, 1), U(0, 2), U(1, 2), U(2, 2), blocks(U(0, 0)),
                                       blocks(U(1, 1)), dim == 2 ? 1 : blocks(U(2, 2)), 8);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d p = Q.transpose() * set.position(i);
        container.put(static_cast<int>(i), p.x(), p.y(), dim == 2 ? U(2, 2) / 2 : p.z());
    }
    std::vector<double> cells(n, -1);
    voro::c_loop_all_periodic loop(container);
    voro::voronoicell cell;
    std::size_t done = 0;
    if (loop.start()) do {
            if ((++done & 4095) == 0) throw_if_interrupted();
            const int id = loop.pid();
            if (!container.compute_cell(cell, loop))
                fail_input(
                    fmt::format("{}: the Voronoi cell of particle {} cannot be computed (another particle at its "
                                "position?)",
                                set.name, id));
            cells[static_cast<std::size_t>(id)] = dim == 2 ? cell.volume() / thickness : cell.volume();
        } while (loop.inc());
    for (std::size_t i = 0; i < n; ++i)
        if (!(cells[i] > 0)) fail_input(fmt::format("{}: particle {} has no Voronoi cell", set.name, i));
    return cells;
}

} // namespace sphkern
