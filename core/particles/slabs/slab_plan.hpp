// A set larger than memory, planned before any slab is read: three passes over its file (each
// particle's volume, mass and h, exactly as the whole set in memory would sum them; the extent
// of the particles and their periodic images, which fixes the whole set's bins; the points in
// each row of bins along the last axis), then slabs of whole rows, each with its halo of one
// row on either side, sized to the memory budget.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "particles/formats/snapshot_rows.hpp"
#include "particles/particle_volumes.hpp"
#include "particles/smoothing_lengths.hpp"
#include "support/process/parallel_for.hpp"

#include <cstddef>
#include <vector>

namespace sphkern {

// Rows of the file read, and of the spills merged, at a time: a whole number of the blocks
// that sums are taken in (a run adds its blocks as the whole set's sum does), 65536 rows per
// thread so that every thread has blocks to take and values to count, fewer where `room` holds
// fewer rows of `row_bytes`, and never fewer than two blocks. The results do not depend on it.
std::size_t slab_run_rows(int threads, std::size_t row_bytes, std::size_t room);

struct SlabPlanInputs {
    SmoothingSpec smoothing;                   // eta, N_H or the file's h
    VolumeModel volume = VolumeModel::uniform; // uniform or file
    std::optional<double> rho0;
    int threads = 1;
    std::size_t run_rows = particle_block_size; // slab_run_rows
};

// One slab: its own rows of bins along the axis, and the rows it holds (its own and the halo).
struct Slab {
    std::size_t first = 0, last = 0, own_first = 0, own_last = 0;
    std::size_t points = 0; // particles and images in [first, last)
};

struct SlabPlan {
    std::size_t particles = 0;
    double mean_volume = 0, spacing = 0, rho0 = 1;
    // V and h: one value for all (uniform), or each particle's (then these are unused).
    bool uniform_volume = true, uniform_h = true;
    double volume = 0, h = 0, h_max = 0;
    GridGeometry geometry; // the whole set's bins
    int axis = 2;          // the last axis: its rows of bins are contiguous in the grid
    std::vector<Slab> slabs;
};

// Throws Error(input) naming the file and the particle (its row) at fault, as the whole set's
// checks would, and for a row of bins that alone exceeds the budget `slab_bytes`.
SlabPlan plan_slabs(const SnapshotRows& file, const Kernel& kernel, const SlabPlanInputs& inputs,
                    std::size_t slab_bytes);

// Rows [begin, end) of the file, validated and wrapped into the box, as the whole set's would be.
ParticleSet read_valid_rows(const SnapshotRows& file, std::size_t begin, std::size_t end, int threads);

} // namespace sphkern
