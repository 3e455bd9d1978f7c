#include "particles/sources/lattice_particles.hpp"

#include "lattices/rectangular_cell.hpp"
#include "support/process/block_random.hpp"
#include "support/process/parallel_for.hpp"

#include <boost/random/normal_distribution.hpp>

#include <cmath>

namespace sphkern {

Lattice block_cell(const Lattice& lattice, const LatticeBlockSpec& spec)
{
    return spec.rectangular ? rectangular_cell(lattice) : lattice;
}

ParticleSet lattice_particles(const Lattice& lattice, const LatticeBlockSpec& spec, int threads)
{
    const int dim = lattice.dimension;
    double count = lattice.sites();
    for (int a = 0; a < dim; ++a) count *= static_cast<double>(spec.cells[static_cast<std::size_t>(a)]);

    ParticleSet set;
    set.name = lattice.name;
    set.dimension = dim;
    set.spacing = 1; // lattices are rescaled to d = 1
    set.gravity = lattice.gravity;
    PeriodicBox box;
    for (int a = 0; a < 3; ++a)
        box.edges.col(a) =
            lattice.basis.col(a) * static_cast<double>(a < dim ? spec.cells[static_cast<std::size_t>(a)] : 1);
    set.box = box;
    const std::size_t n = static_cast<std::size_t>(count), sites = lattice.motif.size();
    const auto n1 = static_cast<std::size_t>(spec.cells[0]), n2 = static_cast<std::size_t>(spec.cells[1]);
    set.x.resize(n), set.y.resize(n), set.z.resize(n);
    // Particle i is site i % sites of cell i / sites, cells numbered along the first axis first.
    // A disturbance is drawn block by block, one stream per block (Boost's generator and
    // distribution: the same numbers on every platform and thread count).
    ParallelFor place;
    place.run_blocks(n, random_block_size, threads, [&](std::size_t block, std::size_t begin, std::size_t end) {
        auto engine = block_stream(spec.seed, block);
        boost::random::normal_distribution<double> normal(0.0, spec.sigma > 0 ? spec.sigma : 1.0);
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t cell = i / sites;
            const Eigen::Vector3d& site = lattice.motif[i % sites];
            const Eigen::Vector3d f(static_cast<double>(cell % n1) + site.x(),
                                    static_cast<double>(cell / n1 % n2) + site.y(),
                                    dim == 3 ? static_cast<double>(cell / (n1 * n2)) + site.z() : 0.0);
            Eigen::Vector3d p = lattice.basis * f;
            if (spec.sigma > 0) {
                p.x() += normal(engine), p.y() += normal(engine);
                if (dim == 3) p.z() += normal(engine);
            }
            set.x[i] = p.x(), set.y[i] = p.y(), set.z[i] = dim == 3 ? p.z() : 0.0;
        }
    });
    // A displacement of several blocks is still periodic.
    if (spec.sigma > 0) wrap_into_box(set, WrapReach::any_distance, threads);
    validate_particle_set(set, threads);
    return set;
}

} // namespace sphkern
