// Neighbour search for any particle set: a cell list over the particles and, in a periodic
// box, their images within reach of a face ("ghosts"), all sorted in cell order so that the
// candidates of a bin's particles are a few contiguous runs of memory (9 in 3D, 3 in 2D).
// Sums over a bin's runs are taken in a fixed order, whatever thread asks.
#pragma once

#include "particles/particle_set.hpp"

#include <cstdint>
#include <vector>

namespace sphkern {

class NeighbourGrid {
public:
    // Bins are reach / stencil_reach wide and a bin's candidates lie within stencil_reach
    // bins along each axis. Smaller bins hold fewer candidates (5 x 5 x 5 bins of half a reach
    // hold (5/2)^3 reach^3, 3 x 3 x 3 of one reach 27 reach^3), but in more and shorter runs,
    // which cost more than the candidates they save on the sets measured.
    static constexpr std::size_t stencil_reach = 1;

    // `reach`: the largest support radius of any particle. Throws Error(input) for a periodic
    // box narrower than twice the reach (a particle would see two images of one neighbour).
    NeighbourGrid(const ParticleSet& set, double reach);

    std::size_t points() const { return x_.size(); }  // particles and ghosts
    std::size_t particles() const { return particles_; }
    // The particle a point (particle or ghost) stands for.
    std::uint32_t source(std::size_t point) const { return source_[point]; }
    const double* x() const { return x_.data(); }
    const double* y() const { return y_.data(); }
    const double* z() const { return z_.data(); }
    // A per-particle quantity in point order (ghosts carry their particle's value).
    std::vector<double> gather(const std::vector<double>& per_particle) const;

    // Bins in sweep order; the points of bin b are [bin_begin(b), bin_begin(b + 1)).
    std::size_t bins() const { return start_.size() - 1; }
    std::size_t bin_begin(std::size_t b) const { return static_cast<std::size_t>(start_[b]); }
    bool is_ghost(std::size_t point) const { return ghost_[point] != 0; }

    // visit(begin, end) for each run of points that may lie within reach of a point of bin b.
    template <class Visit>
    void for_each_run_of_bin(std::size_t b, Visit&& visit) const
    {
        const std::size_t bx = b % n_[0], by = b / n_[0] % n_[1], bz = b / (n_[0] * n_[1]);
        constexpr std::size_t s = stencil_reach;
        const std::size_t x0 = bx > s ? bx - s : 0, x1 = std::min(bx + s, n_[0] - 1);
        const std::size_t z0 = bz > s ? bz - s : 0, z1 = std::min(bz + s, n_[2] - 1);
        const std::size_t y0 = by > s ? by - s : 0, y1 = std::min(by + s, n_[1] - 1);
        for (std::size_t cz = z0; cz <= z1; ++cz)
            for (std::size_t cy = y0; cy <= y1; ++cy) {
                const std::size_t row = (cz * n_[1] + cy) * n_[0];
                visit(static_cast<std::size_t>(start_[row + x0]), static_cast<std::size_t>(start_[row + x1 + 1]));
            }
    }

private:
    void add_ghosts(const ParticleSet& set, double reach);
    void sort_into_bins(double reach);

    std::size_t particles_ = 0;
    std::vector<double> x_, y_, z_;
    std::vector<std::uint32_t> source_;
    std::vector<std::uint8_t> ghost_;
    std::vector<std::uint64_t> start_; // first point of each bin, and one past the last
    std::size_t n_[3] = {1, 1, 1};
};

} // namespace sphkern
