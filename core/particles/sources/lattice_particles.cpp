#include "particles/sources/lattice_particles.hpp"

#include "support/error.hpp"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/normal_distribution.hpp>
#include <fmt/format.h>

#include <cmath>

namespace sphkern {

ParticleSet lattice_particles(const Lattice& lattice, const LatticeBlockSpec& spec, std::size_t max_particles)
{
    const int dim = lattice.dimension;
    double count = lattice.sites();
    for (int a = 0; a < dim; ++a) {
        if (spec.cells[static_cast<std::size_t>(a)] < 1)
            fail_input(fmt::format("--size: {} cells along axis {}; expected at least 1", spec.cells[static_cast<std::size_t>(a)],
                                   a + 1));
        count *= static_cast<double>(spec.cells[static_cast<std::size_t>(a)]);
    }
    if (count > static_cast<double>(max_particles))
        fail_input(fmt::format("--size: {:.0f} particles, more than the memory limit of {} particles (--memory-limit)",
                               count, max_particles));
    if (!std::isfinite(spec.sigma) || spec.sigma < 0 || spec.sigma > 10)
        fail_input(fmt::format("--sigma {}: expected a number in [0, 10] (units of d)", spec.sigma));

    ParticleSet set;
    set.name = lattice.name;
    set.dimension = dim;
    set.spacing = 1; // lattices are rescaled to d = 1
    set.gravity = lattice.gravity;
    PeriodicBox box;
    for (int a = 0; a < 3; ++a)
        box.edges.col(a) = lattice.basis.col(a) * static_cast<double>(a < dim ? spec.cells[static_cast<std::size_t>(a)] : 1);
    set.box = box;
    const std::size_t n = static_cast<std::size_t>(count);
    set.x.reserve(n), set.y.reserve(n), set.z.reserve(n);
    const long long n3 = dim == 3 ? spec.cells[2] : 1;
    for (long long c3 = 0; c3 < n3; ++c3)
        for (long long c2 = 0; c2 < spec.cells[1]; ++c2)
            for (long long c1 = 0; c1 < spec.cells[0]; ++c1)
                for (const auto& site : lattice.motif) {
                    const Eigen::Vector3d f(static_cast<double>(c1) + site.x(), static_cast<double>(c2) + site.y(),
                                            dim == 3 ? static_cast<double>(c3) + site.z() : 0.0);
                    const Eigen::Vector3d p = lattice.basis * f;
                    set.x.push_back(p.x()), set.y.push_back(p.y()), set.z.push_back(dim == 3 ? p.z() : 0.0);
                }
    if (spec.sigma > 0) {
        // Boost's generator and distribution: the same numbers on every platform, drawn in id order.
        boost::random::mt19937_64 engine(spec.seed);
        boost::random::normal_distribution<double> normal(0.0, spec.sigma);
        for (std::size_t i = 0; i < n; ++i) {
            set.x[i] += normal(engine);
            set.y[i] += normal(engine);
            if (dim == 3) set.z[i] += normal(engine);
        }
        wrap_into_box(set, WrapReach::any_distance); // a displacement of several blocks is still periodic
    }
    validate_particle_set(set);
    return set;
}

} // namespace sphkern
