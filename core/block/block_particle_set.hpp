// A lattice block as a particle set for the neighbour-sum engine: the block's positions,
// and for a periodic block a periodic box whose edges are the block's lateral sides and,
// vertically, a height with two support radii of empty space above the top and below the
// bottom, so that both stay free. Positions are wrapped into the box laterally (the images
// are the same); the block's own positions, in result.x, y and z, do not move.
#pragma once

#include "block/particle_block.hpp"
#include "particles/particle_set.hpp"

namespace sphkern {

// Throws Error(input) for a periodic block narrower than twice the reach (a particle would
// see two images of one neighbour), naming the cells it needs; nothing is allocated.
void require_periodic_width(const Lattice& lattice, const BlockOptions& options, double reach);

// The points the engine holds per particle of the block: 1, and for a periodic block the
// images within reach of its lateral sides (at most, as if every side were a plane).
double block_points_per_particle(const Lattice& lattice, const BlockOptions& options, double reach);

// The block of `result` (positions and gravity placed) as a particle set.
ParticleSet block_particle_set(const Lattice& lattice, const BlockOptions& options, const BlockResult& result,
                               double reach);

} // namespace sphkern
