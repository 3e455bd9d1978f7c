// Copies of a periodic set side by side: the way large initial conditions are made from a
// small relaxed glass. Each copy keeps its particles' order; the copies follow one another
// along the first edge first. The box grows by the same counts, so every particle sees the
// neighbourhood it had (the original's periodic images are the copies).
#pragma once

#include "particles/particle_set.hpp"

#include <array>

namespace sphkern {

// `tiles`: copies along each edge (D of them used, each at least 1). Throws Error(input) for a
// set without a box and for more particles than the memory budget holds.
ParticleSet tiled_set(const ParticleSet& set, const std::array<int, 3>& tiles, int threads = 1);

} // namespace sphkern
