// `sphkern particles` on a snapshot larger than the memory budget: the same answer as the
// whole set in memory, bit for bit, from slabs of the set along its last axis. Each slab is
// read with a halo one row of the whole set's bins wide (periodic images of the far side
// included) and sorted into those same bins, so that each of its own particles sees the same
// neighbours in the same order as in the whole set; its results go to a spill file, and the
// spills are merged back into file order for the statistics (exact: share/docs/internals.md,
// "Sets larger than memory") and for the per-particle output.
#pragma once

#include "particles/formats/snapshot_rows.hpp"
#include "particles/particle_analysis.hpp"

#include <array>
#include <cstdint>
#include <functional>

namespace sphkern {

// Rows [begin, begin + count) of the per-particle values, in file order.
struct MeasuredRows {
    std::size_t begin = 0, count = 0;
    const double *x, *y, *z, *h, *volume, *neighbours, *e0, *eps_rho, *eps_gradp;
    std::array<const double*, 3> e1, m1;
};
using MeasuredRowsSink = std::function<void(const MeasuredRows&)>;

// The bytes of disk the slabs' per-particle results take (`per_particle`: with the values a
// per-particle output writes).
std::size_t slab_spill_bytes(std::size_t particles, bool per_particle);

// One h (eta, N_H or the file's, not solved from the density), volumes uniform or the file's;
// Error(input) for what a slab cannot give, naming it. `rows`, where given, receives every
// particle's values in file order (a per-particle output).
ParticleAnswer analyse_particles_in_slabs(const Kernel& kernel, const SnapshotRows& file,
                                          const ParticleRequest& request, const MeasuredRowsSink& rows);

} // namespace sphkern
