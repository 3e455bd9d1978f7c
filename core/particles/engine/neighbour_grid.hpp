// Neighbour search for any particle set: a cell list over the particles and, in a periodic
// box, their images within reach of a face ("ghosts"), all sorted in cell order so that the
// candidates of a bin's particles are a few contiguous runs of memory (9 in 3D, 3 in 2D).
// Sums over a bin's runs are taken in a fixed order, whatever thread asks.
#pragma once

#include "particles/particle_set.hpp"
#include "support/process/first_touch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace sphkern {

// The bins of a whole set: along each axis n bins from lo, coordinate c in bin
// floor((c - lo) scale) clamped to [0, n - 1]. A slab of a larger set (particles/slabs) sorts
// its points into the whole set's bins, so that each bin holds the same points in the same order.
struct GridGeometry {
    std::size_t n[3] = {1, 1, 1};
    double lo[3] = {0, 0, 0}, scale[3] = {0, 0, 0};
    std::size_t bin(int a, double c) const
    {
        const double t = std::floor((c - lo[a]) * scale[a]);
        return static_cast<std::size_t>(std::clamp(t, 0.0, static_cast<double>(n[a] - 1)));
    }
    // The bins of `count` points (particles and ghosts) within range = {min x, max x, min y,
    // max y, min z, max z}, for a largest support radius `reach`.
    static GridGeometry of(const std::array<double, 6>& range, std::size_t count, double reach);
};

// A slab of a larger set: the whole set's bins, of which the rows [first, last) along `axis`
// hold points: the slab's own rows [own_first, own_last) and the halo beside them (a row of
// bins is at least a reach wide). Only the particles in the own rows are visited.
struct GridWindow {
    GridGeometry whole;
    int axis = 2;
    std::size_t first = 0, last = 0, own_first = 0, own_last = 0;
};

class NeighbourGrid {
public:
    // Bins are reach / stencil_reach wide across and reach / (stencil_reach x_bins_per_reach)
    // along x, and a bin's candidates lie within stencil_reach bins across (x_bins_per_reach
    // times as many along x). Smaller bins across hold fewer candidates but in more and
    // shorter runs, which cost more than the candidates they save on the sets measured; along
    // x, where a row of bins is one run, narrow bins let a cluster cut each run to the chord of
    // its support (for_each_run_near_box): about 3 candidates per neighbour instead of 6.
    static constexpr std::size_t stencil_reach = 1;
    static constexpr std::size_t x_bins_per_reach = 4;
    // The particles of this many consecutive bins along x form a cluster (half a reach along
    // x, a reach across): the unit whose candidates are gathered once. Measured on fcc and
    // Poisson sets: 2 beats 1 and 4, and cubes of half a reach (2 bins a reach across) hold
    // too few particles to share their candidates (BENCHMARKS.md).
    static constexpr std::size_t bins_per_cluster = 2;

    // `reach`: the largest support radius of any particle. Throws Error(input) for a periodic
    // box narrower than twice the reach (a particle would see two images of one neighbour).
    // Built on `threads` threads; the grid is the same on any number. With a window, the set
    // is a slab of a larger one and only the window's rows are kept.
    NeighbourGrid(const ParticleSet& set, double reach, int threads = 1, const GridWindow* window = nullptr);

    std::size_t points() const { return x_.size(); } // particles and ghosts
    std::size_t particles() const { return particles_; }
    // The particle a point (particle or ghost) stands for.
    std::uint32_t source(std::size_t point) const { return source_[point] & ~unvisited_bit; }
    // The particle's row in its file (ParticleSet::id), for errors.
    std::uint64_t id(std::size_t point) const { return ids_.empty() ? source(point) : ids_[source(point)]; }
    const double* x() const { return x_.data(); }
    const double* y() const { return y_.data(); }
    const double* z() const { return z_.data(); }
    // A per-particle quantity in point order (ghosts carry their particle's value).
    std::vector<double> gather(std::span<const double> per_particle) const;
    int threads() const { return threads_; }

    // Bins in sweep order; the points of bin b are [bin_begin(b), bin_begin(b + 1)).
    std::size_t bins() const { return start_.size() - 1; }
    std::size_t bin_begin(std::size_t b) const { return static_cast<std::size_t>(start_[b]); }
    // A particle the passes visit: not a ghost, nor a particle that is a neighbour only
    // (ParticleSet::neighbours_only), whose points are candidates of the others all the same.
    bool visited(std::size_t point) const { return (source_[point] & unvisited_bit) == 0; }

    // The rows of bins kept along y and z (a row runs along x); the clusters of row (y, z) are
    // [(z rows_y + y) clusters_per_row, + clusters_per_row).
    std::size_t rows(int axis) const { return n_[axis]; }
    std::size_t clusters_per_row() const { return (n_[0] + bins_per_cluster - 1) / bins_per_cluster; }

    // Clusters in sweep order (bins_per_cluster bins of one row); the points of cluster c are
    // [cluster_begin(c), cluster_end(c)).
    std::size_t clusters() const { return n_[1] * n_[2] * clusters_per_row(); }
    std::size_t cluster_begin(std::size_t c) const
    {
        return bin_begin(c / clusters_per_row() * n_[0] + c % clusters_per_row() * bins_per_cluster);
    }
    std::size_t cluster_end(std::size_t c) const
    {
        const std::size_t last = std::min(c % clusters_per_row() * bins_per_cluster + bins_per_cluster, n_[0]);
        return bin_begin(c / clusters_per_row() * n_[0] + last);
    }

    // visit(begin, end) for each run of points that may lie within `reach` (at most the
    // grid's reach) of a point of the box [lo, hi] (inside one bin across, as the points of
    // one cluster are): the rows of bins around it, each cut along x to [lo_x - chord,
    // hi_x + chord] with the chord of `reach` at the row's distance from the box. In a fixed order.
    template <class Visit>
    void for_each_run_near_box(const double* lo, const double* hi, double reach, Visit&& visit) const
    {
        const std::size_t by = bin_along(1, lo[1]), bz = bin_along(2, lo[2]);
        constexpr std::size_t s = stencil_reach;
        const std::size_t z0 = bz > s ? bz - s : 0, z1 = std::min(bz + s, n_[2] - 1);
        const std::size_t y0 = by > s ? by - s : 0, y1 = std::min(by + s, n_[1] - 1);
        for (std::size_t cz = z0; cz <= z1; ++cz) {
            const double gz = gap(2, cz, bz, cz < bz ? lo[2] : hi[2], reach);
            for (std::size_t cy = y0; cy <= y1; ++cy) {
                const double gy = gap(1, cy, by, cy < by ? lo[1] : hi[1], reach);
                const double chord2 = reach * reach - gy * gy - gz * gz;
                if (chord2 < 0) continue;
                const double chord = std::sqrt(chord2);
                const std::size_t row = (cz * n_[1] + cy) * n_[0];
                visit(static_cast<std::size_t>(start_[row + bin_along(0, lo[0] - chord)]),
                      static_cast<std::size_t>(start_[row + bin_along(0, hi[0] + chord) + 1]));
            }
        }
    }

private:
    // The bin of coordinate c along axis a: the one formula of the sort and the search, so
    // that a point within the chord lies in a bin of the cut run (the formula is monotone).
    // Counted from the window's first row (0 for a whole set).
    std::size_t bin_along(int a, double c) const
    {
        return std::clamp(geometry_.bin(a, c), offset_[a], offset_[a] + n_[a] - 1) - offset_[a];
    }
    // The distance along axis a from c (in bin `own`) to bin `cell`, a little short of it
    // (the bin edges are computed, not stored).
    double gap(int a, std::size_t cell, std::size_t own, double c, double reach) const
    {
        if (cell == own) return 0.0;
        const double edge =
            geometry_.lo[a] + static_cast<double>(offset_[a] + (cell < own ? cell + 1 : cell)) / geometry_.scale[a];
        return std::max(0.0, std::abs(c - edge) - 1e-9 * reach);
    }
    struct Unsorted;
    void size_bins(const Unsorted& points, std::size_t count, double reach);
    void sort_into_bins(const Unsorted& points, std::size_t count);
    void sort_rows(const std::vector<std::uint32_t>& row_start);

    int threads_ = 1;
    std::size_t particles_ = 0;
    // Allocated once and first touched by the threads that sort into them.
    FirstTouchVector<double> x_, y_, z_;
    // The particle each point stands for, unvisited_bit set for a ghost or a particle that is a
    // neighbour only (particles number fewer than 2^31).
    static constexpr std::uint32_t unvisited_bit = std::uint32_t{1} << 31;
    std::size_t measured_ = 0; // particles [0, measured_) are visited
    FirstTouchVector<std::uint32_t> source_;
    std::vector<std::uint32_t> start_; // first point of each bin, and one past the last (points number fewer than 2^32)
    GridGeometry geometry_;            // the whole set's bins
    std::size_t n_[3] = {1, 1, 1};     // the bins kept along each axis (a window's rows, or all)
    std::size_t offset_[3] = {0, 0, 0}; // the whole set's bin of the first kept one
    std::vector<std::uint64_t> ids_;    // ParticleSet::ids
};

} // namespace sphkern
