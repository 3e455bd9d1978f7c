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
    set_neighbour_number(p);
    return p;
}

} // namespace sphkern
