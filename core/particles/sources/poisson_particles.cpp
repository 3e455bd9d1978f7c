#include "particles/sources/poisson_particles.hpp"

#include "support/process/block_random.hpp"
#include "support/process/parallel_for.hpp"

#include <boost/random/uniform_real_distribution.hpp>

#include <cmath>

namespace sphkern {

ParticleSet poisson_particles(const PoissonSpec& spec, int threads)
{
    ParticleSet set;
    set.name = "poisson";
    set.dimension = spec.dimension;
    if (spec.dimension == 2) set.gravity = Eigen::Vector3d(0, -1, 0);
    PeriodicBox box;
    box.edges = Eigen::Vector3d(spec.box.x(), spec.box.y(), spec.dimension == 3 ? spec.box.z() : 1.0).asDiagonal();
    set.box = box;
    set.x.resize(spec.count), set.y.resize(spec.count), set.z.resize(spec.count);
    ParallelFor draw;
    draw.run_blocks(spec.count, random_block_size, threads, [&](std::size_t block, std::size_t begin, std::size_t end) {
        auto engine = block_stream(spec.seed, block);
        boost::random::uniform_real_distribution<double> unit(0.0, 1.0);
        for (std::size_t i = begin; i < end; ++i) {
            set.x[i] = unit(engine) * spec.box.x();
            set.y[i] = unit(engine) * spec.box.y();
            set.z[i] = spec.dimension == 3 ? unit(engine) * spec.box.z() : 0.0;
        }
    });
    validate_particle_set(set, threads);
    return set;
}

} // namespace sphkern
