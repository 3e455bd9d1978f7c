// A uniform random (Poisson) set: N independent uniform positions in a periodic box.
#pragma once

#include "particles/particle_set.hpp"

#include <cstdint>

namespace sphkern {

struct PoissonSpec {
    int dimension = 3;
    std::size_t count = 0;
    Eigen::Vector3d box = Eigen::Vector3d::Ones(); // the sides of a rectangular box
    std::uint64_t seed = 1;
};

// Drawn block by block of particles, one random stream per block: the same set on any number
// of threads. The spec as checked by requests/source_request.hpp (dimension 2 or 3, at least
// 2 particles within the memory budget, positive box sides).
ParticleSet poisson_particles(const PoissonSpec& spec, int threads = 1);

} // namespace sphkern
