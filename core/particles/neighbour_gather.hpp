// The neighbours of one point of a NeighbourGrid inside a radius: their displacements,
// distances and two per-point values gathered alongside (a volume and a mass, or what a
// caller needs), in the grid's fixed order. The loops are written so that they vectorise.
#pragma once

#include "particles/neighbour_grid.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sphkern {

// A run of candidate points [begin, end) of a bin's neighbourhood.
struct PointRun {
    std::size_t begin, end;
};

// The candidate runs of bin b (those that are not empty).
void runs_of_bin(const NeighbourGrid& grid, std::size_t b, std::vector<PointRun>& runs);

// One point's neighbours (x_j - x_i, r, the gathered values a_j and b_j) and room for q, W
// and W' of a caller; the scratch of the candidates.
struct Neighbours {
    std::vector<double> r2, dx, dy, dz, r, q, a, b, w, dw, inv_r;
    std::vector<std::uint32_t> index;
    std::size_t count = 0;
    void reserve(std::size_t n);
};

// The points of `runs` within sqrt(reach2) of point p, p itself left out, with a[j] and b[j]
// (per point). Throws Error(input) naming both ids for another particle at p's position.
void gather_neighbours(const NeighbourGrid& grid, std::size_t p, const std::vector<PointRun>& runs, double reach2,
                       const double* a, const double* b, const std::string& set_name, Neighbours& nb);

// The fused pair loops take neighbours in groups of this many; gather_near pads to it.
inline constexpr std::size_t neighbour_lanes = 8;

// As gather_neighbours, but over the runs cut to p's support (NeighbourGrid::for_each_run_near)
// and with r2, dx, dy, dz, a and b only (no r, no index), in one pass that keeps the points
// inside: AVX-512 compress where the processor has it. After the `count` neighbours, up to
// the next multiple of neighbour_lanes, entries with a = b = dx = dy = dz = 0 and r2 = reach2.
void gather_near(const NeighbourGrid& grid, std::size_t p, double reach2, const double* a, const double* b,
                 const std::string& set_name, Neighbours& nb);

// q[j] = r[j] * factor.
void scale_distances(const double* r, std::size_t n, double factor, double* q);

} // namespace sphkern
