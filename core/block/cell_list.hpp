// The block's cell list: the bins are the lattice cells themselves (each holds the motif's
// sites), particles are stored site-major so that a row of cells is a contiguous run, and
// the neighbours of a row are visited as runs, one per stencil offset and site pair.
#pragma once

#include "block/block_geometry.hpp"
#include "lattices/lattice.hpp"

#include <Eigen/Dense>

#include <vector>

namespace sphkern {

// A contiguous run of particles i = first_i + p and their neighbours j = first_j + p
// (seen through a periodic image shifted by `shift`), p < length.
struct Run {
    std::size_t first_i, first_j, length, offset; // offset: of the run's first particle in its row
    Eigen::Vector3d shift;
};

class CellList {
public:
    // Throws Error(input) for cells too skewed for the reach, or a periodic block too
    // narrow for it.
    CellList(const Lattice& lattice, const BlockGeometry& geometry, bool periodic, double reach);

    std::size_t rows() const { return static_cast<std::size_t>(size_[1] * size_[2]); }

    // Every run of row `row` (fixed c2, c3) for site s, in stencil order whatever thread
    // asks, so that sums do not depend on the thread count; the particle itself is left out.
    template <class Visit>
    void for_each_run(std::size_t row, int s, std::vector<Run>& runs, Visit&& visit) const
    {
        for (const auto& o : stencil_)
            for (int t = 0; t < sites_; ++t) {
                row_runs(row, s, t, o, runs);
                for (const auto& run : runs) {
                    if (o.isZero() && t == s) continue;
                    visit(run);
                }
            }
    }

private:
    void row_runs(std::size_t row, int s, int t, const Eigen::Vector3i& o, std::vector<Run>& runs) const;

    std::vector<Eigen::Vector3i> stencil_;
    Eigen::Matrix3d basis_;
    long long size_[3];
    std::size_t cells_;
    int sites_, lateral_;
    bool periodic_;
};

} // namespace sphkern
