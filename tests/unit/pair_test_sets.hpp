// The particle sets the pair passes' tests share, each with a search reach: Poisson sets in
// 2D and 3D, periodic and free (in a box of 1 x 1.3 x 0.9), and a disturbed fcc block.
#pragma once

#include "lattices/lattice.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sphkern::test {

struct PairTestSet {
    std::string name;
    ParticleSet set;
    double reach;
};

// The Poisson sets' seeds are seed + D.
inline std::vector<PairTestSet> pair_test_sets(std::uint64_t seed)
{
    std::vector<PairTestSet> sets;
    for (int dim : {2, 3})
        for (bool periodic : {true, false}) {
            PoissonSpec spec;
            spec.dimension = dim, spec.count = dim == 3 ? 6000 : 3000, spec.seed = seed + static_cast<unsigned>(dim);
            spec.box = Eigen::Vector3d(1.0, 1.3, 0.9);
            ParticleSet set = poisson_particles(spec);
            if (!periodic) set.box.reset();
            sets.push_back(
                {fmt::format("Poisson {}D{}", dim, periodic ? " periodic" : ""), set, dim == 3 ? 0.13 : 0.08});
        }
    LatticeBlockSpec spec;
    spec.cells = {7, 7, 6}, spec.sigma = 0.05;
    sets.push_back({"fcc block", lattice_particles(load_lattice("fcc"), spec), 2.1});
    return sets;
}

} // namespace sphkern::test
