// The block's sums on the particle engine's neighbour search: every particle's density and
// pressure gradient (P = rho0 g depth, in each gradient form) by direct summation over the
// neighbours the engine's cluster pass keeps, with one fused kernel call per particle.
#pragma once

#include "block/block_geometry.hpp"
#include "kernels/kernel.hpp"
#include "particles/engine/neighbour_grid.hpp"

namespace sphkern {

struct SweepParameters {
    int dimension = 3;
    double k = 1, a_p = 1;
    GradientForm form = GradientForm::sum;
    double reach = 0; // the radius searched: the grid's (search_reach)
    // Each pair once (symmetric_pair_pass), its terms added to both particles; else every
    // particle gathers its own (pair_pass): the same sums to rounding.
    bool each_pair_once = true;
};

// One sweep over every particle of the grid (the block as a particle set, in the block's
// order) in result.threads threads: eps_rho (with_density), eps_gradp (with_gradient;
// Monaghan's form reads the densities `rho`, in the block's order) or both from one distance
// per pair. Returns the pairs within reach. Sums do not depend on the thread count. An
// exception or an interrupt in any thread stops them all and is thrown here.
std::size_t sum_block(const Kernel& kernel, const NeighbourGrid& grid, const BlockGeometry& geometry,
                      const SweepParameters& parameters, bool with_density, bool with_gradient, const double* rho,
                      BlockResult& result);

} // namespace sphkern
