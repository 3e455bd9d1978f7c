#include "codes/gadget2/gadget2.hpp"

#include "codes/neighbour_number.hpp"

namespace sphkern {

CodeProfile gadget2_code()
{
    // 3D, and 2D with TWODIMS (allvars.h: NUMDIMS, the kernel's coefficients); the cubic spline only.
    const std::vector<int> dims{2, 3};
    CodeProfile p;
    p.name = "gadget2";
    p.title = "GADGET-2";
    p.parameter = "nngb";
    p.parameter_help = "the weighted neighbour number";
    p.source = "Springel 2005 (GADGET-2, MNRAS 364, 1105): (4 pi / 3) H^3 rho = N_sph m, H the support radius";
    p.from_sph_density = true;
    p.counts = NeighbourCount::number;
    p.count_source = "density.c, density_evaluate: weighted_numngb += NORM_COEFF * wk / hinv3, no masses";
    p.dimensions = dims;
    p.kernels = {{"cubic spline", "cubic_bspline", dims}};
    p.counts_neighbours = true;
    p.layout = CodeLayout::gadget;
    p.hdf5_suffix = ".hdf5";
    p.hdf5_suffix_reason = "GADGET opens <InitCondFile>.hdf5 for HDF5 initial conditions (ICFormat 3)";
    p.support_per_h = [](const Kernel&, int) { return 1.0; }; // its SmoothingLength is the support radius
    p.parameter_of = [](const Kernel& kernel, int dim, double k, double spacing) {
        return neighbour_number(dim, kernel.support() * k, spacing);
    };
    return p;
}

} // namespace sphkern
