// The block's particles: sizes checked before anything is allocated, positions in
// site-major order (particle (site s, cell c) is s * cells + c, c = (c3 * n2 + c2) * n1 + c1:
// the order of the block's outputs, whatever order the engine sums in), depths below the top
// particle and the layers, the occupied planes ranked from the top.
#pragma once

#include "block/huge_array.hpp"
#include "block/particle_block.hpp"
#include "lattices/lattice.hpp"

namespace sphkern {

struct BlockGeometry {
    long long size[3] = {1, 1, 1}; // cells along the basis vectors
    std::size_t cells = 0, count = 0;
    HugeArray<double> depth; // below the top particle, along gravity
};

// The number of particles of the block; Error(input) for a bad size or one over the limit.
std::size_t checked_block_size(const Lattice& lattice, const BlockOptions& options);

// Fills result.x, y, z and layer (and touches eps_rho, eps_gradp) in `threads` threads, each
// writing the part it will read later; result.gravity must be set.
BlockGeometry place_particles(const Lattice& lattice, const BlockOptions& options, BlockResult& result);

} // namespace sphkern
