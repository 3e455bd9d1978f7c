// The block's sums: every particle's density and pressure gradient by direct summation
// over the runs of its cell list, with the kernel's batch calls. The loops over a run use
// plain pointers and no branch so that they vectorise (one clone per instruction set).
#pragma once

#include "block/block_geometry.hpp"
#include "block/cell_list.hpp"
#include "kernels/kernel.hpp"

namespace sphkern {

struct SweepParameters {
    int dimension = 3;
    double k = 1, a_p = 1;
    GradientForm form = GradientForm::sum;
};

// One sweep over every row in result.threads threads: eps_rho (with_density), eps_gradp
// (with_gradient; Monaghan's form reads the densities `rho`) or both from one distance
// per pair. Returns the pairs within reach (with_density only). An exception or an
// interrupt in any thread stops them all and is thrown here.
std::size_t sweep_block(const Kernel& kernel, const CellList& cells, const BlockGeometry& geometry,
                        const SweepParameters& parameters, bool with_density, bool with_gradient, const double* rho,
                        BlockResult& result);

} // namespace sphkern
