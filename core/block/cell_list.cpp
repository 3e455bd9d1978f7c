#include "block/cell_list.hpp"

#include "kernels/kernel.hpp"
#include "support/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace sphkern {

namespace {

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
    const double reach2 = reach * reach * (1 + 2 * support_edge); // (1 + support_edge) squared, as the lattice sums
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

} // namespace

CellList::CellList(const Lattice& lattice, const BlockGeometry& geometry, bool periodic, double reach)
    : basis_(lattice.basis), size_{geometry.size[0], geometry.size[1], geometry.size[2]}, cells_(geometry.cells),
      sites_(lattice.sites()), lateral_(lattice.dimension - 1), periodic_(periodic)
{
    Eigen::Vector3i extent;
    stencil_ = make_stencil(lattice, reach, extent);
    if (periodic)
        for (int i = 0; i < lateral_; ++i)
            if (size_[i] <= 2 * extent[i])
                fail_input("a periodic block needs more than " + std::to_string(2 * extent[i]) +
                           " cells along basis vector " + std::to_string(i + 1) + " at this support (R k = " +
                           std::to_string(reach) + " d)");
}

// The runs of one row of cells, one site pair and one stencil offset: the row's particles
// whose neighbour cell exists, split where a periodic side wraps.
void CellList::row_runs(std::size_t row, int s, int t, const Eigen::Vector3i& o, std::vector<Run>& runs) const
{
    runs.clear();
    const long long c[3] = {0, static_cast<long long>(row) % size_[1], static_cast<long long>(row) / size_[1]};
    long long target[3] = {0, 0, 0};
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    for (int d = 1; d < 3; ++d) {
        target[d] = c[d] + o[d];
        if (target[d] >= 0 && target[d] < size_[d]) continue;
        if (!periodic_ || d >= lateral_) return;
        long long wrap = target[d] < 0 ? size_[d] : -size_[d];
        target[d] += wrap;
        shift -= static_cast<double>(wrap) * basis_.col(d);
    }
    const std::size_t row_i = static_cast<std::size_t>(s) * cells_ + row * static_cast<std::size_t>(size_[0]);
    const std::size_t row_j = static_cast<std::size_t>(t) * cells_ + static_cast<std::size_t>((target[2] * size_[1] + target[1]) * size_[0]);
    auto add = [&](long long lo, long long hi, long long wrap) {
        if (hi <= lo) return;
        Eigen::Vector3d s1 = shift - static_cast<double>(wrap) * basis_.col(0);
        runs.push_back({row_i + static_cast<std::size_t>(lo), row_j + static_cast<std::size_t>(lo + o[0] + wrap),
                        static_cast<std::size_t>(hi - lo), static_cast<std::size_t>(lo), s1});
    };
    add(std::max(0LL, -static_cast<long long>(o[0])), std::min(size_[0], size_[0] - o[0]), 0);
    if (periodic_ && lateral_ > 0) {
        if (o[0] < 0) add(0, -o[0], size_[0]);    // wraps to the far end
        if (o[0] > 0) add(size_[0] - o[0], size_[0], -size_[0]);
    }
}

} // namespace sphkern
