// A lattice cut to a periodic block of N1 x N2 [x N3] cells, optionally disturbed by
// independent Gaussian displacements (the same set for a seed on every machine).
#pragma once

#include "lattices/lattice.hpp"
#include "particles/particle_set.hpp"

#include <array>
#include <cstdint>

namespace sphkern {

struct LatticeBlockSpec {
    std::array<long long, 3> cells = {1, 1, 1};
    double sigma = 0; // standard deviation per axis, in units of d
    std::uint64_t seed = 1;
    bool rectangular = false; // cells of the lattice's rectangular cell (rectangular_cell), not its primitive one
};

// The cell a block is cut from: the lattice's primitive cell, or its rectangular one.
Lattice block_cell(const Lattice& lattice, const LatticeBlockSpec& spec);

// Particles in cell-major order: id = ((c3 * N2 + c2) * N1 + c1) * sites + s, placed (and
// disturbed) on `threads` threads; the set does not depend on the number. `lattice` is the
// block's cell (block_cell). The spec as checked
// by requests/source_request.hpp (positive cells, sigma in [0, 10], within the memory budget).
ParticleSet lattice_particles(const Lattice& lattice, const LatticeBlockSpec& spec, int threads = 1);

} // namespace sphkern
