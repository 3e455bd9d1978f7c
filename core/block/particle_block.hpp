// A finite block of lattice cells filled with particles: the independent check of the
// lattice sums by direct SPH summation, and the scalable path (share/docs/method.md section 7).
#pragma once

#include "analysis/surface_profile.hpp"
#include "block/huge_array.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace sphkern {

// Bytes of memory per particle of a block: its positions, layers and results, the particle
// set and neighbour grid the engine builds from it (with ghosts), and their sort.
inline constexpr std::size_t bytes_per_block_particle = 200;

struct BlockOptions {
    std::array<long long, 3> cells = {1, 1, 1}; // along the basis vectors; the last is vertical
    bool periodic = false;                      // lateral sides
    double k = 1.0;
    double a_p = 1.0;
    GradientForm form = GradientForm::sum;
    int threads = 0; // 0: every core
    // Each pair evaluated once for both particles; false: every particle gathers its own (the
    // same sums to rounding; tests compare the two).
    bool each_pair_once = true;
};

struct BlockTimings {
    double setup = 0;      // positions, depths and layers, in seconds
    double evaluation = 0; // both sums: one fused sweep (sum, difference) or two passes (monaghan)
    bool fused = false;
};

struct LayerRange {
    int layer;
    int particles;
    double rho_min, rho_max, gradp_min, gradp_max;
    std::vector<int> sites; // the motif sites on this plane
};

struct BlockResult {
    int dimension = 0;
    HugeArray<double> x, y, z;         // positions, site-major (see evaluate_block)
    HugeArray<int> layer;              // 0 on top
    HugeArray<double> eps_rho;         // per particle
    HugeArray<double> eps_gradp;       // per particle, along gravity
    Eigen::Vector3d gravity;           // normal to the top face, pointing down
    double spacing = 0;                // between layers
    std::size_t pair_interactions = 0; // per sum (the density and the gradient each see this many)
    int threads = 1;
    int sites = 1; // particle i belongs to motif site i / (particles / sites)
    BlockTimings timings;
    std::size_t particles() const { return x.size(); }
    std::vector<LayerRange> layers() const;
};

// Builds the block and evaluates every particle's density and pressure gradient by
// direct sums over the neighbours the particle engine finds. Sizes and memory are
// checked before anything is allocated; throws Error(input) with one line.
BlockResult evaluate_block(const Kernel& kernel, const Lattice& lattice, const BlockOptions& options);

// The top face's downward normal for a block of this lattice.
Eigen::Vector3d block_gravity(const Lattice& lattice);

} // namespace sphkern
