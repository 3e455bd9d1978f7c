#include "lattices/rectangular_cell.hpp"

#include "support/error.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace sphkern {

namespace {

constexpr int search_cells = 12;
constexpr double tolerance = 1e-9; // lattices are rescaled to d = 1

// The shortest n (integer, in primitive cells) whose translation B n points along +axis.
std::optional<Eigen::Vector3i> translation_along(const Lattice& lattice, int axis)
{
    const int d = lattice.dimension, r = search_cells, rz = d == 3 ? r : 0;
    std::optional<Eigen::Vector3i> best;
    double shortest = INFINITY;
    for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j)
            for (int k = -rz; k <= rz; ++k) {
                const Eigen::Vector3i n(i, j, k);
                const Eigen::Vector3d t = lattice.basis * n.cast<double>();
                bool along = t[axis] > tolerance;
                for (int a = 0; a < d; ++a) along = along && (a == axis || std::abs(t[a]) < tolerance);
                if (along && t[axis] < shortest) shortest = t[axis], best = n;
            }
    return best;
}

} // namespace

Lattice rectangular_cell(const Lattice& lattice)
{
    const int d = lattice.dimension;
    Eigen::Matrix3i m = Eigen::Matrix3i::Identity(); // primitive cells per rectangular edge, as columns
    Eigen::Vector3d sides(1, 1, 1);
    for (int a = 0; a < d; ++a) {
        const auto n = translation_along(lattice, a);
        if (!n)
            fail_input(fmt::format("{}: no lattice translation along axis {} within {} cells; expected a lattice "
                                   "whose rows lie along the axes for a rectangular cell",
                                   lattice.name, a + 1, search_cells));
        m.col(a) = *n;
        sides[a] = (lattice.basis * n->cast<double>())[a];
    }
    const int cells = std::abs(static_cast<int>(std::lround(m.cast<double>().determinant())));
    // Every site of the primitive cells that can reach into the rectangle, kept if inside it.
    Lattice out = lattice;
    out.basis = Eigen::Matrix3d::Identity();
    for (int a = 0; a < d; ++a) out.basis(a, a) = sides[a];
    out.motif.clear();
    const int r = search_cells * d, rz = d == 3 ? r : 0;
    for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j)
            for (int k = -rz; k <= rz; ++k)
                for (const Eigen::Vector3d& s : lattice.motif) {
                    const Eigen::Vector3d p = lattice.basis * (Eigen::Vector3d(i, j, k) + s);
                    Eigen::Vector3d f = Eigen::Vector3d::Zero();
                    bool inside = true;
                    for (int a = 0; a < d; ++a) {
                        f[a] = p[a] / sides[a];
                        if (std::abs(f[a] - std::round(f[a])) < tolerance) f[a] = std::round(f[a]); // on an edge
                        inside = inside && f[a] >= 0 && f[a] < 1;
                    }
                    if (inside) out.motif.push_back(f);
                }
    std::sort(out.motif.begin(), out.motif.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        return std::tie(a.z(), a.y(), a.x()) < std::tie(b.z(), b.y(), b.x());
    });
    if (out.motif.size() != static_cast<std::size_t>(cells) * lattice.motif.size())
        throw std::logic_error(fmt::format("rectangular_cell: {} sites of {} in a cell of {} primitive cells",
                                           out.motif.size(), lattice.name, cells));
    return out;
}

} // namespace sphkern
